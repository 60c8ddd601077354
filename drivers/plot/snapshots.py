#!/usr/bin/python3
"""A grid of picdem pictures: one row per run, one column per time.

usage: snapshots.py RUN_DIR [RUN_DIR ...] --times 0.1 0.2 0.3 [--labels a b] [--crop-top F]
                    [--out snapshots.png]
Each RUN_DIR is a picdem output directory: pictures/frame_NNNNNN.png (NNNNNN = step) is written
every output/interval seconds; the time of each step comes from timeseries.csv. Each time takes
the nearest picture, and the title gives that picture's time.
--crop-top F leaves out the top fraction F of every picture (empty air above the water).
"""
import argparse
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


def pictures_by_time(run):
    """[(t, path)] of the run's pictures pictures/frame_<step>.png, the time of each step read
    from timeseries.csv (step 0 is t = 0)."""
    times = {0: 0.0}
    with open(os.path.join(run, "timeseries.csv")) as f:
        header = f.readline().strip().split(",")
        it, istep = header.index("t"), header.index("step")
        for line in f:
            cols = line.split(",")
            if len(cols) == len(header):
                times[int(float(cols[istep]))] = float(cols[it])
    found = []
    folder = os.path.join(run, "pictures")
    if not os.path.isdir(folder):
        raise SystemExit(f"{run}: no pictures/ folder (the run had output/png false)")
    for name in os.listdir(folder):
        m = re.fullmatch(r"frame_(\d+)\.png", name)
        if m and int(m.group(1)) in times:
            found.append((times[int(m.group(1))], os.path.join(run, "pictures", name)))
    if not found:
        raise SystemExit(f"{run}: no pictures/frame_*.png with a step in timeseries.csv")
    return sorted(found)


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
        pictures = pictures_by_time(run)
        label = args.labels[r] if args.labels and r < len(args.labels) else os.path.basename(run.rstrip("/"))
        for c, t in enumerate(args.times):
            t_frame, path = min(pictures, key=lambda tp: abs(tp[0] - t))
            if t > pictures[-1][0] + 1e-9 and abs(t_frame - t) > 1e-6:
                raise SystemExit(f"{run}: the run ends at t = {pictures[-1][0]} s, before t = {t} s")
            ax = axes[r][c]
            ax.set_xticks([])
            ax.set_yticks([])
            image = mpimg.imread(path)
            ax.imshow(image[int(args.crop_top * image.shape[0]):])
            if r == 0:
                ax.set_title(f"t = {t_frame:.2f} s", fontsize=9)
            if c == 0:
                ax.set_ylabel(label, fontsize=9)
    fig.tight_layout()
    fig.savefig(args.out, dpi=130)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
