#!/usr/bin/env python3
"""The final heap of each run measured five ways (doc/validation.md, "Why 8 to 15 degrees").

The flank fit of analyse.py between 0.2 and 0.8 of the heap's height (the case's measure), the
same fit over 0.1-0.9, 0.3-0.7 and 0.4-0.9, and the heap's height over its half base; the base is
the contiguous run of 10 mm bins, from the summit outwards, whose top lies more than one d50 above
the teeth's tips. Reads OUT_DIR/mu<mu>_mur<mur>/solids.csv as analyse.py does.
usage: measures.py OUT_DIR [MOUTH_Z]
"""
import math
import os
import sys

import analyse

BANDS = ((0.2, 0.8), (0.1, 0.9), (0.3, 0.7), (0.4, 0.9))


def base_angle(top):
    """Height over half base [deg], height and base [m] of the surface bins top."""
    k_top = max(top, key=lambda k: (top[k], -abs((k + 0.5) * analyse.BIN - analyse.XC)))
    ends = []
    for side in (-1, 1):
        k = k_top
        while k + side in top and top[k + side] > analyse.D50:
            k += side
        ends.append(k)
    h, base = top[k_top], (ends[1] - ends[0] + 1) * analyse.BIN
    return math.degrees(math.atan(h / (base / 2))), h, base


def main():
    out = sys.argv[1]
    if len(sys.argv) > 2:
        analyse.MOUTH_Z = float(sys.argv[2])
    print("run             " + "  ".join(f"fit {a:g}-{b:g}" for a, b in BANDS) +
          "  H/half base [deg]  H [m]  base [m]")
    for _, _, name, path in analyse.runs(out):
        fr = analyse.gc.frames(path)
        top = analyse.surface(fr[max(fr)])
        fits = []
        for band in BANDS:
            analyse.BAND = band
            fits.append((analyse.gc.slope_deg(analyse.flank(top, -1)) +
                         analyse.gc.slope_deg(analyse.flank(top, +1))) / 2)
        ang, h, base = base_angle(top)
        print(f"{name:15s} " + "  ".join(f"{f:9.1f}" for f in fits) +
              f"  {ang:17.1f}  {h:.3f}  {base:.2f}")


if __name__ == "__main__":
    main()
