#!/usr/bin/env python3
"""The graded dump's final mound: the stones' centres at the last output time, with the pipe.

Reads OUT_DIR/solids.csv (t, id, x, z, u, w, ...); the stones' sizes are not in it, so the centres
are drawn as dots (d from 5 to 15 mm). Prints the mound's extent (leftmost and rightmost centre),
the highest centre, the stones' mean centre and the fastest stone; draws OUT_DIR/mound.png.
usage: plot_mound.py OUT_DIR
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import granular_common as gc  # noqa: E402  (solids.csv reader)

PIPE_X, PIPE_W, WALL, BOTTOM, TOP, FUNNEL_W, FUNNEL_H = 0.2145, 0.045, 0.0045, 0.09, 0.195, 0.135, 0.09


def main():
    out = sys.argv[1]
    frames = gc.frames(os.path.join(out, "solids.csv"))
    t = max(frames)
    g = frames[t]
    xs, zs = [p[0] for p in g], [p[1] for p in g]
    print(f"t = {t:.2f} s: {len(g)} stones, centres from x = {min(xs):.4f} to {max(xs):.4f} m, "
          f"highest centre z = {max(zs):.4f} m, mean centre ({sum(xs) / len(xs):.4f}, "
          f"{sum(zs) / len(zs):.4f}) m, fastest {max(p[2] for p in g):.3f} m/s; "
          f"{sum(1 for z in zs if z > BOTTOM)} above the pipe's lower end")
    plt = gc.pyplot()
    if plt is None:
        return
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.scatter(xs, zs, s=12, color="k", label=f"stone centres, t = {t:.2f} s")
    for s in (-1, 1):
        x_in = PIPE_X + s * PIPE_W / 2
        x_out = x_in + s * WALL
        ax.plot([x_in, x_in, x_out, x_out], [TOP, BOTTOM, BOTTOM, TOP], color="grey")
        ax.plot([x_in, PIPE_X + s * FUNNEL_W / 2], [TOP, TOP + FUNNEL_H], color="grey")
    ax.set_xlim(0, 0.429)
    ax.set_ylim(0, 0.3)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "mound.png"), dpi=110)
    print("wrote", os.path.join(out, "mound.png"))


if __name__ == "__main__":
    main()
