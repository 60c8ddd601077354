#!/usr/bin/env python3
"""What holds the stones in the fall pipe: the water levels against the stones in the pipe.

For a run of this case (timeseries.csv, solids.csv) prints, every PRINT_EVERY seconds: the stones
whose centre lies in the pipe's clear width above its lower end (x within PIPE_X, z above
PIPE_BOTTOM: the pipe and the funnel's column), their mean and fastest downward speed, the water
level inside the pipe (level_1) and outside (mean of level_2 and level_3), the head difference
dh = outside - inside, the upward push of that head on the pipe's water, rho g dh W (W the pipe's
clear width), next to the stones' weight in the pipe (the stones below the inside level counted
submerged, (rho_s - rho) g A, those above in air, rho_s g A), and the inside level's rate of rise.
It also prints the terminal settling speed of a lone stone, a 2D disk (a cylinder across the
flow): (rho_s - rho) g pi d^2 / 4 = C_d rho v^2 d / 2, v = sqrt(pi (rho_s / rho - 1) g d / (2 C_d)),
for C_d = 1.0 and 1.2 (a circular cylinder at Re = v d / nu of 10^3 to 10^4).

The stones' sizes are not in solids.csv: they are read from a ParaView frame of a run of the same
case (the solids' outlines, frames/*.h5; the sizes depend only on the generator's seed and keys,
not on the grid), SIZES_RUN, e.g. a one-step run with `--set output/paraview=true
--set time/end=0.001`.
usage: plug.py RUN_DIR SIZES_RUN [PRINT_EVERY]
"""
import csv
import glob
import math
import os
import sys


RHO, RHO_S, G = 1000.0, 2650.0, 9.81
PIPE_X, PIPE_BOTTOM, PIPE_TOP = (0.192, 0.237), 0.09, 0.195
W = PIPE_X[1] - PIPE_X[0]


def read_solids(path):
    """solids.csv by output time: {t: {id: (x, z, w)}} (w the vertical velocity)."""
    out = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            out.setdefault(float(r["t"]), {})[int(r["id"])] = (float(r["x"]), float(r["z"]),
                                                               float(r["w"]))
    return out


def diameters(run):
    """{id: d} from the first ParaView frame of run: the largest distance of a solid's outline
    points (x, z) from its centre at t = 0 (solids.csv)."""
    import h5py

    centres = read_solids(os.path.join(run, "solids.csv"))[0.0]
    h5 = h5py.File(sorted(glob.glob(os.path.join(run, "frames", "*.h5")))[0], "r")
    conn, xyz = h5["solids/connectivity"][:], h5["solids/xyz"][:]
    out, k = {}, 0
    for b in h5["solids/body_id"][:]:
        n = int(conn[k + 1])
        pts = xyz[conn[k + 2:k + 2 + n]]
        k += 2 + n
        cx, cz, _ = centres[int(b)]
        out[int(b)] = 2 * max(math.hypot(p[0] - cx, p[1] - cz) for p in pts)
    return out


def settling(d, cd):
    return math.sqrt(math.pi * (RHO_S / RHO - 1) * G * d / (2 * cd))


def main():
    run, sizes_run = sys.argv[1:3]
    every = float(sys.argv[3]) if len(sys.argv) > 3 else 0.1
    d = diameters(sizes_run)
    ds = sorted(d.values())
    print(f"{len(ds)} stones, d = {ds[0] * 1e3:.1f} to {ds[-1] * 1e3:.1f} mm, median "
          f"{ds[len(ds) // 2] * 1e3:.2f} mm; lone stone's settling speed (C_d 1.0 / 1.2): "
          + ", ".join(f"d {x * 1e3:.1f} mm {settling(x, 1.0):.2f} / {settling(x, 1.2):.2f} m/s"
                      for x in (ds[0], ds[len(ds) // 2], ds[-1])))
    fr = read_solids(os.path.join(run, "solids.csv"))
    with open(os.path.join(run, "timeseries.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    print("t [s]  stones in pipe  mean/max down speed [m/s]  level in/out [cm]  dh [cm]  "
          "rho g dh W [N/m]  stones' weight [N/m]  inside rise [m/s]")
    next_t = 0.0
    for t in sorted(fr):
        if t + 1e-9 < next_t:
            continue
        next_t += every
        r = min(rows, key=lambda q: abs(q["t"] - t))
        prev = min(rows, key=lambda q: abs(q["t"] - (t - 0.05)))
        inside, outside = r["level_1"], (r["level_2"] + r["level_3"]) / 2
        rise = (inside - prev["level_1"]) / max(r["t"] - prev["t"], 1e-12)
        pipe = [(i, z, w) for i, (x, z, w) in fr[t].items()
                if PIPE_X[0] < x < PIPE_X[1] and z > PIPE_BOTTOM]
        weight = sum((RHO_S - (RHO if z < inside else 0.0)) * G * math.pi * d[i] ** 2 / 4
                     for i, z, _ in pipe)
        down = [-w for _, _, w in pipe]
        mean_down = sum(down) / len(down) if down else 0.0
        print(f"{t:5.2f}  {len(pipe):14d}  {mean_down:6.3f} / {max(down, default=0.0):6.3f}"
              f"            {inside * 100:5.1f} / {outside * 100:5.1f}     "
              f"{(outside - inside) * 100:5.1f}    {RHO * G * (outside - inside) * W:8.1f}"
              f"          {weight:8.1f}            {rise:6.3f}")


if __name__ == "__main__":
    main()
