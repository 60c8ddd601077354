#!/usr/bin/env python3
"""Angle of repose of the dumped heaps: a straight-line fit to each flank of the heap's surface.

Reads OUT_DIR/mu<mu>_mur<mur>/solids.csv (t, id, x, z, ...) written by sweep.sh. The surface is
the highest grain centre in bins of width d50 (10 mm) along x; the grains' radii are not in
solids.csv, and a constant offset (centre + d50/2) would not change a slope. A flank's points:
bins outside the container's footprint (|x - xc| > W/2 + wall + d50: under the mouth the surface
is the column still falling or resting in the container), from the footprint outwards up to the
first empty bin (grains bounced beyond the deposit are left out), and with the surface at least
1.5 d50 above the teeth's tips (the toe, one or two grains thick, is left out). Each flank is
fitted by least squares; the angle is atan(|slope|), and the heap's angle the mean of both flanks.
Rest: the same angles 0.2 s before the end, and the fastest grain at the end.
Writes OUT_DIR/angle_of_repose.csv and, with matplotlib, OUT_DIR/angle_of_repose.png.
usage: analyse.py OUT_DIR
"""
import csv
import math
import os
import sys

XC, HALF_FOOT, D50, FLOOR, BIN = 0.8, 0.15 + 0.01 + 0.01, 0.01, 0.004, 0.01
MPS_MU, MPS_DEG, MPS_DEM_DEG = 0.1, 22.3, 22.5


def frames(path):
    out = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            out.setdefault(float(r["t"]), []).append(
                (float(r["x"]), float(r["z"]), math.hypot(float(r["u"]), float(r["w"]))))
    return out


def surface(grains):
    top = {}
    for x, z, _ in grains:
        k = math.floor(x / BIN)
        top[k] = max(top.get(k, -1.0), z)
    return top


def flank(top, side):
    """(x, z) of the surface bins of one flank, from the footprint outwards (side = -1 or +1)."""
    pts = []
    k = math.floor((XC + side * HALF_FOOT) / BIN)
    while k in top:
        x = (k + 0.5) * BIN
        if side * (x - XC) > HALF_FOOT and top[k] + D50 / 2 - FLOOR >= 1.5 * D50:
            pts.append((x, top[k]))
        k += side
    return pts


def slope_deg(pts):
    if len(pts) < 3:
        return float("nan")
    n = len(pts)
    mx = sum(p[0] for p in pts) / n
    mz = sum(p[1] for p in pts) / n
    b = sum((p[0] - mx) * (p[1] - mz) for p in pts) / sum((p[0] - mx) ** 2 for p in pts)
    return math.degrees(math.atan(abs(b)))


def angles(grains):
    top = surface(grains)
    left, right = flank(top, -1), flank(top, +1)
    a_l, a_r = slope_deg(left), slope_deg(right)
    height = max(top.values()) + D50 / 2 - FLOOR if top else 0.0
    xs = [x for x, _, _ in grains]
    return a_l, a_r, (a_l + a_r) / 2, len(left), len(right), height, min(xs), max(xs)


def runs(out):
    for name in sorted(os.listdir(out)):
        path = os.path.join(out, name, "solids.csv")
        if name.startswith("mu") and os.path.exists(path):
            mu, mur = name[2:].split("_mur")
            yield float(mu), float(mur), name, path


def main():
    out = sys.argv[1]
    rows = []
    for mu, mur, name, path in runs(out):
        fr = frames(path)
        ts = sorted(fr)
        t_end = ts[-1]
        t_prev = min(ts, key=lambda t: abs(t - (t_end - 0.2)))
        a_l, a_r, a, n_l, n_r, h, x0, x1 = angles(fr[t_end])
        rows.append(dict(mu=mu, mur=mur, t_end=t_end, left=a_l, right=a_r, angle=a, n_left=n_l,
                         n_right=n_r, height=h, x_min=x0, x_max=x1,
                         angle_prev=angles(fr[t_prev])[2],
                         vmax=max(v for _, _, v in fr[t_end]),
                         in_container=sum(1 for _, z, _ in fr[t_end] if z > 0.17)))
    print("mu    mu_r  t_end  left   right  angle [deg] (0.2 s before)  points L/R  height [m]"
          "  x range [m]      v_max [m/s]  left in container")
    for r in rows:
        print(f"{r['mu']:<5g} {r['mur']:<5g} {r['t_end']:.2f}  {r['left']:5.1f}  {r['right']:5.1f}"
              f"  {r['angle']:5.1f}       ({r['angle_prev']:5.1f})         {r['n_left']:3d}/{r['n_right']:<3d}"
              f"    {r['height']:.3f}      {r['x_min']:.3f}-{r['x_max']:.3f}  {r['vmax']:.3f}"
              f"        {r['in_container']}")
    keys = ["mu", "mur", "t_end", "left", "right", "angle", "angle_prev", "n_left", "n_right",
            "height", "x_min", "x_max", "vmax", "in_container"]
    with open(os.path.join(out, "angle_of_repose.csv"), "w") as f:
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join(f"{r[k]:.6g}" for k in keys) + "\n")
    plot(rows, out)


def plot(rows, out):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not found: no plot")
        return
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    for mur, style in ((0.0, "ko-"), (0.1, "bs-")):
        sel = sorted((r for r in rows if r["mur"] == mur), key=lambda r: r["mu"])
        if sel:
            ax[0].plot([r["mu"] for r in sel], [r["angle"] for r in sel], style,
                       label=f"picdem, 2D disks, mu_r = {mur:g}")
    ax[0].plot([MPS_MU], [MPS_DEG], "r^", ms=9, label="Kim et al. 2018, MPS (22.3 deg)")
    ax[0].plot([MPS_MU], [MPS_DEM_DEG], "gv", ms=9, label="Kim et al. 2018, their DEM (22.5 deg)")
    mus = [0.05 + 0.01 * k for k in range(41)]
    ax[0].plot(mus, [math.degrees(math.atan(m)) for m in mus], "k:", lw=0.8, label="atan(mu)")
    ax[0].set_xlabel("friction coefficient mu")
    ax[0].set_ylabel("angle of repose [deg]")
    ax[0].legend(fontsize=7)
    for mu, mur, name, path in runs(out):
        fr = frames(path)
        top = surface(fr[max(fr)])
        ks = sorted(top)
        ax[1].plot([(k + 0.5) * BIN for k in ks], [top[k] + D50 / 2 for k in ks],
                   "-" if mur == 0 else "--", lw=1, label=f"mu {mu:g}, mu_r {mur:g}")
    ax[1].axhline(0.17, color="grey", lw=0.5)
    ax[1].set_xlabel("x [m]")
    ax[1].set_ylabel("surface height [m] (top grain, centre + d50/2)")
    ax[1].legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "angle_of_repose.png"), dpi=110)
    print("wrote", os.path.join(out, "angle_of_repose.png"))


if __name__ == "__main__":
    main()
