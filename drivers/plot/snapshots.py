#!/usr/bin/python3
"""A grid of picdem pictures: one row per run, one column per time.

usage: snapshots.py RUN_DIR [RUN_DIR ...] --times 0.1 0.2 0.3 [--labels a b] [--crop-top F]
                    [--out snapshots.png]
Each RUN_DIR is a picdem output directory: pictures/frame_NNNNNN.png is written every
output/interval seconds (read from case_resolved.yaml), frame 0 at t = 0. A time that is not a
multiple of the interval takes the nearest frame, and the title gives that frame's time.
--crop-top F leaves out the top fraction F of every picture (empty air above the water).
"""
import argparse
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


def output_interval(run):
    """output/interval from the resolved case file: 'interval:' inside the 'output:' block."""
    indent = None
    with open(os.path.join(run, "case_resolved.yaml")) as f:
        for line in f:
            m = re.match(r"^(\s*)(\w+):\s*(.*?)\s*$", line)
            if not m:
                continue
            depth, key, value = len(m.group(1)), m.group(2), m.group(3)
            if indent is not None and depth <= indent:
                indent = None
            if key == "output" and not value:
                indent = depth
            elif indent is not None and key == "interval":
                return float(value)
    raise SystemExit(f"{run}: no output/interval in case_resolved.yaml")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--times", nargs="+", type=float, required=True)
    ap.add_argument("--labels", nargs="*")
    ap.add_argument("--crop-top", type=float, default=0.0)
    ap.add_argument("--out", default="snapshots.png")
    args = ap.parse_args()
    rows, cols = len(args.runs), len(args.times)
    fig, axes = plt.subplots(rows, cols, figsize=(2.6 * cols, 1.9 * (1 - args.crop_top) * rows + 0.5), squeeze=False)
    for r, run in enumerate(args.runs):
        dt = output_interval(run)
        label = args.labels[r] if args.labels and r < len(args.labels) else os.path.basename(run.rstrip("/"))
        for c, t in enumerate(args.times):
            n = int(round(t / dt))
            path = os.path.join(run, "pictures", f"frame_{n:06d}.png")
            ax = axes[r][c]
            ax.set_xticks([])
            ax.set_yticks([])
            if not os.path.exists(path):
                raise SystemExit(f"{path} is missing: the run ends before t = {t} s")
            image = mpimg.imread(path)
            ax.imshow(image[int(args.crop_top * image.shape[0]):])
            if r == 0:
                ax.set_title(f"t = {n * dt:.2f} s", fontsize=9)
            if c == 0:
                ax.set_ylabel(label, fontsize=9)
    fig.tight_layout()
    fig.savefig(args.out, dpi=130)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
