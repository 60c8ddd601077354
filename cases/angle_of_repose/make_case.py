#!/usr/bin/env python3
"""Writes case.yaml of the angle-of-repose case (the MPS paper's cargo dump in 2D, through a slot).

Geometry (metres): a tank TANK_L long; its floor a sawtooth of teeth TOOTH_H high every TOOTH_P
(rough: the heap's base cannot slide out), one obstacle per tooth; a container of inner width
BOX_W centred on the tank, walls WALL_T thick from its flat bottom up to WALL_TOP; the bottom,
WALL_T thick with its underside (the mouth) at MOUTH_Z (the MPS paper's 0.17 m; 0.34 m for its
raised dump), has a slot SLOT_W wide in the middle. The grains poured onto the bottom at t = 0
run out through the slot and pile up below it.
Rerun after changing a constant: python3 make_case.py [MOUTH_Z] > case.yaml
"""
import sys

TANK_L, TANK_H = 1.6, 0.8
TOOTH_H, TOOTH_P = 0.004, 0.01
MOUTH_Z, BOX_W, SLOT_W, WALL_T, WALL_TOP = 0.17, 0.2, 0.07, 0.01, 0.75
N_GRAINS, T_END = 300, 2.0


def teeth():
    """The floor as one obstacle per tooth (counter-clockwise), so that the contact search tests
    a grain only against the teeth whose boxes it reaches and a grain resting on two teeth gets a
    contact from each (one polygon for the whole floor gives one contact, its closest point)."""
    out = []
    for k in range(round(TANK_L / TOOTH_P)):
        x0, x1 = k * TOOTH_P, (k + 1) * TOOTH_P
        out.append(([x0, x1, x1, x0 + TOOTH_P / 2, x0],
                    [0.0, 0.0, TOOTH_H / 2, TOOTH_H, TOOTH_H / 2]))
    return out


def rect(x0, x1, z0, z1):
    return [x0, x1, x1, x0], [z0, z0, z1, z1]


def fmt(v):
    return "[" + ", ".join(f"{a:.6g}" for a in v) + "]"


def teeth_yaml():
    return "\n".join(f"  tooth_{k}:\n    type: polygon\n    x: {fmt(x)}\n    z: {fmt(z)}"
                     for k, (x, z) in enumerate(teeth()))


def containers(xc, mouth_z):
    """The container's halves, L-shaped (side wall and half of the bottom), counter-clockwise."""
    xl, xr, s, top, bot = xc - BOX_W / 2, xc + BOX_W / 2, SLOT_W / 2, mouth_z + WALL_T, mouth_z
    left = ([xl - WALL_T, xc - s, xc - s, xl, xl, xl - WALL_T],
            [bot, bot, top, top, WALL_TOP, WALL_TOP])
    right = ([xc + s, xr + WALL_T, xr + WALL_T, xr, xr, xc + s],
             [bot, bot, WALL_TOP, WALL_TOP, top, top])
    return left, right


def main():
    mouth_z = float(sys.argv[1]) if len(sys.argv) > 1 else MOUTH_Z
    xc = TANK_L / 2
    (lx, lz), (rx, rz) = containers(xc, mouth_z)
    print(f"""# Angle of repose of a heap poured through a slot, dry (the MPS paper's cargo dump,
# Kim et al. 2018, sec. 3: container mouth {mouth_z:g} m above the floor), in 2D.
# Written by make_case.py (geometry) - edit that script, not this file. README.md says more.
# {N_GRAINS} disks, d from 8 to 12 mm (uniform in ln d by number, d50 = 10 mm), density 2500, poured
# (placement pour) onto the bottom of a container of inner width {BOX_W:g} m whose bottom has a slot
# {SLOT_W:g} m wide; they run out at t = 0. Floor: teeth {TOOTH_H * 1000:g} mm high every
# {TOOTH_P * 1000:g} mm, one obstacle each. sweep.sh runs dem/mu = 0.1..0.4 with
# dem/rolling_resistance = 0 and 0.1.
case:
  name: angle_of_repose
grid:
  length: {TANK_L}
  height: {TANK_H}
  cell_size: 0.002
time:
  end: {T_END}
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
{teeth_yaml()}
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
    region: [{xc - BOX_W / 2:.6g}, {mouth_z + WALL_T:.6g}, {xc + BOX_W / 2:.6g}, {WALL_TOP:.6g}]
    placement: pour
    count: {N_GRAINS}
    basis: number
    d_min: 0.008
    d50: 0.01
    d_max: 0.012
    seed: 1""")


if __name__ == "__main__":
    main()
