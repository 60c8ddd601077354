#!/usr/bin/env python3
"""Prints the `obstacles` section of case.yaml: the rough floor as one obstacle per tooth.

Teeth TOOTH_H high (valleys at TOOTH_H / 2, tips at TOOTH_H) every TOOTH_P along the tank, each a
counter-clockwise pentagon from z = 0. One polygon for the whole sawtooth has the same surface,
but the DEM gives a solid one contact per obstacle (its closest point), so a grain resting on two
teeth would get one, and it tests every grain near the floor against all its edges (600 here):
one obstacle per tooth lets the bounding-box test skip all but the teeth a grain reaches.
usage: python3 make_teeth.py   (paste the output over the obstacles section of case.yaml)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import granular_common as gc  # noqa: E402  (the floor writer)

TANK_L, TOOTH_H, TOOTH_P = 1.5, 0.004, 0.005


def main():
    print("obstacles:")
    print(gc.teeth_yaml(TANK_L, TOOTH_H, TOOTH_P))


if __name__ == "__main__":
    main()
