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
TANK_L, TANK_H = 0.6, 0.6
TOOTH_H, TOOTH_P = 0.004, 0.01
COL_L, N_GRAINS, DROPS, T_END = 0.15, 300, 512, 1.5


def fmt(v):
    return "[" + ", ".join(f"{a:.6g}" for a in v) + "]"


def teeth_yaml():
    out = []
    for k in range(round(TANK_L / TOOTH_P)):
        x0, x1 = k * TOOTH_P, (k + 1) * TOOTH_P
        x = [x0, x1, x1, x0 + TOOTH_P / 2, x0]
        z = [0.0, 0.0, TOOTH_H / 2, TOOTH_H, TOOTH_H / 2]
        out.append(f"  tooth_{k}:\n    type: polygon\n    x: {fmt(x)}\n    z: {fmt(z)}")
    return "\n".join(out)


def main():
    print(f"""# Granular dam break (Kim et al. 2018, sec. 3, Fig. 2-3b): a column of grains {COL_L:g} m wide
# and about 0.3 m high against the left wall of a {TANK_L:g} m x {TANK_H:g} m container, released at t = 0.
# Written by make_case.py - edit that script, not this file. README.md says more.
# {N_GRAINS} disks, d from 8 to 12 mm (uniform in ln d by number, d50 = 10 mm), density 2500, poured
# (placement pour, {DROPS} tries per grain: a settled packing) into the column's box. Floor: teeth
# {TOOTH_H * 1000:g} mm high every {TOOTH_P * 1000:g} mm, one obstacle each. Dry: no water section.
case:
  name: granular_dam_break
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
  directory: out_granular_dam_break
dem:
  mu: 0.2
  tangential_model: accumulated
  gap_cells: 1
  theta: 0.002
obstacles:
{teeth_yaml()}
solids:
  grains:
    type: graded_packing
    density: 2500
    region: [0, {TOOTH_H:g}, {COL_L:g}, {TANK_H:g}]
    placement: pour
    drops: {DROPS}
    count: {N_GRAINS}
    basis: number
    d_min: 0.008
    d50: 0.01
    d_max: 0.012
    seed: 1""")


if __name__ == "__main__":
    main()
