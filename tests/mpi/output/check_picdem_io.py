"""drivers/picdem_io.py on a real run's output: what it loads agrees across the files.
usage: check_picdem_io.py OUTPUT_DIR DRIVERS_DIR RANKS

Asserted: timeseries.csv has one row per step 1..N with increasing t; each frame after step 0 has
the time and the particle count of the timeseries row of its step; its particles have unique ids,
speed = |velocity|, and lie on both sides of every rank boundary the case puts in water (x =
0.06 m on 2 ranks); solids.csv at each frame time lists the frame's solids, whose outline vertices
average to the solids.csv centre within 1e-12 m; the newest checkpoint is at the last frame's step
and time, its pressure and cell states equal the frame's cell arrays bitwise, its particles (by id)
the frame's positions and velocities bitwise, its solids the solids.csv rows of that time bitwise.
"""
import sys

import numpy as np

out, drivers, ranks = sys.argv[1], sys.argv[2], int(sys.argv[3])
sys.path.insert(0, drivers)
import picdem_io  # noqa: E402
from check_support import check, finish


run = picdem_io.Run(out)
ts = run.timeseries()
n = len(ts["step"])
check(n > 0 and np.array_equal(ts["step"], np.arange(1, n + 1)), "timeseries steps not 1..N")
check(np.all(np.diff(ts["t"]) > 0), "timeseries t not increasing")
solids = run.solids()
frames = list(run.frames())
check(len(frames) >= 3, f"only {len(frames)} frames")
for fr in frames:
    where = f"frame at step {fr.step}"
    p = fr.particles
    check(fr.ranks == ranks, f"{where}: written by {fr.ranks} ranks")
    check(fr.units["cells/pressure"] == "Pa" and fr.units["particles/velocity"] == "m/s",
          f"{where}: units")
    check(len(np.unique(p["id"])) == len(p["id"]) and p["id"].dtype == np.int64,
          f"{where}: ids not unique int64")
    check(np.array_equal(p["speed"], np.hypot(p["u"], p["w"])), f"{where}: speed != |velocity|")
    check(np.any(p["x"] < 0.06) and np.any(p["x"] > 0.06), f"{where}: water on one rank only")
    if fr.step > 0:
        row = np.flatnonzero(ts["step"] == fr.step)
        check(len(row) == 1, f"{where}: no timeseries row")
        if len(row) == 1:
            check(ts["t"][row[0]] == fr.time, f"{where}: time {fr.time} != {ts['t'][row[0]]}")
            check(ts["particles"][row[0]] == len(p["x"]),
                  f"{where}: {len(p['x'])} particles, timeseries says {ts['particles'][row[0]]}")
    rows = np.flatnonzero(solids["t"] == fr.time)
    check(sorted(solids["id"][rows]) == sorted(b for b, _ in fr.solids), f"{where}: solid ids")
    for b, v in fr.solids:
        r = rows[solids["id"][rows] == b]
        if len(r) == 1:
            centre = v[:-1].mean(axis=0)  # closed outline: the last vertex repeats the first
            check(abs(centre[0] - solids["x"][r[0]]) < 1e-12 and
                  abs(centre[1] - solids["z"][r[0]]) < 1e-12,
                  f"{where}: solid {b} outline centre {centre} != solids.csv")

last = frames[-1]
ck = run.checkpoint()
check(ck.step == last.step and ck.t == last.time, f"checkpoint at step {ck.step}, t {ck.t}")
check(np.array_equal(ck.pressure, last.cells["pressure"]), "checkpoint pressure != frame")
check(np.array_equal(ck.cell_state, last.cells["cell_state"]), "checkpoint cell states != frame")
a, b = np.argsort(ck.particles["id"]), np.argsort(last.particles["id"])
check(np.array_equal(ck.particles["id"][a], last.particles["id"][b]), "checkpoint particle ids")
for name in ("x", "z", "u", "w"):
    check(np.array_equal(ck.particles[name][a], last.particles[name][b]),
          f"checkpoint particles {name} != frame")
rows = np.flatnonzero(solids["t"] == ck.t)
check(np.array_equal(solids["id"][rows], ck.solids["id"]), "checkpoint solid ids")
for name in ("x", "z", "theta", "u", "w", "omega"):
    check(np.array_equal(solids[name][rows], ck.solids[name]), f"checkpoint solids {name}")

finish(f"picdem_io: {n} time-series rows, {len(frames)} frames, {len(ck.solids['id'])} solids and "
       f"{len(ck.particles['id'])} particles in the checkpoint agree across the files")
