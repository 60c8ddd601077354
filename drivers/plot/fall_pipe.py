#!/usr/bin/python3
"""Water levels inside and outside the fall pipe and the cylinders still in the pipe.

usage: fall_pipe.py RUN_DIR [RUN_DIR ...] [--labels a b] [--out fall_pipe.png]
Each RUN_DIR holds a picdem timeseries.csv from a fall-pipe case (level_1 inside the pipe,
level_2 and level_3 left and right of it, solids_in_box the cylinders in the pipe and funnel).
Prints, per run, the time at which the last cylinder left the pipe.
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(run):
    with open(os.path.join(run, "timeseries.csv")) as f:
        rows = list(csv.DictReader(f))
    col = lambda k: [float(r[k]) if r[k] not in ("nan", "") else float("nan") for r in rows]
    return {k: col(k) for k in rows[0].keys()}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--labels", nargs="*")
    ap.add_argument("--out", default="fall_pipe.png")
    args = ap.parse_args()
    fig, (ax_l, ax_n) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for n, run in enumerate(args.runs):
        d = read(run)
        label = args.labels[n] if args.labels and n < len(args.labels) else os.path.basename(run.rstrip("/"))
        t = d["t"]
        line, = ax_l.plot(t, [100 * z for z in d["level_1"]], "-", label=f"{label}: inside the pipe")
        outside = [100 * 0.5 * (a + b) for a, b in zip(d["level_2"], d["level_3"])]
        ax_l.plot(t, outside, "--", color=line.get_color(), label=f"{label}: outside (mean of both sides)")
        ax_n.plot(t, d["solids_in_box"], "-", color=line.get_color(), label=label)
        left = next((ti for ti, c in zip(t, d["solids_in_box"]) if c == 0), None)
        print(f"{label}: " + (f"all cylinders left the pipe at t = {left:.3f} s" if left is not None
                               else f"{int(d['solids_in_box'][-1])} cylinders still in the pipe at t = {t[-1]:.3f} s"))
    ax_l.set_ylabel("water level [cm]")
    ax_l.grid(alpha=0.3)
    ax_l.legend(fontsize=8)
    ax_n.set_ylabel("cylinders in the pipe")
    ax_n.set_xlabel("t [s]")
    ax_n.grid(alpha=0.3)
    ax_n.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=150)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
