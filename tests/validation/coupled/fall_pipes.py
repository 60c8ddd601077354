#!/usr/bin/env python3
"""The fall-pipe dumping of Chen et al. (2019), section 3.3, a CI check of its findings.

Both pipes of the paper (cases/fall_pipe_continuous and cases/fall_pipe_perforated: 33 cylinders of
1 cm falling through a funnel and a 3 cm pipe into water 12 cm deep) run through the `picdem`
executable on RANKS ranks at CELL (the case files: 0.5 mm, the paper's 20 cells per diameter; the
main job of the README runs the continuous pipe at this CELL) to T_END, with the case files' other
settings. A third run is the continuous pipe with `coupling/mixture_cut_faces` true (not the
default; doc/coupling.md) to T_MIXTURE, past the dumping's window: the key's whole-run check.
From their timeseries.csv and solids.csv:

  - no cylinder is faster than free fall: none reaches below the pipe's lower end (its centre, in
    solids.csv, written every FRAME) earlier than a free fall from the lowest centre at t = 0 to
    that end allows, sqrt(2 (z0 - bottom) / g) (the funnel, buoyancy and drag can only delay it);
  - the water's volume (timeseries fluid_volume) stays within VOLUME_TOL (relative, chosen as for
    the cylinder dam breaks, issue 14) of its volume at t = 0 at every step; that volume is the
    case's geometry: the tank's length times the still level, less the pipe's two walls below the
    level (less their holes; the funnel and the cylinders lie above the level: checked);
  - the paper's drawdown ("a decrease of the water level inside the pipe while an increase of the
    water level outside the pipe"): over the dumping, DUMPING = [0.3, 0.8] s, the mean level
    inside the pipe (the probe in its centre column, level_1) lies at least DRAWDOWN_MIN below the
    mean of the two outside probes (level_2, level_3, 10 cm either side), and the outside level
    rises at least RISE_MIN (two cells) above the still level;
  and, for the two pipes at the case files' settings:
  - the dump finishes: no cylinder in the pipe and funnel at T_END (timeseries solids_in_box, the
    cylinders whose centre lies in the case's solid_count_box, the pipe and funnel above the
    pipe's lower end: 0; a cylinder thrown over the funnel's rim counts as out, as in the
    section's figures; the emptying time is the first step with none, after which a cylinder
    can be lifted back into the outlet, hence the check at T_END);
  - the paper's delay: the continuous pipe empties later than the perforated one (the reversed
    flow "slows down and even lifts up the cylinders": "a delay of the solid dumping"; through the
    holes "the cylinders are quickly dumped out without delay");
  - the reversed flow lifts: after DUMPING's start some cylinder inside the continuous pipe (its
    centre between the walls and between the pipe's ends, in solids.csv) rises at LIFT_MIN or
    faster (the perforated pipe's fastest rise is printed, not asserted: the paper says its
    reversed flows are "not as continuous", not absent).
The runs' figures are printed whether they pass or not; doc/validation.md, "Fall-pipe dumping".
T_END leaves room after the emptying times measured at this CELL (1.11 to 1.22 s for the continuous
pipe over three particle seeds and two rank counts).

usage: fall_pipes.py PICDEM SOURCE_DIR WORK_DIR [MPIEXEC ...]
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "dem"))
import case_check  # noqa: E402
import yaml  # noqa: E402

CELL, T_END, T_MIXTURE, RANKS, FRAME = 0.0015, 1.5, 0.9, 2, 0.005
COUNT, G = 33, 9.81
DUMPING = (0.3, 0.8)
DRAWDOWN_MIN, RISE_MIN, LIFT_MIN = 0.01, 0.003, 0.02
VOLUME_TOL = 0.02


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def number(s):
    return float(s) if s not in ("", "nan", "NaN") else float("nan")


def initial_volume(case, lowest_bottom):
    """The water's area at t = 0 from the run's resolved case: the tank's length times the still
    level, less the pipe's walls (and their holes) below the level; exits with FAIL if the funnel
    or a cylinder (lowest_bottom: the lowest centre less its radius) reaches below the level."""
    level, length = case["water"]["tank"]["z"], case["grid"]["length"]
    pipe = case["obstacles"]["pipe"]
    if pipe["top"] < level or lowest_bottom < level:
        sys.exit("FAIL: the funnel or a cylinder reaches below the still level at t = 0: the "
                 "volume at t = 0 is not the one computed here")
    wet = max(0.0, level - pipe["bottom"])
    holes = 0.0
    size, spacing = pipe["hole_size"], pipe["hole_spacing"]
    if size > 0.0:  # centres bottom + spacing / 2 + n spacing, each hole below the pipe's top
        n = 0
        while pipe["bottom"] + (n + 0.5) * spacing + size / 2 < pipe["top"]:
            c = pipe["bottom"] + (n + 0.5) * spacing
            holes += max(0.0, min(c + size / 2, level) - (c - size / 2))
            n += 1
    return length * level - 2 * pipe["wall_thickness"] * (wet - holes)


def run_pipe(picdem, source, work, mpiexec, name, case_name, t_end, extra):
    out = case_check.fresh(work, name)
    console = case_check.run(mpiexec + ["-n", str(RANKS), picdem,
                                        os.path.join(source, "cases", case_name, "case.yaml"),
                                        "--output", out, "--set", f"grid/cell_size={CELL}",
                                        "--set", f"time/end={t_end}", "--set", "output/png=false",
                                        "--set", "output/paraview=false",
                                        "--set", f"output/interval={FRAME}",
                                        "--set", "checkpoint/at_end=false"] + extra)
    print(f"{name}: {case_check.resolution(console, out)}; {RANKS} ranks; "
          f"{' '.join(extra) or 'the case file settings'}")
    with open(os.path.join(out, "case_resolved.yaml")) as f:
        case = yaml.safe_load(f)["case"]
    rows = read_csv(os.path.join(out, "timeseries.csv"))
    solids = read_csv(os.path.join(out, "solids.csv"))
    first = [s for s in solids if float(s["t"]) == 0.0]
    if len(first) != COUNT:
        sys.exit(f"FAIL: {name}: {len(first)} cylinders at t = 0 in solids.csv, not {COUNT}")
    radius = case["solids"]["cylinders"]["radius"]
    z0 = min(float(s["z"]) for s in first)
    pipe = case["obstacles"]["pipe"]
    v0 = initial_volume(case, z0 - radius)
    t = [float(r["t"]) for r in rows]
    box = [int(float(r["solids_in_box"])) for r in rows]
    volume = [float(r["fluid_volume"]) / v0 - 1.0 for r in rows]
    worst = max(range(len(rows)), key=lambda n: abs(volume[n]))
    first_out = min((float(s["t"]) for s in solids if float(s["z"]) < pipe["bottom"]),
                    default=None)
    empty = next((t[n] for n in range(len(rows)) if box[n] == 0), None)
    in_pipe = [s for s in solids if float(s["t"]) >= DUMPING[0]
               and abs(float(s["x"]) - pipe["centre_x"]) < pipe["inner_width"] / 2
               and pipe["bottom"] < float(s["z"]) < pipe["top"]]
    lift = max(in_pipe, key=lambda s: float(s["w"]), default=None)
    still = case["water"]["tank"]["z"]
    inside, outside = [], []
    for r, tn in zip(rows, t):
        if DUMPING[0] <= tn <= DUMPING[1]:
            a, b, c = number(r["level_1"]), number(r["level_2"]), number(r["level_3"])
            if not math.isnan(a):
                inside.append(a)
            if not (math.isnan(b) or math.isnan(c)):
                outside.append(0.5 * (b + c))
    fig = {
        "name": name, "t_end": t[-1], "t_asked": t_end,
        "volume_worst": volume[worst], "volume_worst_t": t[worst],
        "first_out": first_out, "free_fall": math.sqrt(2 * (z0 - pipe["bottom"]) / G),
        "empty": empty, "left_at_end": box[-1],
        "lift": float(lift["w"]) if lift else float("nan"),
        "inside": sum(inside) / len(inside) if inside else float("nan"),
        "outside": sum(outside) / len(outside) if outside else float("nan"),
        "outside_max": max(outside) if outside else float("nan"), "still": still,
    }
    print(f"  water volume: worst change {100 * fig['volume_worst']:+.2f}% at "
          f"{fig['volume_worst_t']:.3f} s against the {v0:.6e} m^2 at t = 0 (limit "
          f"{100 * VOLUME_TOL:.0f}%)")
    print(f"  first cylinder below the pipe at {case_check_time(first_out)} (free fall: no "
          f"earlier than {fig['free_fall']:.4f} s); pipe empty at {case_check_time(empty)}, "
          f"{box[-1]} cylinders left at {t[-1]:.3f} s")
    if lift:
        print(f"  fastest rise of a cylinder in the pipe from {DUMPING[0]} s: "
              f"{float(lift['w']):+.4f} m/s (id {lift['id']} at {float(lift['t']):.3f} s, "
              f"z = {float(lift['z']):.4f} m)")
    print(f"  levels over {DUMPING[0]}-{DUMPING[1]} s: inside mean {100 * fig['inside']:.2f} cm "
          f"({len(inside)} steps), outside mean {100 * fig['outside']:.2f} cm, highest "
          f"{100 * fig['outside_max']:.2f} cm (still water {100 * still:.1f} cm)")
    return fig


def case_check_time(t):
    return "never" if t is None else f"{t:.4f} s"


def health(fig, failures):
    """The checks every run must pass: volume, free fall, drawdown and outside rise."""
    n = fig["name"]
    if fig["t_end"] < fig["t_asked"] - 1e-9:
        failures.append(f"{n}: the run ended at {fig['t_end']:.4f} s, before {fig['t_asked']} s")
    if abs(fig["volume_worst"]) > VOLUME_TOL:
        failures.append(f"{n}: water volume changed by {100 * fig['volume_worst']:+.2f}% at "
                        f"{fig['volume_worst_t']:.3f} s (limit {100 * VOLUME_TOL:.0f}%)")
    if fig["first_out"] is not None and fig["first_out"] < fig["free_fall"]:
        failures.append(f"{n}: a cylinder was below the pipe at {fig['first_out']:.4f} s, before a "
                        f"free fall allows ({fig['free_fall']:.4f} s)")
    if not fig["outside"] - fig["inside"] >= DRAWDOWN_MIN:
        failures.append(f"{n}: inside level {100 * fig['inside']:.2f} cm not "
                        f"{100 * DRAWDOWN_MIN:.0f} cm below the outside "
                        f"{100 * fig['outside']:.2f} cm over the dumping")
    if not fig["outside_max"] - fig["still"] >= RISE_MIN:
        failures.append(f"{n}: the outside level rose to {100 * fig['outside_max']:.2f} cm only, "
                        f"not {1000 * RISE_MIN:.0f} mm above the still {100 * fig['still']:.1f} cm")


def main():
    picdem, source, work = sys.argv[1:4]
    mpiexec = sys.argv[4:] or ["mpirun"]
    failures = []
    cont = run_pipe(picdem, source, work, mpiexec, "continuous", "fall_pipe_continuous", T_END, [])
    perf = run_pipe(picdem, source, work, mpiexec, "perforated", "fall_pipe_perforated", T_END, [])
    mix = run_pipe(picdem, source, work, mpiexec, "continuous_mixture", "fall_pipe_continuous",
                   T_MIXTURE, ["--set", "coupling/mixture_cut_faces=true"])
    for fig in (cont, perf, mix):
        health(fig, failures)
    for fig in (cont, perf):
        if fig["left_at_end"] != 0:  # a cylinder can be lifted back into the outlet
            failures.append(f"{fig['name']}: {fig['left_at_end']} cylinders in the pipe at "
                            f"{T_END} s")
    if cont["empty"] is not None and perf["empty"] is not None:
        print(f"delay of the continuous pipe: {cont['empty'] - perf['empty']:+.4f} s")
        if not cont["empty"] > perf["empty"]:
            failures.append(f"the continuous pipe emptied at {cont['empty']:.4f} s, not later than "
                            f"the perforated one ({perf['empty']:.4f} s)")
    if not cont["lift"] >= LIFT_MIN:
        failures.append(f"no cylinder in the continuous pipe rose at {LIFT_MIN} m/s or faster "
                        f"after {DUMPING[0]} s (fastest {cont['lift']:+.4f} m/s): no lifting "
                        f"reversed flow")
    if failures:
        sys.exit("FAIL:\n  " + "\n  ".join(failures))
    print("PASS")


if __name__ == "__main__":
    main()
