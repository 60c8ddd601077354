#!/usr/bin/env python3
"""A cheap subset of the granular column collapse (cases/granular_column_collapse, README.md).

Two columns of 500 disks, a = 2 (L0 = 0.1056 m) and a = 8 (L0 = 0.0528 m), run concurrently
through the `picdem` executable (one rank each). From each solids.csv (analyse.py's measures):
  - the deposit is at rest: runout and height change by less than d50 = 5 mm in the last 0.1 s;
  - the exponents between the two runs, of (L_inf - L0)/L0 and of H_inf/L0 against a, lie in
    the ranges reported for 2D collapses: runout 0.60..1.0 (Lube et al. 2005: 2/3 for a > 2.8;
    Balmforth & Kerswell 2005: 0.65 +- 0.05 in narrow slots, 0.9 +- 0.1 in wide channels; Staron
    & Hinch 2005, discrete 2D: the same 2/3 power law), height 1/3..1/2 (Lube et al. 2005: 2/5;
    Balmforth & Kerswell 2005: 0.4 wide, 0.5 narrow; true-2D rods: 1/3).
usage: column_collapse_executable.py PICDEM SOURCE_DIR WORK_DIR
"""
import math
import os
import shutil
import subprocess
import sys

RUNS = {2: (0.1056, 1.1), 8: (0.0528, 1.5)}  # a: (L0, end time)
N = 500
RUNOUT_RANGE, HEIGHT_RANGE = (0.60, 1.0), (1.0 / 3.0, 0.5)
D50 = 0.005


def run(picdem, case_dir, work):
    """Both runs at once; exits on a failed run."""
    procs = {}
    for a, (l0, end) in RUNS.items():
        out = os.path.join(work, f"a{a}")
        shutil.rmtree(out, ignore_errors=True)
        cmd = [picdem, os.path.join(case_dir, "case.yaml"), "--output", out,
               "--set", f"time/end={end}", "--set", f"solids/grains/count={N}",
               "--set", f"solids/grains/region=[0, 0.006, {l0}, 0.8]"]
        procs[a] = (cmd, subprocess.Popen(cmd, stdout=subprocess.PIPE,
                                          stderr=subprocess.STDOUT, text=True))
    for a, (cmd, p) in procs.items():
        log = p.communicate()[0]
        if p.returncode != 0:
            sys.exit(f"FAIL: {' '.join(cmd)} exited {p.returncode}:\n{log[-3000:]}")


def check(case_dir, work):
    """The measures and the checks on WORK_DIR/a2 and a8; returns the failures."""
    sys.path.insert(0, case_dir)
    import analyse
    failures, res = [], {}
    for a in RUNS:
        fr = analyse.frames(os.path.join(work, f"a{a}", "solids.csv"))
        ts = sorted(fr)
        t_prev = min(ts, key=lambda t: abs(t - (ts[-1] - 0.1)))
        l0 = RUNS[a][0]
        h0 = analyse.height(fr[ts[0]])
        l_inf, ejected = analyse.runout(fr[ts[-1]])
        l_prev, _ = analyse.runout(fr[t_prev])
        h_inf, h_prev = analyse.height(fr[ts[-1]]), analyse.height(fr[t_prev])
        res[a] = (h0 / l0, (l_inf - l0) / l0, h_inf / l0)
        print(f"a = {a} (measured {h0 / l0:.3f}): L_inf = {l_inf:.4f} m ({l_prev:.4f} 0.1 s "
              f"before), H_inf = {h_inf:.4f} m ({h_prev:.4f}), ejected {ejected}, "
              f"(L_inf-L0)/L0 = {res[a][1]:.3f}, H_inf/L0 = {res[a][2]:.3f}")
        if abs(l_inf - l_prev) >= D50 or abs(h_inf - h_prev) >= D50:
            failures.append(f"a = {a}: not at rest at the end")
    (a1, r1, h1), (a2, r2, h2) = res[2], res[8]
    br = math.log(r2 / r1) / math.log(a2 / a1)
    bh = math.log(h2 / h1) / math.log(a2 / a1)
    print(f"exponents: runout {br:.3f} (allowed {RUNOUT_RANGE}), height {bh:.3f} "
          f"(allowed {HEIGHT_RANGE[0]:.3f}..{HEIGHT_RANGE[1]})")
    if not RUNOUT_RANGE[0] <= br <= RUNOUT_RANGE[1]:
        failures.append(f"runout exponent {br:.3f} outside {RUNOUT_RANGE}")
    if not HEIGHT_RANGE[0] <= bh <= HEIGHT_RANGE[1]:
        failures.append(f"height exponent {bh:.3f} outside {HEIGHT_RANGE}")
    return failures


def main():
    picdem, source, work = sys.argv[1:4]
    case_dir = os.path.join(source, "cases", "granular_column_collapse")
    os.makedirs(work, exist_ok=True)
    run(picdem, case_dir, work)
    failures = check(case_dir, work)
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("PASS")


if __name__ == "__main__":
    main()
