#!/usr/bin/env python3
"""Final runout and height of the granular column collapses against the aspect ratio a = H0/L0.

Reads OUT_DIR/a<a>/solids.csv (t, id, x, z, ...) written by sweep.sh (L0 from the run's
case_resolved.yaml, so runs of other counts and widths are read too). Lengths from the left wall
(x = 0) and from the tips of the floor's teeth (z = 4 mm); a grain's extent is taken as its
centre +- d50/2 (2.5 mm; the sizes run from 4 to 6 mm):
  L0 = the column's width (the pour region's), H0 = highest grain top at t = 0;
  L_inf = front of the continuous deposit (grains beyond a horizontal gap of 3 d_max = 18 mm
          between neighbouring centres are counted as ejected, not as runout);
  H_inf = highest grain top at the end.
Bulk measures of the same deposit, which a few grains at its tip do not move:
  x90, x95 = the positions below which 90% and 95% of the grains' centres lie (+ d50/2);
  edge10   = the end of the deposit's part at least 0.1 H0 thick, counted from the wall in bins
             of d50 (the highest grain top in each).
Rest: L_inf and H_inf 0.1 s before the end are printed next to the final ones.
Fits log((L_inf - L0)/L0) and log(H_inf/L0) against log a by least squares over a >= 2
(the large-a regime of Lube et al. 2005), over a >= 1 and over all a; prints the fastest grain at
the end; writes OUT_DIR/collapse.csv and, if
matplotlib is present, OUT_DIR/granular_column_collapse.png.
usage: analyse.py OUT_DIR
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import granular_common as gc  # noqa: E402  (solids.csv reader, deposit front, line fits)

WIDTH = {0.5: 0.2746, 1: 0.1942, 2: 0.1373, 4: 0.0971, 8: 0.0687}
R50, FLOOR, GAP_EJECT = 0.0025, 0.004, 0.018


def frames(path):
    """solids.csv by output time: {t: [(x, z, speed)]}."""
    return gc.frames(path)


def runout(grains):
    front, ejected = gc.front(grains, GAP_EJECT)
    return front + R50, ejected


def height(grains):
    return max(z for _, z, _ in grains) + R50 - FLOOR


def quantile_x(grains, q):
    """The position below which a share q of the grains' centres lie, plus d50/2."""
    xs = sorted(x for x, _, _ in grains)
    return xs[max(0, math.ceil(q * len(xs)) - 1)] + R50


def thick_edge(grains, thickness):
    """End of the deposit's part at least `thickness` thick, from the wall, in bins of d50."""
    tops = {}
    for x, z, _ in grains:
        k = int(x / (2 * R50))
        tops[k] = max(tops.get(k, 0.0), z + R50 - FLOOR)
    k = 0
    while tops.get(k, 0.0) >= thickness:
        k += 1
    return k * 2 * R50


def fit(xs, ys):
    """Least squares in log-log: (b, c) of y = c x^b."""
    b, c = gc.line_fit([(math.log(x), math.log(y)) for x, y in zip(xs, ys)])
    return b, math.exp(c)


def width_of(run_dir, default):
    """L0: the x1 of the grains' pour region in the run's case_resolved.yaml (a run with another
    count sets its own width), else the sweep's width for its a."""
    path = os.path.join(run_dir, "case_resolved.yaml")
    if not os.path.exists(path):
        return default
    with open(path) as f:
        for line in f:
            s = line.strip()
            if s.startswith("region:"):
                return float(s.split("[")[1].split("]")[0].split(",")[2])
    return default


def main():
    out = sys.argv[1]
    rows = []
    for a_nom, l0 in WIDTH.items():
        path = os.path.join(out, f"a{a_nom:g}", "solids.csv")
        if not os.path.exists(path):
            print(f"a = {a_nom:g}: no {path}")
            continue
        l0 = width_of(os.path.join(out, f"a{a_nom:g}"), l0)
        fr = frames(path)
        ts, t_end, t_prev = gc.end_times(fr, 0.1)
        h0 = height(fr[ts[0]])
        l_inf, ejected = runout(fr[t_end])
        l_prev, _ = runout(fr[t_prev])
        rows.append(dict(a_nom=a_nom, n=len(fr[ts[0]]), L0=l0, H0=h0, a=h0 / l0, t_end=t_end,
                         L_inf=l_inf, H_inf=height(fr[t_end]), ejected=ejected,
                         L_prev=l_prev, H_prev=height(fr[t_prev]),
                         vmax=max(v for _, _, v in fr[t_end]),
                         x90=quantile_x(fr[t_end], 0.9), x95=quantile_x(fr[t_end], 0.95),
                         edge10=thick_edge(fr[t_end], 0.1 * h0)))
    print("a_nom   N     L0      H0      a      t_end  L_inf   (0.1 s before)  H_inf   (before)"
          "  ejected  (L_inf-L0)/L0  H_inf/L0  v_max [m/s]")
    for r in rows:
        r["run"] = (r["L_inf"] - r["L0"]) / r["L0"]
        r["h"] = r["H_inf"] / r["L0"]
        print(f"{r['a_nom']:<5g} {r['n']:5d}  {r['L0']:.4f}  {r['H0']:.4f}  {r['a']:.3f}  "
              f"{r['t_end']:.2f}  {r['L_inf']:.4f}  ({r['L_prev']:.4f})       {r['H_inf']:.4f}  "
              f"({r['H_prev']:.4f})  {r['ejected']:5d}    {r['run']:.3f}          {r['h']:.3f}     "
              f"{r['vmax']:.3f}")
    print("bulk (over a): a_nom  (x90-L0)/L0  (x95-L0)/L0  (edge10-L0)/L0  (L_inf-L0)/L0")
    for r in rows:
        print(f"               {r['a_nom']:<5g}" + "".join(
            f"  {(r[k] - r['L0']) / r['L0'] / r['a']:9.3f} a" for k in ("x90", "x95", "edge10",
                                                                        "L_inf")))
    with open(os.path.join(out, "collapse.csv"), "w") as f:
        keys = ["a_nom", "n", "L0", "H0", "a", "t_end", "L_inf", "H_inf", "ejected", "run", "h",
                "vmax", "x90", "x95", "edge10"]
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join(f"{r[k]:.6g}" for k in keys) + "\n")
    for label, sel in (("a >= 2", [r for r in rows if r["a_nom"] >= 2]),
                       ("a >= 1", [r for r in rows if r["a_nom"] >= 1]), ("all a", rows)):
        if len(sel) < 2:
            continue
        br, cr = fit([r["a"] for r in sel], [r["run"] for r in sel])
        bh, ch = fit([r["a"] for r in sel], [r["h"] for r in sel])
        print(f"fit over {label}: (L_inf-L0)/L0 = {cr:.2f} a^{br:.3f};  H_inf/L0 = {ch:.2f} a^{bh:.3f}")
    plot(rows, out)


def plot(rows, out):
    plt = gc.pyplot()
    if plt is None:
        return
    a = [r["a"] for r in rows]
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    grid = [0.4 * 1.05 ** k for k in range(70)]
    ax[0].loglog(a, [r["run"] for r in rows], "ko", label="picdem (disks, rough floor)")
    ax[0].loglog([x for x in grid if x < 1.8], [1.2 * x for x in grid if x < 1.8], "b-",
                 label="Lube et al. 2005: 1.2 a (a < 1.8)")
    ax[0].loglog([x for x in grid if x < 3], [1.8 * x for x in grid if x < 3], "b:",
                 label="Lajeunesse et al. 2005: 1.8 a (a < 3)")
    ax[0].loglog([x for x in grid if x > 2.8], [1.9 * x ** (2 / 3) for x in grid if x > 2.8], "r-",
                 label="Lube et al. 2005: 1.9 a^(2/3) (a > 2.8)")
    ax[0].set_xlabel("a = H0/L0")
    ax[0].set_ylabel("(L_inf - L0)/L0")
    ax[0].legend(fontsize=7)
    ax[1].loglog(a, [r["h"] for r in rows], "ko", label="picdem")
    ax[1].loglog([x for x in grid if x < 1.15], [x for x in grid if x < 1.15], "b-",
                 label="Lube et al. 2005: a (a < 1.15)")
    ax[1].loglog([x for x in grid if x > 1.15], [x ** 0.4 for x in grid if x > 1.15], "r-",
                 label="Lube et al. 2005: a^(2/5) (a > 1.15)")
    ax[1].set_xlabel("a = H0/L0")
    ax[1].set_ylabel("H_inf/L0")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "granular_column_collapse.png"), dpi=110)
    print("wrote", os.path.join(out, "granular_column_collapse.png"))


if __name__ == "__main__":
    main()
