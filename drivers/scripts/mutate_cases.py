#!/usr/bin/python3
"""Mutate case files key by key and sort what picdem does with each mutant.

For every leaf key of each case file (of `obstacles` and `solids` only the first two entries),
the value is replaced by a mutant: negative, 0, NaN, inf, 1e30, 1e-30, a text, a list, an
interval swapped, shortened, emptied or moved far away, a boolean as a word, or the key deleted.
Each mutant case is given to `picdem --check`; a mutant that --check accepts runs 3 steps with
PNG and ParaView output off. One JSON line per mutant goes to standard output:

    {"case", "key", "mut", "stage": "check" | "run", "code": exit code or "timeout", "msg"}

Exit codes: 2 refused by --check (or at launch), 3 stopped at run time with a message, 0 ran.
Read the lines with code 0 (a mutant that ran: is its value possible?), "timeout" (a hang) and
anything else (a crash). doc/parameters.md, "Checks before the run", lists what --check refuses.

usage: mutate_cases.py PICDEM WORK_DIR CASE.yaml [CASE.yaml ...] > results.jsonl

PICDEM is best a copy of the executable, so that rebuilding does not disturb a long run; WORK_DIR
holds the mutant file and the 3-step output (one WORK_DIR per concurrent run).
"""
import copy
import json
import math
import os
import shutil
import subprocess
import sys

import yaml

DELETE = object()


def leaves(node, path=()):
    """(path, value) of every leaf; lists of dicts and the obstacle/solid entries: the first two."""
    if isinstance(node, dict):
        items = list(node.items())
        if path and path[-1] in ("obstacles", "solids"):
            items = items[:2]
        for k, v in items:
            yield from leaves(v, path + (k,))
    elif isinstance(node, list) and node and all(isinstance(x, dict) for x in node):
        yield from leaves(node[0], path + (0,))
    else:
        yield path, node


def put(node, path, value):
    for k in path[:-1]:
        node = node[k]
    if value is DELETE:
        del node[path[-1]]
    else:
        node[path[-1]] = value


def mutants(v):
    out = []
    if isinstance(v, bool):
        out += [("str", "maybe"), ("num", 2)]
    elif isinstance(v, (int, float)):
        out += [("neg", -abs(v) - 1 if v == 0 else -v), ("zero", 0), ("nan", math.nan),
                ("inf", math.inf), ("huge", 1e30 if isinstance(v, float) else 10**12),
                ("tiny", 1e-30), ("str", "abc"), ("list", [v, v])]
    elif isinstance(v, str):
        out += [("str", "nonsense_value"), ("num", 3.5), ("empty", "")]
    elif isinstance(v, list):
        if len(v) == 2 and all(isinstance(x, (int, float)) for x in v):
            out += [("swap", [v[1], v[0]]), ("short", [v[0]]), ("empty", []),
                    ("nan", [math.nan, v[1]]), ("far", [v[0] + 1e3, v[1] + 1e3])]
        else:
            out += [("empty", []), ("scalar", 1.0)]
    out.append(("delete", DELETE))
    return out


def run(cmd, timeout):
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        return "timeout", ""


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    picdem, work, cases = sys.argv[1], sys.argv[2], sys.argv[3:]
    os.makedirs(work, exist_ok=True)
    mutant_file, out_dir = os.path.join(work, "mutant.yaml"), os.path.join(work, "out")
    for case in cases:
        base = yaml.safe_load(open(case))
        for path, value in leaves(base):
            for name, new in mutants(value):
                doc = copy.deepcopy(base)
                put(doc, path, new)
                with open(mutant_file, "w") as f:
                    yaml.safe_dump(doc, f)
                code, text = run([picdem, "--check", mutant_file], 60)
                stage = "check"
                if code == 0:
                    shutil.rmtree(out_dir, ignore_errors=True)
                    code, text = run([picdem, mutant_file, "--output", out_dir, "--max-steps", "3",
                                      "--set", "output/png=false", "--set", "output/paraview=false"],
                                     120)
                    stage = "run"
                lines = [l for l in text.strip().splitlines() if l.strip()]
                print(json.dumps({"case": case, "key": "/".join(str(k) for k in path), "mut": name,
                                  "stage": stage, "code": code,
                                  "msg": lines[-1][:300] if lines else ""}), flush=True)


if __name__ == "__main__":
    main()
