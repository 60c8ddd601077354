#!/usr/bin/env python3
"""Writes case.yaml of the granular dam break (the MPS paper's broken dam, Kim et al. 2018, sec. 3,
Fig. 2-3b, in 2D with disks).

Geometry (metres): a container TANK_L long and TANK_H high (the tank's walls; no lid is needed,
no grain reaches the top); its floor a sawtooth of teeth TOOTH_H high every TOOTH_P (rough at the
grain scale, as the paper's wall particles), one obstacle per tooth. The column, COL_L wide and
about COL_H high, stands against the left wall; it is released at t = 0 (the paper's gate opened
"at infinite speed": here no gate, the grains are placed and released).
The column is poured (placement pour) with DROPS tries per grain, each grain kept at the lowest
landing place found: with the generator's default (8) the pour is loose (a solid fraction of about
0.63 of the grains' bounding circles grown by the gap) and the column compacts as it fails; 512
tries give about 0.79, a settled random packing (doc/validation.md, "Granular column collapse").
Rerun after changing a constant: python3 make_case.py > case.yaml
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import granular_common as gc  # noqa: E402  (the floor writer)

TANK_L, TANK_H = 0.6, 0.6
TOOTH_H, TOOTH_P = 0.004, 0.01
COL_L, N_GRAINS, DROPS, T_END = 0.15, 300, 512, 1.5


def main():
    print(f"""# Granular dam break (Kim et al. 2018, sec. 3, Fig. 2-3b): a column of grains {COL_L:g} m wide
# and about 0.3 m high against the left wall of a {TANK_L:g} m x {TANK_H:g} m container, released at t = 0.
# Written by make_case.py - edit that script, not this file. README.md says more.
# {N_GRAINS} disks, d from 8 to 12 mm (uniform in ln d by number, d50 = 10 mm), density 2500, poured
# (placement pour, {DROPS} tries per grain: a settled packing) into the column's box. Floor: teeth
# {TOOTH_H * 1000:g} mm high every {TOOTH_P * 1000:g} mm, one obstacle each. Dry: no water section.
{gc.head_yaml("granular_dam_break", TANK_L, TANK_H, T_END,
             [("mu", 0.2), ("tangential_model", "accumulated")])}
obstacles:
{gc.teeth_yaml(TANK_L, TOOTH_H, TOOTH_P)}
solids:
{gc.graded_yaml("grains", 2500, [0, TOOTH_H, COL_L, TANK_H], "pour", N_GRAINS,
                (0.008, 0.01, 0.012), 1, drops=DROPS)}""")


if __name__ == "__main__":
    main()
