#!/usr/bin/env python3
"""Granular dam break: the front and top over time, the final deposit's runout, height and slope.

Reads OUT_DIR/solids.csv (t, id, x, z, u, w, ...). Lengths from the left wall and from the teeth's
tips (z = 4 mm); a grain's extent is its centre +- d50/2 (5 mm; sizes 8 to 12 mm):
  L0 = the column's width (0.15 m), H0 = highest grain top at t = 0;
  front = the continuous deposit's front (grains beyond a horizontal gap of 3 d_max = 36 mm
          between neighbouring centres are counted as ejected), top = highest grain top;
  slope = the dune face: a least-squares line through the surface (highest grain top in 10 mm
          bins) over the bins from the summit towards the front whose top lies between 0.2 and
          0.8 of the deposit's height; the angle is atan(|slope|).
Prints front and top every 0.1 s, the final figures and those 0.1 s before (rest), and
(L_inf - L0)/L0 and H_inf/L0 against the 2D column-collapse laws at this a (Lube et al. 2005;
Lajeunesse et al. 2005, via Lagree et al. 2011). With matplotlib, writes OUT_DIR/granular_dam_break.png
(snapshots at the times of the paper's Fig. 3b that were output).
usage: analyse.py OUT_DIR
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import granular_common as gc  # noqa: E402  (solids.csv reader, deposit front, line fits)

L0, R50, FLOOR, GAP_EJECT, BIN, TANK_L = 0.15, 0.005, 0.004, 0.036, 0.01, 0.6
BAND = (0.2, 0.8)


def front(grains):
    f, ejected = gc.front(grains, GAP_EJECT)
    return min(f + R50, TANK_L), ejected


def top(grains):
    return max(z for _, z, _ in grains) + R50 - FLOOR


def slope_deg(grains):
    surf = gc.surface(((x, z + R50 - FLOOR) for x, z, _ in grains), BIN)
    k = max(surf, key=lambda j: (surf[j], -j))
    pts = gc.flank(surf, k, +1, BAND, BIN)
    return gc.slope_deg(pts), len(pts)


def at_end(path):
    fr = gc.frames(path)
    ts, t_end, t_prev = gc.end_times(fr, 0.1)
    h0 = top(fr[ts[0]])
    l_inf, ejected = front(fr[t_end])
    ang, npts = slope_deg(fr[t_end])
    return dict(t_end=t_end, H0=h0, a=h0 / L0, L_inf=l_inf, ejected=ejected,
                L_prev=front(fr[t_prev])[0], H_inf=top(fr[t_end]), H_prev=top(fr[t_prev]),
                angle=ang, n_angle=npts, angle_prev=slope_deg(fr[t_prev])[0],
                vmax=max(v for _, _, v in fr[t_end]),
                series=[(t, front(fr[t])[0], top(fr[t])) for t in ts])


def main():
    out = sys.argv[1]
    path = os.path.join(out, "solids.csv")
    m = at_end(path)
    for t, f, h in m["series"]:
        if abs(t * 10 - round(t * 10)) < 1e-6:
            print(f"t = {t:.1f} s: front {f:.4f} m, top {h:.4f} m")
    run = (m["L_inf"] - L0) / L0
    print(f"H0 = {m['H0']:.4f} m, a = {m['a']:.3f}; t = {m['t_end']:.2f} s: L_inf = {m['L_inf']:.4f}"
          f" m ({m['L_prev']:.4f} 0.1 s before), (L_inf - L0)/L0 = {run:.3f} = {run / m['a']:.3f} a"
          f"; H_inf = {m['H_inf']:.4f} m ({m['H_prev']:.4f}) = {m['H_inf'] / m['H0']:.3f} H0 = "
          f"{m['H_inf'] / L0:.3f} L0; face {m['angle']:.1f} deg ({m['angle_prev']:.1f} 0.1 s "
          f"before, {m['n_angle']} bins); {m['ejected']} ejected; fastest grain {m['vmax']:.3f} m/s")
    a = m["a"]
    print(f"2D laws at a = {a:.2f}: runout 1.2 a = {1.2 * a:.2f} (Lube, a < 1.8), 1.8 a = "
          f"{1.8 * a:.2f} (Lajeunesse, a < 3), 1.9 a^(2/3) = {1.9 * a ** (2 / 3):.2f} (Lube, a > 2.8);"
          f" the far wall caps it at {(TANK_L - L0) / L0:.2f}")
    plot(path, out)


def plot(path, out):
    plt = gc.pyplot()
    if plt is None:
        return
    fr = gc.frames(path)
    want = [0.0, 0.2, 0.4, 0.6, 1.0, max(fr)]
    fig, ax = plt.subplots(1, len(want), figsize=(2.6 * len(want), 2.6))
    for a, t in zip(ax, want):
        t = min(fr, key=lambda s: abs(s - t))
        g = fr[t]
        a.scatter([x for x, _, _ in g], [z for _, z, _ in g], s=2, color="k")
        a.set_xlim(0, TANK_L)
        a.set_ylim(0, 0.35)
        a.set_aspect("equal")
        a.set_title(f"t = {t:.2f} s", fontsize=8)
        a.tick_params(labelsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "granular_dam_break.png"), dpi=110)
    print("wrote", os.path.join(out, "granular_dam_break.png"))


if __name__ == "__main__":
    main()
