#!/usr/bin/python3
"""Plots the dry collapse mean centre (simulation curves) over the experiment points.

Usage: python3 doc/dem_dry_collapse_plot.py [folder with dem_dry_collapse_<model>.csv] [out.png]
The CSV files are written by the validation test test_dem_dry_collapse (in its build folder);
copies are kept in doc/. The experiment is tests/validation/data/zhang2009_dry_collapse_6layers.csv.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
folder = sys.argv[1] if len(sys.argv) > 1 else here
out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "dem_dry_collapse.png")
experiment = os.path.join(here, "..", "tests", "validation", "data", "zhang2009_dry_collapse_6layers.csv")


def read(path):
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    head, data = rows[0], rows[1:]
    return {k: [float(r[i]) for r in data] for i, k in enumerate(head)}


exp = read(experiment)
fig, ax = plt.subplots(figsize=(6.4, 4.2))
styles = {"one_step": ("C0", "one-step tangential spring (paper eq. 8)"),
          "accumulated": ("C1", "accumulated tangential spring (Zhang et al. 2009)")}
for model, (colour, label) in styles.items():
    path = os.path.join(folder, "dem_dry_collapse_%s.csv" % model)
    if not os.path.exists(path):
        continue
    sim = read(path)
    ax.plot(sim["t_s"], sim["xc_over_L"], "-", color=colour, label="x/L, " + label)
    ax.plot(sim["t_s"], sim["zc_over_L"], "--", color=colour, label="z/L, " + label)
ax.plot(exp["t_s"], exp["xc_over_L"], "ko", label="x/L, experiment (Zhang et al. 2009)")
ax.plot(exp["t_s"], exp["zc_over_L"], "ks", mfc="none", label="z/L, experiment")
for t, x, z in zip(exp["t_s"][1:], exp["xc_over_L"][1:], exp["zc_over_L"][1:]):
    ax.errorbar(t, x, yerr=0.03, color="k", capsize=3, lw=0.8)
    ax.errorbar(t, z, yerr=0.015, color="k", capsize=3, lw=0.8)
ax.set_xlabel("t [s]")
ax.set_ylabel("mean cylinder centre / L")
ax.set_title("Dry collapse of 6 cylinder layers, h = 0.5 mm (bars: test tolerances)")
ax.legend(fontsize=7)
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(out, dpi=120)
print("wrote", out)
