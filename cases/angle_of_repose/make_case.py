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
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import granular_common as gc  # noqa: E402  (the floor and container writers)

TANK_L, TANK_H = 1.6, 0.8
TOOTH_H, TOOTH_P = 0.004, 0.01
MOUTH_Z, BOX_W, SLOT_W, WALL_T, WALL_TOP = 0.17, 0.2, 0.07, 0.01, 0.75
N_GRAINS, T_END = 300, 2.0


def containers(xc, mouth_z):
    """The container's halves, L-shaped (side wall and half of the bottom), counter-clockwise."""
    return gc.containers(xc, mouth_z, BOX_W, SLOT_W, WALL_T, WALL_TOP)


def main():
    mouth_z = float(sys.argv[1]) if len(sys.argv) > 1 else MOUTH_Z
    xc = TANK_L / 2
    print(f"""# Angle of repose of a heap poured through a slot, dry (the MPS paper's cargo dump,
# Kim et al. 2018, sec. 3: container mouth {mouth_z:g} m above the floor), in 2D.
# Written by make_case.py (geometry) - edit that script, not this file. README.md says more.
# {N_GRAINS} disks, d from 8 to 12 mm (uniform in ln d by number, d50 = 10 mm), density 2500, poured
# (placement pour) onto the bottom of a container of inner width {BOX_W:g} m whose bottom has a slot
# {SLOT_W:g} m wide; they run out at t = 0. Floor: teeth {TOOTH_H * 1000:g} mm high every
# {TOOTH_P * 1000:g} mm, one obstacle each. sweep.sh runs dem/mu = 0.1..0.4 with
# dem/rolling_resistance = 0 and 0.1.
{gc.head_yaml("angle_of_repose", TANK_L, TANK_H, T_END,
             [("mu", 0.1), ("rolling_resistance", 0)])}
obstacles:
{gc.teeth_yaml(TANK_L, TOOTH_H, TOOTH_P)}
{gc.containers_yaml(*containers(xc, mouth_z))}
solids:
{gc.graded_yaml("grains", 2500, [xc - BOX_W / 2, mouth_z + WALL_T, xc + BOX_W / 2, WALL_TOP],
                "pour", N_GRAINS, (0.008, 0.01, 0.012), 1)}""")


if __name__ == "__main__":
    main()
