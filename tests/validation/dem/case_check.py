"""What the granular case checks (angle_of_repose_slot.py, column_collapse_small.py,
granular_dam_break.py, granular_sorting.py, fall_pipe_graded.py) share: a fresh output
directory, a run of the `picdem` executable that fails the check when it fails, the resolution
the run states, the case's analysis script, the verdict.
"""
import importlib
import os
import shutil
import subprocess
import sys

import yaml


def fresh(work, name):
    """WORK/name, emptied (WORK created if missing)."""
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(work, exist_ok=True)
    return out


def run(cmd):
    """Runs cmd (picdem and its arguments) and returns its console output; exits with FAIL and
    the output's tail if it fails."""
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {r.returncode}:\n{r.stdout[-3000:]}")
    return r.stdout


def resolution(console, out):
    """The resolution a run of `picdem` ran at, as it states it (issue 14): the grid's cell size
    (grid/cell_size in OUT/case_resolved.yaml) and picdem's line on the solids in its console
    output (their number, bounding diameters, dt_DEM and the subcycles at time/dt_max); exits
    with FAIL if the line is missing."""
    line = next((s for s in console.splitlines() if " solids, bounding diameters " in s), None)
    if line is None:
        sys.exit("FAIL: the run's console output states no solids' resolution")
    with open(os.path.join(out, "case_resolved.yaml")) as f:
        grid = yaml.safe_load(f)["case"]["grid"]  # Teuchos: the case under a top list "case"
    return f"grid {grid['cell_size']:g} m; " + line.removeprefix("picdem: ")


def case_module(case_dir, name="analyse"):
    """The module `name` of cases/<case> (its analysis script)."""
    sys.path.insert(0, case_dir)
    return importlib.import_module(name)


def verdict(failures):
    """Exits with FAIL and the failures joined, or prints PASS."""
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("PASS")
