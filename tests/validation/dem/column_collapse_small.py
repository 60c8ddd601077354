#!/usr/bin/env python3
"""Granular column collapse at a = 1 (cases/granular_column_collapse), a CI-sized check.

The case as its case.yaml sets it (d 4 to 6 mm, uniform in ln d by number, density 2500,
mu = 0.5, poured with 512 landing places tried per grain: a settled packing; the accumulated
tangential spring: static friction, the paper's one-step spring creeps under any load,
doc/dem.md) with 400 disks instead of 1,000 in a box L0 = 0.1228 m wide against the left wall
(H0 = 0.1235 m, a = 1.006), released at t = 0 on the toothed floor; 1.0 s through the `picdem`
executable on one rank. From its solids.csv, with the case's analyse.py:
  - the normalised runout (L_inf - L0)/L0 lies within the published 2D experiments at this a:
    from 1.2 a (Lube et al. 2005, Phys. Rev. E 72, 041301: sand, rice and sugar in a channel,
    a < 1.8; Lajeunesse et al. 2005, glass beads, give 1.8 a below a = 3; both as consolidated by
    Lagree, Staron & Popinet 2011, J. Fluid Mech. 686, 378, eq. 3.1) up to 3.25 a^0.96 (true 2D
    columns of aluminium rods, i.e. disks, 0.65 <= a <= 1.5: "Failure mechanism of true 2D
    granular flows", arXiv:1512.05180, 2015). The band is the spread of those published fits,
    not a margin around picdem's value;
  - the final height H_inf/H0 within HEIGHT_TOL (relative) of the true-2D rods' law
    h0/h_inf = 1.42 a^(2/3) (a >= 0.65, the same source); the quasi-2D experiments keep H_inf =
    H0 below a = 1.15 (Lube et al.), which 2D disks do not (doc/validation.md);
  - the deposit is at rest: front and top moved by less than REST over the last 0.1 s.
usage: column_collapse_small.py PICDEM SOURCE_DIR WORK_DIR
"""
import os
import sys

import case_check

L0, COUNT, T_END = 0.1228, 400, 1.0
HEIGHT_TOL = 0.10  # relative; chosen, not a published scatter
REST = 0.0025  # m, half a grain's diameter


def runout_band(a):
    """(L_inf - L0)/L0: Lube et al.'s 1.2 a to the true-2D rods' 3.25 a^0.96."""
    return 1.2 * a, 3.25 * a**0.96


def height_rods(a):
    """H_inf/H0 of the true-2D rods: 1 below a = 0.65, 1 / (1.42 a^(2/3)) above."""
    return 1.0 if a < 0.65 else 1.0 / (1.42 * a ** (2.0 / 3.0))


def main():
    picdem, source, work = sys.argv[1:4]
    case_dir = os.path.join(source, "cases", "granular_column_collapse")
    out = case_check.fresh(work, "a1_n400")
    cmd = [picdem, os.path.join(case_dir, "case.yaml"), "--output", out,
           "--set", f"time/end={T_END}", "--set", f"solids/grains/count={COUNT}",
           "--set", f"solids/grains/region=[0, 0.006, {L0}, 0.8]",
           "--set", "checkpoint/at_end=false"]
    print("resolution: " + case_check.resolution(case_check.run(cmd), out))
    analyse = case_check.case_module(case_dir)
    fr = analyse.frames(os.path.join(out, "solids.csv"))
    ts = sorted(fr)
    t_end = ts[-1]
    t_prev = min(ts, key=lambda t: abs(t - (t_end - 0.1)))
    h0 = analyse.height(fr[ts[0]])
    a = h0 / L0
    l_inf, ejected = analyse.runout(fr[t_end])
    l_prev, _ = analyse.runout(fr[t_prev])
    h_inf, h_prev = analyse.height(fr[t_end]), analyse.height(fr[t_prev])
    run = (l_inf - L0) / L0
    band = runout_band(a)
    h_ref = height_rods(a)
    print(f"cases/granular_column_collapse, {len(fr[ts[0]])} disks, L0 = {L0} m, H0 = {h0:.4f} m, "
          f"a = {a:.3f}, t = {t_end:.2f} s: L_inf = {l_inf:.4f} m ({l_prev:.4f} 0.1 s before), "
          f"(L_inf - L0)/L0 = {run:.3f} = {run / a:.3f} a (band {band[0]:.3f}..{band[1]:.3f}: "
          f"1.2 a Lube et al. to 3.25 a^0.96 true-2D rods; Lajeunesse et al. 1.8 a = {1.8 * a:.3f})"
          f"; H_inf = {h_inf:.4f} m ({h_prev:.4f} 0.1 s before) = {h_inf / h0:.3f} H0 (rods "
          f"{h_ref:.3f} +- {HEIGHT_TOL:.0%}) = {h_inf / L0:.3f} L0; {ejected} grains ejected")
    failures = []
    if abs(l_inf - l_prev) > REST or abs(h_inf - h_prev) > REST:
        failures.append(f"front or top moved by more than {REST} m over the last 0.1 s: "
                        f"not at rest")
    if not band[0] <= run <= band[1]:
        failures.append(f"runout {run:.3f} outside {band[0]:.3f}..{band[1]:.3f}")
    if abs(h_inf / h0 - h_ref) > HEIGHT_TOL * h_ref:
        failures.append(f"height {h_inf / h0:.3f} H0 not within {HEIGHT_TOL:.0%} of {h_ref:.3f}")
    case_check.verdict(failures)


if __name__ == "__main__":
    main()
