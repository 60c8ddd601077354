"""picdem.log and run.yaml (doc/output.md) of real runs, parsed with PyYAML.
usage: check_run_record.py OUTPUT_DIR RANKS CASE_FILE -- MPIEXEC... PICDEM

OUTPUT_DIR is the fixture's run (its console output in OUTPUT_DIR.stdout). Asserted there: the log
equals the console output line for line; run.yaml holds version, git hash, code version, host,
ranks, decomposition (the cut lines against the checkpoint's blocks), start and end dates, wall time, steps, time and exit status consistent with
the run (timeseries.csv, frame attributes, this machine). Then five more runs: a restart from the
fixture's checkpoint appends to the log and records where it started; the finished fixture
restarted as it stands runs no step and says so; a cell size that does not divide the tank
says the tank's size in whole cells; a restart from a missing
file (input error, exit 2) and a run that blows up (solver error, exit 3) each leave run.yaml with
their status, exit code, message and steps, and the error line at the end of the log.
"""
import datetime
import os
import re
import shutil
import socket
import subprocess
import sys

import h5py
import yaml
from check_support import check, finish

out, ranks, case = sys.argv[1], int(sys.argv[2]), sys.argv[3]
launch = sys.argv[sys.argv.index("--") + 1:]
mpiexec, picdem = launch[:-1], launch[-1]
KEYS = ["version", "git_hash", "code_version", "command", "case_file", "case_name", "output",
        "restarted_from", "host", "ranks", "decomposition", "started", "finished", "wall_seconds",
        "first_step", "steps", "steps_this_run", "time", "status", "exit_code", "message"]


def record(directory):
    with open(os.path.join(directory, "run.yaml")) as f:
        r = yaml.safe_load(f)
    check(list(r) == KEYS, f"{directory}/run.yaml keys {list(r)}")
    return r


def log_lines(directory):
    with open(os.path.join(directory, "picdem.log")) as f:
        return f.read().splitlines()


def run(n, directory, *args):
    cmd = mpiexec + ["-n", str(n), picdem, case, "-o", directory, *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=300).returncode


def date(s):
    return datetime.datetime.strptime(s, "%Y-%m-%dT%H:%M:%SZ").replace(tzinfo=datetime.timezone.utc)


# The fixture's run.
r = record(out)
with open(out + ".stdout") as f:
    check(log_lines(out) == f.read().splitlines(), "picdem.log differs from the console output")
rows = open(os.path.join(out, "timeseries.csv")).read().splitlines()
last = dict(zip(rows[0].split(","), rows[-1].split(",")))
check(r["status"] == "completed" and r["exit_code"] == 0 and r["message"] is None, "status")
split = r["decomposition"]
check(r["ranks"] == ranks and split["method"] == "weighted" and split["ranks"] == [2, 1],
      f"ranks {r['ranks']} {split}")
# The cut lines are those the run ended with: the owned cell boxes in its last checkpoint
# (grid/boxes: per rank FaceX, FaceZ, Cell, each storage then owned box as i0, i1, k0, k1).
with h5py.File(os.path.join(out, "checkpoints", "checkpoint_%08d.h5" % r["steps"]), "r") as f:
    boxes = [int(v) for v in f["grid/boxes"][...].ravel()]
owned = [boxes[24 * n + 20:24 * n + 24] for n in range(len(boxes) // 24)]
x_cuts = sorted({b[0] for b in owned} | {b[1] for b in owned})
z_cuts = sorted({b[2] for b in owned} | {b[3] for b in owned})
check(split["x_cuts"] == x_cuts and split["z_cuts"] == z_cuts,
      f"cut lines {split['x_cuts']} {split['z_cuts']} against the checkpoint's {x_cuts} {z_cuts}")
check(0 < split["x_cuts"][1] < split["x_cuts"][2], f"x cuts {split['x_cuts']}")
check(r["steps"] == int(last["step"]) == r["steps_this_run"] and r["first_step"] == 0, "steps")
check(r["time"] == float(last["t"]), f"time {r['time']} != timeseries {last['t']}")
check(r["code_version"].startswith(r["version"] + " "), "version and code_version disagree")
check(re.fullmatch(r"[0-9a-f]{40}(-dirty)?", r["git_hash"]) is not None, f"git hash {r['git_hash']}")
check(r["git_hash"][:7] in r["code_version"], "git hash not in code_version")
check(r["host"] == socket.gethostname(), f"host {r['host']}")
check(r["case_name"] == "output_small" and r["case_file"] == case, "case")
check(os.path.samefile(r["output"], out) and r["restarted_from"] is None, "output folder")
start, end = date(r["started"]), date(r["finished"])
now = datetime.datetime.now(datetime.timezone.utc)
check(start <= end <= now and now - start < datetime.timedelta(hours=1), "dates")
check(0 < r["wall_seconds"] <= (end - start).total_seconds() + 1.0, f"wall {r['wall_seconds']}")

# A restart from the fixture's checkpoint, in a copy: the log goes on, run.yaml says where from.
again = out + "_restart"
shutil.rmtree(again, ignore_errors=True)
shutil.copytree(out, again)
checkpoint = os.path.join(again, "checkpoints", "checkpoint_%08d.h5" % r["steps"])
code = run(ranks, again, "--restart", checkpoint, "--set", "time/end=1",
           "--max-steps", str(r["steps"] + 2))
check(code == 0, f"restart exit code {code}")
r2, before, after = record(again), log_lines(out), log_lines(again)
check(after[:len(before)] == before and len(after) > len(before), "the restart's log does not go on")
check(any("restarted from" in line for line in after[len(before):]), "no restart line in the log")
check(r2["restarted_from"] == checkpoint and r2["first_step"] == r["steps"] and
      r2["steps"] == r["steps"] + 2 and r2["steps_this_run"] == 2 and r2["status"] == "completed",
      f"restart record {r2}")

# The finished fixture restarted with its own time/end (a job script that always passes
# --restart latest): no step, a note saying so, no progress line, exit 0.
done = out + "_finished"
shutil.rmtree(done, ignore_errors=True)
shutil.copytree(out, done)
code = run(ranks, done, "--restart", "latest")
r5, tail = record(done), log_lines(done)[len(log_lines(out)):]
check(code == 0 and r5["status"] == "completed" and r5["steps_this_run"] == 0 and
      r5["steps"] == r["steps"], f"finished run restarted: exit {code}, record {r5}")
check(any("no step to run" in line and "time/end" in line for line in tail),
      f"no note that the checkpoint is at time/end: {tail}")
check(not any(line.startswith("[") for line in tail), f"a progress line: {tail}")

# A cell size that does not divide the tank: the log gives the tank's size in whole cells
# (0.12 m / 0.0023 m = 52.17 cells: 52 cells, 0.1196 m).
odd = out + "_odd_cells"
shutil.rmtree(odd, ignore_errors=True)
code = run(1, odd, "--set", "grid/cell_size=0.0023", "--max-steps", "1")
notes = [line for line in log_lines(odd) if line.startswith("picdem: grid/length = 0.12 m")]
check(code == 0 and len(notes) == 1 and "the tank is 52 cells, 0.1196 m" in notes[0],
      f"odd cell size: exit {code}, notes {notes}")

# A missing checkpoint: input error after the output folder is known.
bad = out + "_input_error"
shutil.rmtree(bad, ignore_errors=True)
code = run(ranks, bad, "--restart", bad + "/missing.h5")
r3 = record(bad)
check(code != 0 and r3["status"] == "input_error" and r3["exit_code"] == 2, f"input error {r3}")
check("missing.h5" in r3["message"] and r3["steps"] == 0, "input error message / steps")
check(log_lines(bad)[-1] == "picdem: error: " + r3["message"], "input error not last in the log")

# Five times the CFL limit: the run blows up (solver error) at a step it names.
blown = out + "_solver_error"
shutil.rmtree(blown, ignore_errors=True)
code = run(1, blown, "--set", "time/cfl=5", "--set", "time/dt_max=0.01", "--set", "time/end=1",
           "--max-steps", "100")
r4 = record(blown)
check(code == 3 and r4["status"] == "solver_error" and r4["exit_code"] == 3, f"solver error {r4}")
m = re.match(r"step (\d+) at t = ", r4["message"] or "")
check(m is not None and int(m.group(1)) == r4["steps"] and 0 < r4["steps"] < 100, "blow-up step")
check(log_lines(blown)[-1] == "picdem: the run stopped: " + (r4["message"] or ""),
      "solver error not last in the log")

finish(f"run.yaml and picdem.log: fixture ({r['steps']} steps on {ranks} ranks), restart "
       f"(+2 steps), finished run restarted (no step), odd cell size, input error and blow-up "
       f"at step {r4['steps']} recorded")
