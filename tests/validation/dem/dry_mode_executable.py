#!/usr/bin/env python3
"""picdem's dry mode (solids, no water) run through the executable, as a user runs it.

The 6-layer dry collapse (cases/dry_collapse_6layers) is run to 0.5 s by `picdem` on 1 rank and
on 4 ranks cut along x (grid/ranks_x = 4: the first rank boundary, at a quarter of the tank,
lies just beyond the stack's foot, so the cylinders cross it as the stack collapses). Checked
from the solids.csv the executable writes:
  - every output time lists the 33 cylinders, ids 0..32, and the times match output/interval;
  - the 4-rank file equals the 1-rank file byte for byte (the DEM alone is bitwise independent
    of the rank count, doc/dem.md), and cylinders did cross the first rank boundary (the 4-rank
    run takes grid/decomposition = uniform, so that the boundary lies where the test puts it);
  - a 2-rank run with the default decomposition (weighted: a dry run's cut lines share out the
    solids, doc/performance.md) moved its cut lines (picdem.log) and equals the 1-rank file too;
  - the mean centre (eq. 26) divided by the tank length follows the experiment of Zhang et al.
    (2009) within |d(x/L)| <= 0.03 and |d(z/L)| <= 0.015 at 0.1, 0.3 and 0.5 s, the tolerances of
    test_dem_dry_collapse (which runs the same case through the library, not the executable).

usage: dry_mode_executable.py PICDEM SOURCE_DIR WORK_DIR MPIEXEC...
"""
import csv
import os
import re
import shutil
import subprocess
import sys

N_SOLIDS = 33
TOL_X, TOL_Z = 0.03, 0.015


def run(picdem, case, out, ranks, mpiexec, extra):
    shutil.rmtree(out, ignore_errors=True)
    cmd = mpiexec + ["-n", str(ranks), picdem, case, "--output", out,
                     "--set", "time/end=0.5"] + extra
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {r.returncode}:\n{r.stdout[-3000:]}")
    return os.path.join(out, "solids.csv")


def read_solids(path):
    frames = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            frames.setdefault(float(row["t"]), []).append(
                (int(float(row["id"])), float(row["x"]), float(row["z"])))
    return frames


def experiment(data_dir):
    rows = []
    with open(os.path.join(data_dir, "zhang2009_dry_collapse_6layers.csv")) as f:
        for line in f:
            if not line.strip() or line[0] in "#t":
                continue
            t, x, z = (float(v) for v in line.split(","))
            rows.append((t, x, z))
    return rows


def mean_over_l(frame, length):
    xs = [s[1] for s in frame]
    zs = [s[2] for s in frame]
    return sum(xs) / len(xs) / length, sum(zs) / len(zs) / length


def interpolate(curve, t):
    for (t0, x0, z0), (t1, x1, z1) in zip(curve, curve[1:]):
        if t1 >= t:
            w = (t - t0) / (t1 - t0)
            return x0 + w * (x1 - x0), z0 + w * (z1 - z0)
    return curve[-1][1], curve[-1][2]


def main():
    picdem, source, work = sys.argv[1:4]
    mpiexec = sys.argv[4:]
    case = os.path.join(source, "cases", "dry_collapse_6layers", "case.yaml")
    length, h, interval = 0.286, 0.0005, 0.01  # the case file's grid/length, cell_size, interval
    os.makedirs(work, exist_ok=True)
    one = run(picdem, case, os.path.join(work, "np1"), 1, mpiexec, [])
    four = run(picdem, case, os.path.join(work, "np4"), 4, mpiexec,
               ["--set", "grid/ranks_x=4", "--set", "grid/ranks_z=1",
                "--set", "grid/decomposition=uniform"])
    two = run(picdem, case, os.path.join(work, "np2"), 2, mpiexec, [])
    failures = []
    with open(os.path.join(os.path.dirname(one), "case_resolved.yaml")) as f:
        ran_h = float(re.search(r"^\s*cell_size:\s*([0-9.eE+-]+)", f.read(), re.M).group(1))
    print(f"dry mode through the executable: resolution h = {ran_h} m (case_resolved.yaml), "
          f"1 rank and 4 ranks")
    if abs(ran_h - h) > 1e-15:
        failures.append(f"ran at h = {ran_h} m, the test's figures assume {h} m")

    frames = read_solids(one)
    times = sorted(frames)
    print(f"dry mode through the executable: {len(times)} output times, "
          f"last t = {times[-1]:.4f} s")
    if abs(times[-1] - 0.5) > 1e-9 or len(times) != round(0.5 / interval) + 1:
        failures.append(f"output times: {len(times)} up to {times[-1]}, expected 51 up to 0.5")
    for t in times:
        ids = sorted(s[0] for s in frames[t])
        if ids != list(range(N_SOLIDS)):
            failures.append(f"t = {t}: ids {ids[:5]}... ({len(ids)}), expected 0..32")
            break

    with open(one, "rb") as a, open(four, "rb") as b:
        same = a.read() == b.read()
    print(f"1 rank vs 4 ranks (ranks_x = 4): solids.csv {'identical' if same else 'DIFFERENT'}")
    if not same:
        failures.append("solids.csv of 4 ranks differs from 1 rank (DEM must be bitwise)")
    with open(one, "rb") as a, open(two, "rb") as b:
        same_two = a.read() == b.read()
    with open(os.path.join(os.path.dirname(two), "picdem.log")) as f:
        cut_lines = [line.strip() for line in f if "cut lines" in line]
    print(f"1 rank vs 2 ranks (weighted): solids.csv {'identical' if same_two else 'DIFFERENT'}; "
          f"cut lines moved {len(cut_lines)} time(s): {cut_lines[:1]}")
    if not same_two:
        failures.append("solids.csv of 2 ranks (weighted) differs from 1 rank")
    if not cut_lines:
        failures.append("the 2-rank dry run never moved its cut lines to share out the solids")
    # grid/ranks_x = 4 splits the 572 columns evenly: the first boundary is at 143 cells
    boundary = 143 * h
    crossed = sorted({s[0] for t in times for s in frames[t] if s[1] > boundary})
    start_beyond = [s[0] for s in frames[times[0]] if s[1] > boundary]
    print(f"cylinders beyond the first rank boundary x = {boundary} m: {len(start_beyond)} "
          f"at t = 0, {len(crossed)} during the run")
    if start_beyond or len(crossed) < 5:
        failures.append(f"expected cylinders to start left of x = {boundary} and at least 5 to "
                        f"cross it; {len(start_beyond)} started beyond, {len(crossed)} crossed")

    curve = [(t,) + mean_over_l(frames[t], length) for t in times]
    for t, ex, ez in experiment(os.path.join(source, "tests", "validation", "data")):
        if t < 0.05:
            continue
        sx, sz = interpolate(curve, t)
        print(f"t = {t:.3f} s: x/L exp {ex:.4f} sim {sx:.4f} (d {sx - ex:+.4f}, tol {TOL_X}), "
              f"z/L exp {ez:.4f} sim {sz:.4f} (d {sz - ez:+.4f}, tol {TOL_Z})")
        if abs(sx - ex) > TOL_X or abs(sz - ez) > TOL_Z:
            failures.append(f"t = {t}: mean centre off the experiment")

    if failures:
        print("FAIL:\n  " + "\n  ".join(failures))
        return 1
    print("dry mode through the executable: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
