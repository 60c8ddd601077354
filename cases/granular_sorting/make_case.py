#!/usr/bin/env python3
"""Writes case.yaml of the gravity-sorting case (the MPS paper's segregated lamination, Kim et al.
2018, sec. 5, Figs. 10-13, in 2D with disks, dry as the paper's).

The apparatus is the angle-of-repose case's (cases/angle_of_repose/make_case.py: a container of
inner width 0.2 m whose bottom has a slot 0.07 m wide, its underside 0.17 m above a toothed floor
in a 1.6 m tank). Three populations of equal size and different density (DENSITIES, light to
heavy) fill the container in six layers, from the bottom: light, medium, heavy, light, medium,
heavy, PER_LAYER disks each, placed at random (placement box) in bands LAYER_H high. The heavy
grains start highest on average, so that they can end lowest only by sorting, not by leaving the
container first. At t = 0 the grains run out through the slot and pile up below it.
`python3 make_case.py reversed` writes the control: the same layers with heavy and light swapped
(heavy, medium, light, heavy, medium, light from the bottom), so that the heavy grains leave first.
`python3 make_case.py water` writes case_water.yaml: the case poured into water WATER_DEPTH deep
over the whole tank (the issue's "into water"), with dt_max WATER_DT_MAX (the fluid's CFL rule sets
the step below it).
`python3 make_case.py friction` and `python3 make_case.py friction_water` write case_friction.yaml
and case_friction_water.yaml: the case (dry, and into water) with a friction coefficient per
population (the paper's "different density (and friction)", its Table 3, whose values are not in
the text we have): FRICTIONS light to heavy, each layer's `friction` key; a pair of grains takes
the smaller of its two (doc/dem.md, "Friction by population"); the floor and the container have
dem/mu = FRICTION_WALLS, the largest, so each grain meets them with its own coefficient.
Rerun after changing a constant:
python3 make_case.py [reversed | water | friction | friction_water] > case[_VARIANT].yaml
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
sys.path.insert(0, os.path.join(here, "..", "angle_of_repose"))
import granular_common as gc  # noqa: E402  (the floor and container writers)
import make_case as repose  # noqa: E402  (the cargo-dump geometry)

DENSITIES = (1500, 2500, 3500)
PER_LAYER, LAYER_H, T_END, MU = 50, 0.07, 2.5, 0.2
WATER_DEPTH, WATER_DT_MAX = 0.1, 0.0005
FRICTIONS, FRICTION_WALLS = (0.2, 0.3, 0.4), 0.4


def main():
    variant = sys.argv[1] if len(sys.argv) > 1 else ""
    order = DENSITIES[::-1] if variant == "reversed" else DENSITIES
    xc, mouth = repose.TANK_L / 2, repose.MOUTH_Z
    x0, x1 = xc - repose.BOX_W / 2, xc + repose.BOX_W / 2
    z = mouth + repose.WALL_T
    by_population = variant.startswith("friction")
    layers = []
    for k in range(6):
        rho = order[k % 3]
        layers.append(gc.graded_yaml(
            f"layer_{k}", rho, [x0, z + k * LAYER_H, x1, z + (k + 1) * LAYER_H], "box", PER_LAYER,
            (0.009, 0.01, 0.011), k + 1,
            friction=FRICTIONS[DENSITIES.index(rho)] if by_population else None))
    mu = FRICTION_WALLS if by_population else MU
    head = gc.head_yaml("granular_sorting", repose.TANK_L, repose.TANK_H, T_END,
                        [("mu", mu), ("tangential_model", "accumulated")])
    medium = f"into water {WATER_DEPTH:g} m deep" if variant.endswith("water") else "dry"
    if by_population:
        medium += ", friction " + ", ".join(f"{f:g}" for f in FRICTIONS) + " light to heavy"
        head = head.replace("granular_sorting", "granular_sorting_friction")
    if variant.endswith("water"):
        name = "granular_sorting_friction" if by_population else "granular_sorting"
        head = head.replace(f"name: {name}", f"name: {name}_water").replace(
            f"out_{name}", f"out_{name}_water").replace(
            "dt_max: 0.0001", f"dt_max: {WATER_DT_MAX:g}") + (
            f"\nwater:\n  pool:\n    type: box\n    x: [0, {repose.TANK_L:g}]\n"
            f"    z: [0, {WATER_DEPTH:g}]")
    print(f"""# Gravity sorting (segregated lamination) of grains of three densities (Kim et al. 2018, sec. 5),
# {medium}, in 2D. Written by make_case.py - edit that script, not this file. README.md says more.
# {6 * PER_LAYER} disks, d from 9 to 11 mm, densities {order[0]}, {order[1]}, {order[2]}, {order[0]}, {order[1]}, {order[2]} in six
# layers from the bottom, in the cargo-dump container of
# cases/angle_of_repose (slot 0.07 m wide, mouth {mouth:g} m above the toothed floor); they run out at t = 0.
{head}
obstacles:
{gc.teeth_yaml(repose.TANK_L, repose.TOOTH_H, repose.TOOTH_P)}
{gc.containers_yaml(*repose.containers(xc, mouth))}
solids:
{chr(10).join(layers)}""")


if __name__ == "__main__":
    main()
