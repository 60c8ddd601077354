#!/usr/bin/env python3
"""Gravity sorting: where each density population ends in the heap, over time.

Reads OUT_DIR/solids.csv (t, id, x, z, u, w, ...). The solids' ids follow the case file: layer k
(k = 0..5, from the container's bottom) holds ids PER_LAYER k .. PER_LAYER (k + 1) - 1 and the
density DENSITIES[k % 3] (make_case.py). Per output time and population, over the grains out of
the container (centre below the mouth): their number and their mean centre height above the
teeth's tips, their mean depth below the heap's surface (the highest heap grain's centre in
the grain's 10 mm bin) and their mean distance from the slot's axis; at the end also the mean height of each population relative to the mean of all
grains in the heap, and the share of each population in the lowest and highest third of the
heap's grains (ranked by height).
Writes OUT_DIR/sorting.csv (per output time and population: count, mean height, mean distance
from the axis and mean depth below the surface, the segregation measure) and, with matplotlib,
OUT_DIR/granular_sorting.png.
usage: analyse.py OUT_DIR
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import granular_common as gc  # noqa: E402  (solids.csv reader)

DENSITIES, PER_LAYER, LAYERS = (1500, 2500, 3500), 50, 6
MOUTH_Z, FLOOR, XC, BIN = 0.17, 0.004, 0.8, 0.01
FLIGHT = 0.3  # m/s: faster grains are in flight, not yet part of the heap
NAMES = ("light", "medium", "heavy")


LAYER_DENSITY = [DENSITIES[k % 3] for k in range(LAYERS)]


def read_layers(out):
    """The density of each layer from the run's case_resolved.yaml (case.yaml or the reversed
    control, case_reversed.yaml)."""
    dens, layer = {}, None
    with open(os.path.join(out, "case_resolved.yaml")) as f:
        for line in f:
            s = line.strip()
            if s.startswith("layer_") and s.endswith(":"):
                layer = int(s[6:-1])
            elif layer is not None and s.startswith("density:"):
                dens[layer] = round(float(s.split(":")[1]))
                layer = None
    for k in range(LAYERS):
        LAYER_DENSITY[k] = dens[k]


def population(i):
    return DENSITIES.index(LAYER_DENSITY[i // PER_LAYER])


def measures(grains):
    """Per population, over the heap's grains (below the mouth, slower than FLIGHT): count, mean
    height above the teeth's tips and mean distance from the slot's axis; the shares of each
    population in the lowest and highest third of the heap's grains."""
    rows = [(z - FLOOR, population(i), abs(x - XC)) for i, x, z, v in grains
            if z < MOUTH_Z and v < FLIGHT]
    heap = [(z, p) for z, p, _ in rows]
    n = [sum(1 for _, p in heap if p == k) for k in range(3)]
    mean = [sum(z for z, p in heap if p == k) / n[k] if n[k] else float("nan") for k in range(3)]
    reach = [sum(r for _, p, r in rows if p == k) / n[k] if n[k] else float("nan")
             for k in range(3)]
    # depth below the surface: the highest heap grain's centre in the grain's 10 mm bin
    top = {}
    for i, x, z, v in grains:
        if z < MOUTH_Z and v < FLIGHT:
            top[int(x // BIN)] = max(top.get(int(x // BIN), -1.0), z)
    depths = [(top[int(x // BIN)] - z, population(i)) for i, x, z, v in grains
              if z < MOUTH_Z and v < FLIGHT]
    depth = [sum(d for d, p in depths if p == k) / n[k] if n[k] else float("nan")
             for k in range(3)]
    ranked = sorted(heap)
    third = len(ranked) // 3
    low, high = ranked[:third], ranked[len(ranked) - third:]
    share_low = [sum(1 for _, p in low if p == k) / max(len(low), 1) for k in range(3)]
    share_high = [sum(1 for _, p in high if p == k) / max(len(high), 1) for k in range(3)]
    all_mean = sum(z for z, _ in heap) / len(heap) if heap else float("nan")
    return dict(n=n, mean=mean, reach=reach, depth=depth, all_mean=all_mean, low=share_low, high=share_high,
                in_container=sum(1 for _, _, z, _ in grains if z >= MOUTH_Z))


def at_end(path):
    fr = gc.frames(path, ids=True)
    ts = sorted(fr)
    m = measures(fr[ts[-1]])
    m["t_end"] = ts[-1]
    m["series"] = [(t, measures(fr[t])) for t in ts]
    return m


def main():
    out = sys.argv[1]
    read_layers(out)
    print("layers from the bottom: " + ", ".join(str(d) for d in LAYER_DENSITY))
    m = at_end(os.path.join(out, "solids.csv"))
    print(f"t = {m['t_end']:.2f} s; heap grains' mean height {m['all_mean'] * 1000:.1f} mm; "
          f"{m['in_container']} grains left in the container")
    for k in range(3):
        print(f"{NAMES[k]:6s} (density {DENSITIES[k]}): {m['n'][k]:3d} out of the container, mean "
              f"height {m['mean'][k] * 1000:.1f} mm ({(m['mean'][k] - m['all_mean']) * 1000:+.1f}"
              f" mm), depth below the surface {m['depth'][k] * 1000:.1f} mm, distance from the axis "
              f"{m['reach'][k] * 1000:.1f} mm, share of the lowest third {m['low'][k]:.2f}, of the highest third "
              f"{m['high'][k]:.2f}")
    with open(os.path.join(out, "sorting.csv"), "w") as f:
        f.write("t," + ",".join(f"n_{s},mean_z_{s},mean_r_{s},depth_{s}" for s in NAMES) + "\n")
        for t, s in m["series"]:
            f.write(f"{t:.4g}," + ",".join(
                f"{s['n'][k]},{s['mean'][k]:.6g},{s['reach'][k]:.6g},{s['depth'][k]:.6g}"
                for k in range(3)) + "\n")
    print("depth below the surface over time [mm] (grains in the heap):")
    print("   t  " + "  ".join(f"{n:>13s}" for n in NAMES))
    for t, s in m["series"]:
        if abs(t / 0.5 - round(t / 0.5)) < 1e-6 and t > 0:
            print(f"{t:4.1f}  " + "  ".join(f"{s['depth'][k] * 1000:7.1f} ({s['n'][k]:3d})"
                                           for k in range(3)))
    plot(os.path.join(out, "solids.csv"), m, out)


def plot(path, m, out):
    plt = gc.pyplot()
    if plt is None:
        return
    fr = gc.frames(path, ids=True)
    last = fr[max(fr)]
    fig, ax = plt.subplots(1, 3, figsize=(15, 3.8))
    colors = ("tab:orange", "tab:green", "tab:blue")
    for k in range(3):
        t = [t for t, s in m["series"] if s["n"][k]]
        z = [s["mean"][k] * 1000 for _, s in m["series"] if s["n"][k]]
        d = [s["depth"][k] * 1000 for _, s in m["series"] if s["n"][k]]
        ax[0].plot(t, z, color=colors[k], label=f"{NAMES[k]} ({DENSITIES[k]} kg/m^3)")
        ax[1].plot(t, d, color=colors[k], label=NAMES[k])
        xs = [x for i, x, z, _ in last if population(i) == k]
        zs = [z for i, x, z, _ in last if population(i) == k]
        ax[2].scatter(xs, zs, s=9, color=colors[k], label=NAMES[k])
    ax[0].set_xlabel("t [s]")
    ax[0].set_ylabel("mean height in the heap [mm]")
    ax[0].legend(fontsize=7)
    ax[1].set_xlabel("t [s]")
    ax[1].set_ylabel("mean depth below the heap's surface [mm]")
    ax[1].legend(fontsize=7)
    ax[2].set_aspect("equal")
    ax[2].set_xlim(0.45, 1.15)
    ax[2].set_ylim(0, 0.35)
    ax[2].set_title(f"t = {m['t_end']:.2f} s", fontsize=9)
    ax[2].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "granular_sorting.png"), dpi=110)
    print("wrote", os.path.join(out, "granular_sorting.png"))


if __name__ == "__main__":
    main()
