#!/usr/bin/env python3
"""Writes case.yaml of the angle-of-repose case (the MPS paper's cargo dump in 2D).

Geometry (metres): a tank TANK_L long; its floor a sawtooth of teeth TOOTH_H high every TOOTH_P
(rough: the heap's base cannot slide out); a container of inner width MOUTH_W centred on the tank,
walls WALL_T thick from the mouth at MOUTH_Z (the MPS paper's 0.17 m) up to WALL_TOP, with no
bottom: the grains placed in it at t = 0 fall through the mouth (the MPS paper's container whose
bottom is opened at once). Rerun after changing a constant: python3 make_case.py > case.yaml
"""
TANK_L, TANK_H = 1.6, 0.55
TOOTH_H, TOOTH_P = 0.004, 0.01
MOUTH_Z, MOUTH_W, WALL_T, WALL_TOP = 0.17, 0.3, 0.01, 0.54


def floor():
    n = round(TANK_L / TOOTH_P)
    xs, zs = [0.0, TANK_L], [0.0, 0.0]
    for k in range(n, 0, -1):  # counter-clockwise: along the top from right to left
        xs += [k * TOOTH_P, (k - 0.5) * TOOTH_P]
        zs += [TOOTH_H / 2, TOOTH_H]
    xs.append(0.0)
    zs.append(TOOTH_H / 2)
    return xs, zs


def wall(x0):
    x1 = x0 + WALL_T
    return [x0, x1, x1, x0], [MOUTH_Z, MOUTH_Z, WALL_TOP, WALL_TOP]


def fmt(v):
    return "[" + ", ".join(f"{a:.6g}" for a in v) + "]"


def main():
    xc = TANK_L / 2
    fx, fz = floor()
    lx, lz = wall(xc - MOUTH_W / 2 - WALL_T)
    rx, rz = wall(xc + MOUTH_W / 2)
    print(f"""# Angle of repose of a heap dumped from a container through its open mouth, dry (the MPS
# paper's cargo dump, Kim et al. 2018, sec. 3: container mouth 0.17 m above the floor), in 2D.
# Written by make_case.py (geometry) - edit that script, not this file. README.md says more.
# 500 disks, d from 8 to 12 mm (uniform in ln d by number, d50 = 10 mm), density 2500, poured
# (placement pour) into the container of inner width {MOUTH_W} m; released at t = 0 (no bottom).
# Floor: teeth {TOOTH_H * 1000:g} mm high every {TOOTH_P * 1000:g} mm. sweep.sh runs dem/mu = 0.1..0.4 with
# dem/rolling_resistance = 0 and 0.1.
case:
  name: angle_of_repose
grid:
  length: {TANK_L}
  height: {TANK_H}
  cell_size: 0.002
time:
  end: 1.5
  dt_max: 0.0001
output:
  interval: 0.05
  paraview: false
  png: false
  directory: out_angle_of_repose
dem:
  mu: 0.1
  rolling_resistance: 0
  gap_cells: 1
  theta: 0.002
obstacles:
  floor:
    type: polygon
    x: {fmt(fx)}
    z: {fmt(fz)}
  container_left:
    type: polygon
    x: {fmt(lx)}
    z: {fmt(lz)}
  container_right:
    type: polygon
    x: {fmt(rx)}
    z: {fmt(rz)}
solids:
  grains:
    type: graded_packing
    density: 2500
    region: [{xc - MOUTH_W / 2:.6g}, {MOUTH_Z + 0.002:.6g}, {xc + MOUTH_W / 2:.6g}, {WALL_TOP:.6g}]
    placement: pour
    count: 500
    basis: number
    d_min: 0.008
    d50: 0.01
    d_max: 0.012
    seed: 1""")


if __name__ == "__main__":
    main()
