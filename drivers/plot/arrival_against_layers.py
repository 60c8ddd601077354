#!/usr/bin/python3
"""First arrival of a cylinder at the right wall against the number of layers, with gap damping
(beta 0.5) and without (beta 1.0): the paper's Fig. 10 from picdem's runs.

usage: arrival_against_layers.py LOG [LOG ...] [--out arrival_against_layers.png] [--title T]
Each LOG is the output of tests/validation/coupled/test_dam_break_cylinders (its lines
"N layers, beta B: arrival T s, volume change ..."); a later line for the same N and B replaces an
earlier one. Prints the table it plots.
"""
import argparse
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LINE = re.compile(r"^(\d+) layers, beta ([0-9.]+): arrival ([0-9.]+|inf) s, volume change ([0-9.]+)%")


def read(logs):
    runs = {}
    for log in logs:
        with open(log, errors="replace") as f:
            for line in f:
                m = LINE.match(line.strip())
                if m:
                    runs[(int(m[1]), float(m[2]))] = (float(m[3]), float(m[4]))
    return runs


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("logs", nargs="+", help="outputs of test_validation_dam_break_cylinders")
    ap.add_argument("--out", default="arrival_against_layers.png", help="the PNG to write")
    ap.add_argument("--title", default="", help="the plot's title")
    a = ap.parse_args()
    runs = read(a.logs)
    if not runs:
        raise SystemExit("no 'N layers, beta B: arrival T s' line in " + ", ".join(a.logs))
    print("layers  beta  arrival [s]  worst volume change [%]")
    for (n, beta), (t, dv) in sorted(runs.items()):
        print(f"{n:6d}  {beta:4.1f}  {t:11.3f}  {dv:6.2f}")
    fig, ax = plt.subplots(figsize=(5, 3.6))
    for beta, style, label in ((0.5, "o-", "gap damping (beta 0.5)"), (1.0, "s--", "none (beta 1.0)")):
        pts = sorted((n, t) for (n, b), (t, _) in runs.items() if b == beta)
        if pts:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], style, label=label)
    ax.set_xlabel("layers of cylinders")
    ax.set_ylabel("first arrival at the right wall [s]")
    ax.set_xticks(sorted({n for n, _ in runs}))
    ax.set(title=a.title)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)
    print("wrote", a.out)


if __name__ == "__main__":
    main()
