#!/usr/bin/env python3
"""Side-by-side speed of case-file settings: the same picdem binary run in alternation (A B, B A,
...) with each variant's --set keys, so that the machine's noise hits all variants alike. Prints,
per run and as medians: wall and CPU seconds, the load average at the start, PPE iterations per
step, the phase timers (max over ranks) of the pressure phase, its MueLu setup and Belos solve, the
density correction, the pressure phase divided by the density correction of the same run (the
density correction does not depend on the pressure settings, so the ratio measures the variant
and not the machine's speed during the run), and the final fluid volume and kinetic energy.

usage: ab_options.py [--ranks N] [--rounds K] [--binary B] [--case FILE] [--out DIR]
                     [--set KEY=VALUE ...] VARIANT [VARIANT ...]
A VARIANT is NAME or NAME:KEY=VALUE,KEY=VALUE (e.g. low_rank:solver/coupling_operator=low_rank);
--set keys go to every run. Default case: cases/dam_break_cylinders_6_layers, output off.
"""
import argparse, csv, os, re, statistics, subprocess, time

top = os.path.abspath(os.path.join(os.path.dirname(__file__), "../../.."))
ap = argparse.ArgumentParser()
ap.add_argument("--ranks", type=int, default=1)
ap.add_argument("--rounds", type=int, default=3)
ap.add_argument("--binary", default=os.path.join(top, "build/drivers/picdem"))
ap.add_argument("--case", default=os.path.join(top, "cases/dam_break_cylinders_6_layers/case.yaml"))
ap.add_argument("--out", default="/tmp/picdem-ab")
ap.add_argument("--set", action="append", default=[])
ap.add_argument("variants", nargs="+")
a = ap.parse_args()
os.makedirs(a.out, exist_ok=True)
quiet = ["output/paraview=false", "output/png=false", "checkpoint/at_end=false"]


def timers(path):
    """Timer name -> seconds (max over ranks when there are several)."""
    t = {}
    for line in open(path):
        m = re.match(r"picdem: (.+?)\s{2,}(\S.*)$", line)
        vals = re.findall(r"([0-9.e+-]+) \((\d+)\)", m.group(2)) if m else []
        if vals:
            t[m.group(1)] = float((vals[2] if len(vals) == 4 else vals[0])[0])
    return t


variants = []
for v in a.variants:
    name, _, keys = v.partition(":")
    variants.append((name, [k for k in keys.split(",") if k]))
res = {name: [] for name, _ in variants}
mpi = ["mpirun", "--oversubscribe", "-n", str(a.ranks)]
if os.geteuid() == 0:
    mpi.insert(1, "--allow-run-as-root")
for k in range(a.rounds):
    for name, keys in variants if k % 2 == 0 else variants[::-1]:
        d = f"{a.out}/{name}-{k}"
        cmd = mpi + [a.binary, a.case, "-o", d]
        for s in quiet + a.set + keys:
            cmd += ["--set", s]
        load = os.getloadavg()[0]
        t0, r0 = time.time(), os.times()
        subprocess.run(cmd, stdout=open(d + ".log", "w"), stderr=subprocess.STDOUT, check=True)
        wall, r1 = time.time() - t0, os.times()
        cpu = r1.children_user - r0.children_user + r1.children_system - r0.children_system
        t = timers(f"{d}/timers.txt")
        rows = list(csv.DictReader(open(f"{d}/timeseries.csv")))
        r = dict(wall=wall, cpu=cpu, load=load, steps=len(rows),
                 its=sum(float(x["ppe_iterations"]) for x in rows) / len(rows),
                 pressure=t["pressure"], setup=t["fluid: pressure preconditioner"],
                 solve=t["fluid: pressure solve"], density=t.get("density correction", float("nan")),
                 vol=rows[-1]["fluid_volume"], ke=rows[-1]["kinetic_energy"])
        r["p_d"], r["share"] = r["pressure"] / r["density"], r["setup"] / r["pressure"]
        res[name].append(r)
        print(f"round {k} {name:12s} load {load:5.1f} wall {wall:7.1f} cpu {cpu:7.1f} "
              f"its/step {r['its']:6.2f} pressure {r['pressure']:7.2f} setup {r['setup']:7.2f} "
              f"solve {r['solve']:7.2f} density {r['density']:7.2f} pressure/density "
              f"{r['p_d']:5.2f} setup/pressure {r['share']:4.2f}", flush=True)
print("medians over the rounds:")
for name, _ in variants:
    R = res[name]
    med = {key: statistics.median(r[key] for r in R)
           for key in ("wall", "cpu", "pressure", "setup", "solve", "density", "p_d", "share")}
    print(f"{name:12s} steps {R[0]['steps']} its/step {R[0]['its']:.2f} wall {med['wall']:.1f} "
          f"cpu {med['cpu']:.1f} pressure {med['pressure']:.2f} setup {med['setup']:.2f} "
          f"solve {med['solve']:.2f} density {med['density']:.2f} pressure/density {med['p_d']:.3f} "
          f"setup/pressure {med['share']:.3f} volume {R[0]['vol']} kinetic {R[0]['ke']}")
