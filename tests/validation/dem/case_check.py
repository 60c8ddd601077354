"""What the granular case checks (angle_of_repose_slot.py, column_collapse_small.py,
granular_dam_break.py, granular_sorting.py) share: a fresh output directory, a run of the
`picdem` executable that fails the check when it fails, the case's analysis script, the verdict.
"""
import importlib
import os
import shutil
import subprocess
import sys


def fresh(work, name):
    """WORK/name, emptied (WORK created if missing)."""
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(work, exist_ok=True)
    return out


def run(cmd):
    """Runs cmd (picdem and its arguments); exits with FAIL and the output's tail if it fails."""
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {r.returncode}:\n{r.stdout[-3000:]}")


def case_module(case_dir, name="analyse"):
    """The module `name` of cases/<case> (its analysis script)."""
    sys.path.insert(0, case_dir)
    return importlib.import_module(name)


def verdict(failures):
    """Exits with FAIL and the failures joined, or prints PASS."""
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("PASS")
