#!/usr/bin/env python3
"""Prints the `obstacles` section of case.yaml: the rough floor as one obstacle per tooth; or, with
--case, a whole case file for a longer (or taller) tank.

Teeth TOOTH_H high (valleys at TOOTH_H / 2, tips at TOOTH_H) every TOOTH_P along the tank, each a
counter-clockwise pentagon from z = 0. One polygon for the whole sawtooth has the same surface,
but the DEM gives a solid one contact per obstacle (its closest point), so a grain resting on two
teeth would get one, and it tests every grain near the floor against all its edges (600 here):
one obstacle per tooth lets the bounding-box test skip all but the teeth a grain reaches.
usage: python3 make_teeth.py                 (paste the output over the obstacles section of case.yaml)
       python3 make_teeth.py --case case.yaml --length 2.4 [--height 1.0] > long.yaml
                                             (case.yaml with grid/length, grid/height and the teeth
                                              set for that tank: columns of more disks, sweep.sh)
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import granular_common as gc  # noqa: E402  (the floor writer)

TANK_L, TOOTH_H, TOOTH_P = 1.5, 0.004, 0.005


def resized_case(text, length, height):
    """The case file's text with grid/length (and grid/height if given) replaced and its
    `obstacles` section replaced by teeth over the whole length."""
    def set_grid_key(text, key, value):
        pattern = re.compile(rf"^(grid:\n(?:  .*\n|\s*#.*\n)*?  {key}: )[^\n#]*", re.M)
        out, n = pattern.subn(rf"\g<1>{value:g}", text, count=1)
        if n != 1:
            sys.exit(f"make_teeth.py: no grid/{key} in the case file")
        return out
    text = set_grid_key(text, "length", length)
    if height is not None:
        text = set_grid_key(text, "height", height)
    section = re.compile(r"^obstacles:\n(?:(?:  .*|\s*#.*|)\n)*", re.M)
    text, n = section.subn(lambda _: "obstacles:\n" + gc.teeth_yaml(length, TOOTH_H, TOOTH_P)
                           + "\n", text, count=1)
    if n != 1:
        sys.exit("make_teeth.py: no obstacles section in the case file")
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", help="case file to resize (prints it whole)")
    ap.add_argument("--length", type=float, default=TANK_L, help="tank length [m]")
    ap.add_argument("--height", type=float, help="tank height [m] (with --case)")
    args = ap.parse_args()
    if args.case:
        with open(args.case) as f:
            sys.stdout.write(resized_case(f.read(), args.length, args.height))
    else:
        print("obstacles:")
        print(gc.teeth_yaml(args.length, TOOTH_H, TOOTH_P))


if __name__ == "__main__":
    main()
