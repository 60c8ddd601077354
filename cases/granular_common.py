"""Code shared by the granular case scripts (cases/angle_of_repose, cases/granular_*): the writers
of the case files' recurring parts (the toothed floor, the cargo-dump container, the sections
before `dem`) for make_case.py, and the readers of solids.csv and the deposit measures for
analyse.py and plot_mound.py.

A script in cases/<case>/ imports it after putting its parent folder on the path:
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    import granular_common as gc
"""
import csv
import math


# --- case-file writers (make_case.py) ---


def fmt(v):
    """A list of numbers as a YAML flow sequence, 6 significant digits."""
    return "[" + ", ".join(f"{a:.6g}" for a in v) + "]"


def teeth(tank_l, tooth_h, tooth_p):
    """The rough floor as one counter-clockwise pentagon per tooth from z = 0 (valleys at
    tooth_h / 2, tips at tooth_h, one every tooth_p), so that the contact search tests a grain
    only against the teeth whose boxes it reaches and a grain resting on two teeth gets a contact
    from each (one polygon for the whole floor gives one contact, its closest point)."""
    out = []
    for k in range(round(tank_l / tooth_p)):
        x0, x1 = k * tooth_p, (k + 1) * tooth_p
        out.append(([x0, x1, x1, x0 + tooth_p / 2, x0],
                    [0.0, 0.0, tooth_h / 2, tooth_h, tooth_h / 2]))
    return out


def polygon_yaml(name, x, z):
    """One entry of the `obstacles` section: a polygon with vertices (x, z)."""
    return f"  {name}:\n    type: polygon\n    x: {fmt(x)}\n    z: {fmt(z)}"


def teeth_yaml(tank_l, tooth_h, tooth_p):
    """The teeth as entries tooth_0, tooth_1, ... of the `obstacles` section."""
    return "\n".join(polygon_yaml(f"tooth_{k}", x, z)
                     for k, (x, z) in enumerate(teeth(tank_l, tooth_h, tooth_p)))


def containers(xc, mouth_z, box_w, slot_w, wall_t, wall_top):
    """The cargo-dump container's halves, L-shaped (side wall and half of the bottom),
    counter-clockwise: inner width box_w centred on xc, walls wall_t thick up to wall_top, the
    bottom wall_t thick with its underside (the mouth) at mouth_z and a slot slot_w wide."""
    xl, xr, s, top, bot = xc - box_w / 2, xc + box_w / 2, slot_w / 2, mouth_z + wall_t, mouth_z
    left = ([xl - wall_t, xc - s, xc - s, xl, xl, xl - wall_t],
            [bot, bot, top, top, wall_top, wall_top])
    right = ([xc + s, xr + wall_t, xr + wall_t, xr, xr, xc + s],
             [bot, bot, wall_top, wall_top, top, top])
    return left, right


def containers_yaml(left, right):
    """The container's halves as entries container_left and container_right of `obstacles`."""
    return polygon_yaml("container_left", *left) + "\n" + polygon_yaml("container_right", *right)


def head_yaml(name, length, height, t_end, dem):
    """The sections `case` to `dem` of a dry granular case (2 mm cells, dt_max 1e-4 s, output
    every 0.05 s to out_<name>, no pictures, gap 1 cell, theta 0.002); dem: the (key, value)
    pairs of `dem` before gap_cells."""
    dem_lines = "".join(f"  {k}: {v}\n" for k, v in dem)
    return f"""case:
  name: {name}
grid:
  length: {length}
  height: {height}
  cell_size: 0.002
time:
  end: {t_end}
  dt_max: 0.0001
output:
  interval: 0.05
  paraview: false
  png: false
  directory: out_{name}
dem:
{dem_lines}  gap_cells: 1
  theta: 0.002"""


def graded_yaml(name, density, region, placement, count, sizes, seed, drops=None,
                friction=None):
    """One `graded_packing` entry of `solids`: disks of d_min, d50, d_max = sizes (uniform in
    ln d by number) in region [x0, z0, x1, z1]; drops: the pour's tries per grain (generator's
    default when None); friction: the grains' own friction coefficient (dem/mu when None)."""
    d_min, d50, d_max = sizes
    tries = f"\n    drops: {drops}" if drops is not None else ""
    mu = f"\n    friction: {friction:g}" if friction is not None else ""
    return f"""  {name}:
    type: graded_packing
    density: {density}{mu}
    region: {fmt(region)}
    placement: {placement}{tries}
    count: {count}
    basis: number
    d_min: {d_min:g}
    d50: {d50:g}
    d_max: {d_max:g}
    seed: {seed}"""


def end_times(fr, before):
    """The sorted output times of frames fr, the last, and the one nearest `before` s earlier."""
    ts = sorted(fr)
    t_prev = min(ts, key=lambda t: abs(t - (ts[-1] - before)))
    return ts, ts[-1], t_prev


# --- solids.csv readers and deposit measures (analyse.py) ---


def frames(path, ids=False):
    """solids.csv by output time: {t: [(x, z, speed)]}, or [(id, x, z, speed)] with ids."""
    out = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            g = (float(r["x"]), float(r["z"]), math.hypot(float(r["u"]), float(r["w"])))
            out.setdefault(float(r["t"]), []).append((int(r["id"]),) + g if ids else g)
    return out


def front(grains, gap):
    """The continuous deposit's front (x of its foremost centre, from the left) and the number
    of grains beyond it: grains past a horizontal gap larger than `gap` between neighbouring
    centres count as ejected. grains: (x, ...) tuples."""
    xs = sorted(g[0] for g in grains)
    f = xs[0]
    for x in xs[1:]:
        if x - f > gap:
            break
        f = x
    return f, sum(1 for x in xs if x > f)


def surface(points, width):
    """The highest value per bin of the given width along x: {bin index: top}; points: (x, top)."""
    top = {}
    for x, h in points:
        k = math.floor(x / width)
        top[k] = max(top.get(k, -1.0), h)
    return top


def flank(top, k_top, side, band, width):
    """(bin centre, top) of the surface bins from bin k_top outwards (side -1 or +1) up to the
    first empty bin, keeping those whose top lies between band[0] and band[1] of top[k_top]."""
    h = top[k_top]
    pts = []
    k = k_top
    while k in top:
        if band[0] * h <= top[k] <= band[1] * h:
            pts.append(((k + 0.5) * width, top[k]))
        k += side
    return pts


def line_fit(pts):
    """Least-squares line through (x, y) points: (slope, intercept)."""
    n = len(pts)
    mx = sum(p[0] for p in pts) / n
    my = sum(p[1] for p in pts) / n
    b = sum((p[0] - mx) * (p[1] - my) for p in pts) / sum((p[0] - mx) ** 2 for p in pts)
    return b, my - b * mx


def slope_deg(pts):
    """atan(|slope|) of the least-squares line through the points [deg]; nan below 3 points."""
    if len(pts) < 3:
        return float("nan")
    return math.degrees(math.atan(abs(line_fit(pts)[0])))


def pyplot():
    """matplotlib.pyplot on the Agg backend, or None (with a message) without matplotlib."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not found: no plot")
        return None
    return plt
