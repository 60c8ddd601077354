#!/usr/bin/env python3
"""Writes case.yaml of cases/settling_disk_ring: a disk settling at the centre of a fixed ring.

The ring (inner radius b) is four fixed polygon obstacles, each a tank corner bounded by about 100
degrees of the circle (n_arc vertices per 90 degrees), overlapping but for a slot of 8 degrees at
the top that joins the fluid inside the ring to the free surface (a fluid pocket closed all round
gives a singular pressure matrix, doc/fluid.md). Run from this directory:
python3 make_case.py > case.yaml
"""
import math

L = 0.1            # tank side [m]
c = (0.5 * L, 0.5 * L)
b = 0.04           # ring radius [m]
a = 0.01           # disk radius [m]
n_arc = 128        # polygon vertices per quarter of the ring
slot = 9           # the top pieces stop 4 degrees short of 90 degrees: a slot to the free surface


def corner(q):
    """The corner obstacle of quadrant q (0: upper right, then counter-clockwise), CCW."""
    t0 = math.radians(90 * q - 5 + (slot if q == 1 else 0))
    t1 = math.radians(90 * q + 95 - (slot if q == 0 else 0))
    n = int(n_arc * (t1 - t0) / (0.5 * math.pi))
    # the arc from t1 down to t0 (the corner region lies outside the circle: clockwise about c is
    # counter-clockwise about the region), then out to the tank's corner
    arc = [(c[0] + b * math.cos(t1 + (t0 - t1) * i / n), c[1] + b * math.sin(t1 + (t0 - t1) * i / n))
           for i in range(n + 1)]
    sx = 1 if q in (0, 3) else -1
    sz = 1 if q in (0, 1) else -1
    cx, cz = c[0] + sx * c[0], c[1] + sz * c[1]  # the tank's corner
    p0, p1 = arc[-1], arc[0]  # at t0 and t1
    if q in (0, 2):  # t0 near a horizontal diameter, t1 near a vertical one
        out = [(cx, p0[1]), (cx, cz), (p1[0], cz)]
    else:
        out = [(p0[0], cz), (cx, cz), (cx, p1[1])]
    pts = arc + out
    area = 0.5 * sum(x0 * z1 - x1 * z0 for (x0, z0), (x1, z1) in zip(pts, pts[1:] + pts[:1]))
    if area < 0:
        pts.reverse()
    return pts


def fmt(v):
    return "[" + ", ".join(f"{x:.9f}" for x in v) + "]"


print("""# A disk settling at the centre of a fixed ring in a viscous fluid (Stokes regime), against the
# exact Stokes drag of a cylinder translating at the centre of a fixed concentric cylinder,
# F = 4 pi mu U / (ln(b/a) - (b^2 - a^2) / (b^2 + a^2)) per unit length, so that the terminal
# velocity is U_t = (rho_s - rho_f) g a^2 K / (4 mu), K = ln(b/a) - (b^2 - a^2) / (b^2 + a^2):
# a = 0.01 m, b = 0.04 m, rho_s = 2000, rho_f = 1000 kg/m^3, nu = 1e-2 m^2/s: U_t = 12.36 mm/s,
# Re = 2 a U_t / nu = 0.025. The ring is four overlapping corner polygons with a slot at the top
# to the free surface (make_case.py writes this file). The disk's viscous loads by the split
# (coupling/viscous_rigid_rows false, stable for this heavy disk); the pressure predictor on.
# Figures: doc/viscous.md, "Settling disk in a ring".
case:
  name: settling_disk_ring
grid:
  length: 0.1
  height: 0.1
  cell_size: 0.00125   # a / h = 8; the test runs 4, 8 and 16 cells per radius
water:
  full:
    type: level
    z: 0.098
fluid:
  density: 1000.0
  viscosity: 1.0e-2
  walls: no_slip
  viscosity_scheme: implicit
  viscous_pressure_predictor: true
solids:
  disk:
    type: disk
    radius: 0.01
    center: [0.05, 0.05]
    density: 2000.0
particles:
  jitter: 0.0
time:
  end: 0.06
  cfl: 0.5
  dt_max: 0.001
output:
  interval: 0.01
  png: false
obstacles:""")
for q in range(4):
    pts = corner(q)
    print(f"  ring_{q}:\n    type: polygon")
    print("    x: " + fmt([p[0] for p in pts]))
    print("    z: " + fmt([p[1] for p in pts]))
