#!/usr/bin/env python3
"""Drag budget of a DFG 2D-1 run (doc/viscous.md, "DFG 2D-1: where the excess drag comes from").

Reads the run's checkpoints (grid u, w, p; h5dump, no h5py needed) and forces.csv, and prints, as
means over the checkpoints (steady state):
  - the surface drag of forces.csv (pressure + viscous loads on the cylinder, mean over [3, 4] s);
  - the control-volume drag: F = -oint (rho u u.n + p n - tau n) dl over squares around the
    cylinder (faces on grid lines, central differences; steady, so no d/dt term): the force the
    computed flow's own momentum balance puts on the cylinder;
  - the viscous part again from the legs (as fluid::viscous_loads: mu (u_P - u_B) / theta per leg
    meeting the circle R = 0.05 m at (0.2, 0.2) m), with the first node as stored and with it
    replaced by the quadratic through the wall value and the next two nodes outward on the leg's
    line, and the median ratio of the two first-node values.
Run: picdem cases/dfg_2d1 --set time/end=4 --set checkpoint/every_steps=N --set checkpoint/keep=6
--output DIR (checkpoints in the last second), then: drag_budget.py DIR H [T0 T1] (forces.csv's
mean over [T0, T1] s, default [3, 4]; every checkpoint in DIR/checkpoints is used)."""
import array
import csv
import glob
import os
import subprocess
import sys
import tempfile

MU, RHO, R, C, SCALE = 1e-3, 1.0, 0.05, 0.2, 500.0  # c = 2 F / (rho U^2 D) = 500 F


def dataset(path, name, code):
    tmp = tempfile.mktemp()
    subprocess.run(["h5dump", "-d", name, "-b", "LE", "-o", tmp, path], check=True,
                   stdout=subprocess.DEVNULL)
    a = array.array(code)
    with open(tmp, "rb") as f:
        a.frombytes(f.read())
    os.remove(tmp)
    return a


def fields(path):
    """u (x = i h, z = (k + 1/2) h), w (x = (i + 1/2) h, z = k h), p (centres) of a 1-rank
    checkpoint (grid/boxes: storage and owned box of u, w and the cells)."""
    boxes = list(dataset(path, "/grid/boxes", "i"))
    out = []
    for which, name in ((0, "u"), (1, "w"), (2, "p")):
        i0, i1, k0, _ = boxes[8 * which:8 * which + 4]
        a, n = dataset(path, "/grid/" + name, "d"), i1 - i0
        out.append(lambda i, k, a=a, n=n, i0=i0, k0=k0: a[(k - k0) * n + (i - i0)])
    return out


def control_volume(u, w, p, h, ia, ib, ka, kb):
    fx = 0.0
    for sgn, i in ((-1, ia), (1, ib)):  # faces x = i h
        for k in range(ka, kb):
            pp = 0.5 * (p(i - 1, k) + p(i, k))
            dudx = (u(i + 1, k) - u(i - 1, k)) / (2 * h)
            fx += sgn * (RHO * u(i, k) ** 2 + pp - 2 * MU * dudx) * h
    for sgn, k in ((-1, ka), (1, kb)):  # faces z = k h
        for i in range(ia, ib):
            uu = 0.25 * (u(i, k - 1) + u(i + 1, k - 1) + u(i, k) + u(i + 1, k))
            dwdx = (w(i + 1, k) - w(i - 1, k)) / (2 * h)
            dudz = 0.5 * ((u(i, k) - u(i, k - 1)) + (u(i + 1, k) - u(i + 1, k - 1))) / h
            fx += sgn * (RHO * uu * w(i, k) - MU * (dudz + dwdx)) * h
    return -fx


def inside(x, z):
    return (x - C) ** 2 + (z - C) ** 2 < R * R


def crossing(x0, z0, x1, z1):
    lo, hi = 0.0, 1.0
    for _ in range(60):
        m = 0.5 * (lo + hi)
        if inside(x0 + m * (x1 - x0), z0 + m * (z1 - z0)):
            hi = m
        else:
            lo = m
    return 0.5 * (lo + hi)


def legs(u, h):
    """Viscous x-load of the u legs (the w legs give no x-load): stored first nodes, smoothed."""
    stored = smooth = 0.0
    ratios = []
    for i in range(round(0.13 / h), round(0.27 / h)):
        for k in range(round(0.13 / h), round(0.27 / h)):
            x, z = i * h, (k + 0.5) * h
            if inside(x, z):
                continue
            for di, dk in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                if not inside(x + di * h, z + dk * h):
                    continue
                th = crossing(x, z, x + di * h, z + dk * h)
                up, u1, u2 = u(i, k), u(i - di, k - dk), u(i - 2 * di, k - 2 * dk)
                a1, a2 = th + 1.0, th + 2.0  # distances from the wall in h
                b = (u2 / a2 - u1 / a1) / (a2 - a1)
                up_s = (u1 / a1 - b * a1) * th + b * th * th  # the quadratic through 0, u1, u2
                if abs(up_s) > 1e-3:
                    ratios.append(up / up_s)
                stored += MU * up / th
                smooth += MU * up_s / th
    return stored, smooth, ratios


def main():
    run, h = sys.argv[1], float(sys.argv[2])
    t0, t1 = (float(sys.argv[3]), float(sys.argv[4])) if len(sys.argv) > 4 else (3.0, 4.0)
    halves = (0.07, 0.10, 0.15)
    cv, stored, smooth, ratios, n = [0.0] * len(halves), 0.0, 0.0, [], 0
    for path in sorted(glob.glob(run + "/checkpoints/*.h5")):
        u, w, p = fields(path)
        n += 1
        for j, half in enumerate(halves):
            lo, hi = round((C - half) / h), round((C + half) / h)
            cv[j] += SCALE * control_volume(u, w, p, h, lo, hi, lo, hi)
        s, m, r = legs(u, h)
        stored, smooth, ratios = stored + SCALE * s, smooth + SCALE * m, ratios + r
    rows = [r for r in csv.DictReader(open(run + "/forces.csv"))
            if t0 - 1e-9 <= float(r["t"]) <= t1 + 1e-9 and r["obstacle"] == "1"]
    px = SCALE * sum(float(r["pressure_x"]) for r in rows) / len(rows)
    vx = SCALE * sum(float(r["viscous_x"]) for r in rows) / len(rows)
    ref = 5.5795
    print(f"{run}: {n} checkpoints")
    print(f"  surface c_D {px + vx:.4f} ({100 * ((px + vx) / ref - 1):+.2f}%) = pressure {px:.4f}"
          f" + viscous {vx:.4f}")
    for half, v in zip(halves, cv):
        print(f"  control volume, half-width {half:.2f} m: c_D {v / n:.4f} ({100 * (v / n / ref - 1):+.2f}%)")
    ratios.sort()
    q = len(ratios)
    print(f"  viscous part from the legs: {stored / n:.4f} (first nodes as stored), {smooth / n:.4f}"
          f" (first nodes from the quadratic); first node / quadratic: median"
          f" {ratios[q // 2]:.3f}, quartiles {ratios[q // 4]:.3f} {ratios[3 * q // 4]:.3f}")
    print(f"  pressure + smoothed viscous: {px + smooth / n:.4f}"
          f" ({100 * ((px + smooth / n) / ref - 1):+.2f}%)")


if __name__ == "__main__":
    main()
