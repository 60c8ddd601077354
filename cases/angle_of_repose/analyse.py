#!/usr/bin/env python3
"""Angle of repose of the heaps poured through the slot: a straight-line fit to each flank.

Reads OUT_DIR/mu<mu>_mur<mur>/solids.csv (t, id, x, z, ...) written by sweep.sh. The surface is
the highest grain centre in bins of width d50 (10 mm) along x, counting only grains below the
mouth (those left in the container are counted apart) and slower than 0.3 m/s (not in flight);
the grains' radii are not in solids.csv, and a constant offset (centre + d50/2) changes no slope.
The heap's height H is the highest bin's top (centre + d50/2) above the teeth's tips. A flank's
points: the bins from the summit outwards up to the first empty bin (grains bounced beyond the
deposit are left out) whose top lies between 0.2 H and 0.8 H (the rounded summit under the slot
and the toe, one or two grains thick, are left out). Each flank is fitted by least squares; the
angle is atan(|slope|), and the heap's angle the mean of both flanks. Rest: the angle and height
0.2 s before the end, the fastest grain and the grains still moving.
Writes OUT_DIR/angle_of_repose.csv and, with matplotlib, OUT_DIR/angle_of_repose.png.
usage: analyse.py OUT_DIR [MOUTH_Z]   (MOUTH_Z: the mouth's height, 0.17 m by default; 0.34 for
       cases/angle_of_repose_034)
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import granular_common as gc  # noqa: E402  (solids.csv reader, surface bins, line fits)

XC, MOUTH_Z, D50, FLOOR, BIN = 0.8, 0.17, 0.01, 0.004, 0.01
BAND = (0.2, 0.8)
FLIGHT = 0.3  # m/s: grains faster than this are in flight, not part of the surface
MOVING = 0.05  # m/s: a grain below the mouth faster than this is counted as moving
MPS_MU, MPS_DEG, MPS_DEM_DEG = 0.1, 22.3, 22.5


def surface(grains):
    """Top of the deposit per bin (centre + d50/2 - the teeth's tips): grains below the mouth and
    slower than FLIGHT (grains still falling from the slot are not the heap's surface)."""
    return gc.surface(((x, z + D50 / 2 - FLOOR) for x, z, v in grains
                       if z < MOUTH_Z and v < FLIGHT), BIN)


def flank(top, side):
    """(x, top) of the surface bins of one flank, from the summit outwards (side = -1 or +1)."""
    k_top = max(top, key=lambda k: (top[k], -abs((k + 0.5) * BIN - XC)))
    return gc.flank(top, k_top, side, BAND, BIN)


def angles(grains):
    """Left and right flank angles [deg], their mean, points per flank, height, extent."""
    top = surface(grains)
    if not top:
        nan = float("nan")
        return dict(left=nan, right=nan, angle=nan, n_left=0, n_right=0, height=0.0, x_min=nan,
                    x_max=nan)
    left, right = flank(top, -1), flank(top, +1)
    a_l, a_r = gc.slope_deg(left), gc.slope_deg(right)
    xs = [x for x, z, _ in grains if z < MOUTH_Z]
    return dict(left=a_l, right=a_r, angle=(a_l + a_r) / 2, n_left=len(left), n_right=len(right),
                height=max(top.values()), x_min=min(xs), x_max=max(xs))


def at_end(path):
    """The measures of one run: the last frame's and 0.2 s before; the fastest grain, the grains
    below the mouth moving faster than MOVING, the grains left in the container."""
    fr = gc.frames(path)
    ts, t_end, t_prev = gc.end_times(fr, 0.2)
    r, prev = angles(fr[t_end]), angles(fr[t_prev])
    r.update(t_end=t_end, angle_prev=prev["angle"], height_prev=prev["height"],
             vmax=max(v for _, _, v in fr[t_end]),
             moving=sum(1 for _, z, v in fr[t_end] if z < MOUTH_Z and v > MOVING),
             in_container=sum(1 for _, z, _ in fr[t_end] if z > MOUTH_Z))
    return r


def runs(out):
    for name in sorted(os.listdir(out)):
        path = os.path.join(out, name, "solids.csv")
        if name.startswith("mu") and os.path.exists(path):
            mu, mur = name[2:].split("_mur")
            yield float(mu), float(mur), name, path


def main():
    global MOUTH_Z
    out = sys.argv[1]
    if len(sys.argv) > 2:
        MOUTH_Z = float(sys.argv[2])
    rows = []
    for mu, mur, name, path in runs(out):
        r = at_end(path)
        r.update(mu=mu, mur=mur)
        rows.append(r)
    print("mu    mu_r  t_end  left   right  angle [deg] (0.2 s before)  points L/R  height [m]"
          "  x range [m]      v_max [m/s]  moving  left in container")
    for r in rows:
        print(f"{r['mu']:<5g} {r['mur']:<5g} {r['t_end']:.2f}  {r['left']:5.1f}  {r['right']:5.1f}"
              f"  {r['angle']:5.1f}       ({r['angle_prev']:5.1f})         "
              f"{r['n_left']:3d}/{r['n_right']:<3d}"
              f"    {r['height']:.3f}      {r['x_min']:.3f}-{r['x_max']:.3f}  {r['vmax']:.3f}"
              f"        {r['moving']:3d}     {r['in_container']}")
    keys = ["mu", "mur", "t_end", "left", "right", "angle", "angle_prev", "n_left", "n_right",
            "height", "height_prev", "x_min", "x_max", "vmax", "moving", "in_container"]
    with open(os.path.join(out, "angle_of_repose.csv"), "w") as f:
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join(f"{r[k]:.6g}" for k in keys) + "\n")
    plot(rows, out)


def plot(rows, out):
    plt = gc.pyplot()
    if plt is None:
        return
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    styles = ("ko-", "bs-", "mD-", "c^-", "yv-")
    for mur, style in zip(sorted({r["mur"] for r in rows}), styles):
        sel = sorted((r for r in rows if r["mur"] == mur), key=lambda r: r["mu"])
        ax[0].plot([r["mu"] for r in sel], [r["angle"] for r in sel], style,
                   label=f"picdem, 2D disks, mu_r = {mur:g}")
        if mur > 0:  # the slope a constant rolling torque holds a lone disk on: tan = mu_r
            ax[0].axhline(math.degrees(math.atan(mur)), color=style[0], ls=":", lw=0.8,
                          label=f"atan(mu_r = {mur:g}) = {math.degrees(math.atan(mur)):.1f} deg")
    ax[0].plot([MPS_MU], [MPS_DEG], "r^", ms=9, label="Kim et al. 2018, MPS (22.3 deg)")
    ax[0].plot([MPS_MU], [MPS_DEM_DEG], "gv", ms=9, label="Kim et al. 2018, their DEM (22.5 deg)")
    mus = [0.05 + 0.01 * k for k in range(41)]
    ax[0].plot(mus, [math.degrees(math.atan(m)) for m in mus], "k:", lw=0.8, label="atan(mu)")
    ax[0].set_xlabel("friction coefficient mu")
    ax[0].set_ylabel("angle of repose [deg]")
    ax[0].legend(fontsize=7)
    for mu, mur, name, path in runs(out):
        fr = gc.frames(path)
        top = surface(fr[max(fr)])
        ks = sorted(top)
        ax[1].plot([(k + 0.5) * BIN for k in ks], [top[k] for k in ks],
                   "-" if mur == 0 else "--", lw=1, label=f"mu {mu:g}, mu_r {mur:g}")
    ax[1].axhline(MOUTH_Z - FLOOR, color="grey", lw=0.5, label="mouth")
    ax[1].set_xlabel("x [m]")
    ax[1].set_ylabel("surface above the teeth [m] (top grain + d50/2)")
    ax[1].legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "angle_of_repose.png"), dpi=110)
    print("wrote", os.path.join(out, "angle_of_repose.png"))


if __name__ == "__main__":
    main()
