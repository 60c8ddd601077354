#!/usr/bin/env python3
"""The MPS paper's dam break with water and with grains (cases/granular_dam_break), a CI check.

Kim, Kim, Jang & Cho (2018, "Simulation of solid particle interactions including segregated
lamination by using MPS method", sec. 3, Fig. 3): a column 0.15 m x 0.3 m against the left wall
of a 0.6 m x 0.6 m container; the water "took less than 0.4 s to traverse the tank", the grains
behave "quite differently": their free surface develops "much slower" and ends as a slope. Runs,
one rank each: water.yaml (picdem's fluid alone, 5 mm cells, to 0.5 s) and case.yaml (300 disks,
mu = 0.2, accumulated spring, 1.5 s). Asserted:
  - the water's front (timeseries.csv front_x) reaches the far wall (x >= 0.595 m) before
    WATER_BY = 0.4 s, the paper's bound;
  - the grains' front (analyse.py: the continuous deposit's front) reaches it later than the
    water's, and the deposit is at rest (front and top unchanged to REST over the last 0.1 s)
    with its top below the column's height (a slope, not a standing column) and above the
    water's still depth (0.075 m; a heap, not a levelled layer).
usage: granular_dam_break.py PICDEM SOURCE_DIR WORK_DIR
"""
import csv
import os
import sys

import case_check

WATER_BY, WALL, REST, STILL_DEPTH = 0.4, 0.595, 0.0025, 0.075


def main():
    picdem, source, work = sys.argv[1:4]
    case_dir = os.path.join(source, "cases", "granular_dam_break")
    water, grains = case_check.fresh(work, "water"), case_check.fresh(work, "grains")
    case_check.run([picdem, os.path.join(case_dir, "water.yaml"), "--output", water, "--set", "time/end=0.5",
         "--set", "checkpoint/at_end=false"])
    console = case_check.run([picdem, os.path.join(case_dir, "case.yaml"), "--output", grains,
                              "--set", "checkpoint/at_end=false"])
    print("resolution of the grains' run: " + case_check.resolution(console, grains))
    t_water = None
    with open(os.path.join(water, "timeseries.csv")) as f:
        for r in csv.DictReader(f):
            if t_water is None and float(r["front_x"]) >= WALL:
                t_water = float(r["t"])
    analyse = case_check.case_module(case_dir)
    m = analyse.at_end(os.path.join(grains, "solids.csv"))
    t_grains = next((t for t, f, _ in m["series"] if f >= WALL), None)
    print(f"cases/granular_dam_break: water (5 mm cells, 1 rank) at the far wall at t = {t_water} s "
          f"(paper: before {WATER_BY} s); grains (300 disks, 2 mm cells, 1 rank) at t = {t_grains}"
          f" s (output every 0.05 s); grains at {m['t_end']:.2f} s: front {m['L_inf']:.4f} m "
          f"({m['L_prev']:.4f} 0.1 s before), top {m['H_inf']:.4f} m ({m['H_prev']:.4f}), "
          f"H0 {m['H0']:.4f} m, face {m['angle']:.1f} deg")
    failures = []
    if t_water is None or t_water >= WATER_BY:
        failures.append(f"water not at the far wall before {WATER_BY} s")
    if t_water is not None and t_grains is not None and t_grains <= t_water:
        failures.append("grains reached the far wall no later than the water")
    if abs(m["L_inf"] - m["L_prev"]) > REST or abs(m["H_inf"] - m["H_prev"]) > REST:
        failures.append("grains not at rest over the last 0.1 s")
    if not STILL_DEPTH < m["H_inf"] < m["H0"]:
        failures.append(f"deposit top {m['H_inf']:.4f} m not between the water's still depth "
                        f"{STILL_DEPTH} m and the column's height {m['H0']:.4f} m")
    case_check.verdict(failures)


if __name__ == "__main__":
    main()
