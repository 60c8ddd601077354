#!/usr/bin/python3
"""Surge front of a dam-break run against Martin & Moyce (1952).

usage: surge_front.py TIMESERIES.csv [--out front.png] [--a 0.05715] [--label text] [more.csv ...]
Reads t and front_x from each picdem timeseries.csv, plots z/a over tau = t sqrt(2 g / a) on top of
the experiment's points, and prints the relative error at each experimental point with tau <= 3.
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
EXPERIMENT = os.path.join(HERE, "..", "..", "tests", "validation", "data",
                          "martin_moyce1952_surge_front.csv")


def read_columns(path, names):
    with open(path) as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    return [[float(r[n]) for r in rows] for n in names]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--out", default="surge_front.png")
    ap.add_argument("--a", type=float, default=0.05715)
    ap.add_argument("--experiment", default=EXPERIMENT)
    ap.add_argument("--labels", nargs="*")
    args = ap.parse_args()
    scale = math.sqrt(2 * 9.81 / args.a)
    tau_e, z_e = read_columns(args.experiment, ["tau", "z_over_a"])
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(tau_e, z_e, "ko", label="Martin & Moyce (1952)")
    for n, run in enumerate(args.runs):
        t, front = read_columns(run, ["t", "front_x"])
        tau = [0.0] + [x * scale for x in t]
        z = [1.0] + [f / args.a for f in front]
        label = args.labels[n] if args.labels and n < len(args.labels) else run
        ax.plot(tau, z, "-", label=label)
        for te, ze in zip(tau_e, z_e):
            if te <= 3.0:
                zs = next((z[i - 1] + (z[i] - z[i - 1]) * (te - tau[i - 1]) / (tau[i] - tau[i - 1])
                           for i in range(1, len(tau)) if tau[i] >= te), z[-1])
                print(f"{label}: tau {te:.3f} experiment {ze:.3f} simulation {zs:.3f} "
                      f"error {100 * (zs - ze) / ze:+.1f}%")
    ax.set_xlabel(r"$\tau = t\sqrt{2g/a}$")
    ax.set_ylabel("front $z/a$")
    ax.set_xlim(0, max(tau_e) + 0.5)
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=150)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
