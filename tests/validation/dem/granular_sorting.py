#!/usr/bin/env python3
"""Gravity sorting of grains of three densities (cases/granular_sorting), a CI-sized check.

The case as documented (300 disks of 9 to 11 mm in six layers of light 1500, medium 2500 and heavy
3500 kg/m^3 grains, light at the bottom and heavy on top, run out of the cargo-dump container
through a 0.07 m slot onto a toothed floor 0.17 m below; mu = 0.2, accumulated spring; 2.5 s) run
through the `picdem` executable on one rank; from its solids.csv, with the case's analyse.py:
  - the MPS paper's finding (Kim, Kim, Jang & Cho 2018, "Simulation of solid particle
    interactions including segregated lamination by using MPS method", sec. 5: grains sort into
    density-specific laminae, the heavier below the lighter; the paper gives no number): in the
    heap, the mean depth below the local surface grows with density (light < medium < heavy), and
    the heavy grains lie at least MIN_SEPARATION (a grain's radius) deeper than the medium ones.
    The heavy grains start on top, so they can end deepest only by sorting. The thresholds hold in
    both starting orders: this case gives steps of 8.0 and 9.1 mm, the control with heavy and
    light swapped (case_reversed.yaml, documented in doc/validation.md, not run here) 2.0 and
    7.7 mm, so the light-medium step is asserted as an order only;
  - the pour is over: at most MAX_LEFT grains in the container and none in flight.
usage: granular_sorting.py PICDEM SOURCE_DIR WORK_DIR
"""
import os
import sys

import case_check

MIN_SEPARATION = 0.005  # m
MAX_LEFT = 10


def main():
    picdem, source, work = sys.argv[1:4]
    case_dir = os.path.join(source, "cases", "granular_sorting")
    out = case_check.fresh(work, "sorting")
    cmd = [picdem, os.path.join(case_dir, "case.yaml"), "--output", out,
           "--set", "checkpoint/at_end=false"]
    print("resolution: " + case_check.resolution(case_check.run(cmd), out))
    analyse = case_check.case_module(case_dir)
    analyse.read_layers(out)
    m = analyse.at_end(os.path.join(out, "solids.csv"))
    flying = sum(m["n"]) + m["in_container"]
    print(f"cases/granular_sorting (300 disks, d 9-11 mm, grid 2 mm, gap 2 mm, 1 rank), "
          f"t = {m['t_end']:.2f} s, {m['in_container']} grains left in the container, "
          f"{300 - flying} in flight:")
    for k in range(3):
        print(f"  {analyse.NAMES[k]} ({analyse.DENSITIES[k]} kg/m^3): {m['n'][k]} in the heap, "
              f"depth below the surface {m['depth'][k] * 1000:.1f} mm, mean height "
              f"{m['mean'][k] * 1000:.1f} mm, distance from the axis {m['reach'][k] * 1000:.1f} mm")
    failures = []
    if m["in_container"] > MAX_LEFT or flying < 300:
        failures.append(f"pour not over ({m['in_container']} in the container, "
                        f"{300 - flying} in flight)")
    light, medium, heavy = m["depth"]
    if not light < medium:
        failures.append(f"light grains not shallower than medium ({light * 1000:.1f} against "
                        f"{medium * 1000:.1f} mm below the surface)")
    if heavy - medium < MIN_SEPARATION:
        failures.append(f"heavy grains lie {(heavy - medium) * 1000:.1f} mm deeper than the medium "
                        f"ones (at least {MIN_SEPARATION * 1000:.0f} mm)")
    case_check.verdict(failures)


if __name__ == "__main__":
    main()
