#!/usr/bin/env python3
"""Front and top of each column against time, for runs finished or not (doc/validation.md).

usage: plot_fronts.py OUT_DIR PNG [SMALL_DIR]
OUT_DIR: sweep.sh's output (OUT_DIR/a<a>/solids.csv, widths of analyse.WIDTH); SMALL_DIR: the
300-disk a = 0.5 run (L0 = 0.1651 m, doc/validation.md), drawn dashed.
"""
import os
import sys

import analyse


def main():
    out, png = sys.argv[1], sys.argv[2]
    runs = [(os.path.join(out, f"a{a:g}", "solids.csv"), l0, f"a = {a:g}, 1000 disks")
            for a, l0 in analyse.WIDTH.items()]
    if len(sys.argv) > 3:
        runs.append((os.path.join(sys.argv[3], "solids.csv"), 0.1651, "a = 0.5, 300 disks"))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for path, l0, label in runs:
        if not os.path.exists(path):
            continue
        fr = analyse.frames(path)
        ts = sorted(fr)
        h0 = analyse.height(fr[ts[0]])
        a = h0 / l0
        style = "--" if "300" in label else "-"
        ax[0].plot(ts, [(analyse.runout(fr[t])[0] - l0) / l0 / a for t in ts], style, label=label)
        ax[1].plot(ts, [analyse.height(fr[t]) / h0 for t in ts], style, label=label)
    ax[0].axhspan(1.2, 1.8, color="grey", alpha=0.2, label="small-a band 1.2-1.8 (Lube; Lajeunesse)")
    ax[0].set_xlabel("t [s]")
    ax[0].set_ylabel("(front - L0) / (L0 a)")
    ax[0].legend(fontsize=7)
    ax[1].set_xlabel("t [s]")
    ax[1].set_ylabel("top / H0")
    ax[1].legend(fontsize=7)
    fig.suptitle("Granular column collapse, runs as far as they got", fontsize=9)
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    print("wrote", png)


if __name__ == "__main__":
    main()
