# The stability limit of eqs. 21-24 (picdem's DEM subcycle) for a damped spring
# x'' = -omega^2 x - 2 zeta omega x', u = omega dt_DEM (doc/dem.md, "Damped time step"):
# trace and determinant of one subcycle (sympy), then the spectral radius scanned over u (numpy)
# against 2 (sqrt(1 + zeta^2) - zeta), for both dem/position_update choices.
# Run: /usr/bin/python3 doc/dem_damped_step_limit.py
import numpy as np
import sympy as sp


def subcycle(x, v, u, zeta, mode):
    f = lambda x, v: -x - 2 * zeta * v  # time in units of 1 / omega
    va = v + u * f(x, v)  # eq. 21
    xa = x + u / 2 * va if mode == "step_start" else x + u / 2 * (v + va)  # eq. 22 (U^n = 0)
    vn = v + u / 2 * (f(x, v) + f(xa, va))  # eq. 23
    xn = x + u / 2 * vn if mode == "step_start" else x + u / 2 * (v + vn)  # eq. 24
    return xn, vn


u, z, x, v = sp.symbols("u zeta x v")
for mode in ("step_start", "subcycle_start"):
    xn, vn = (sp.expand(e) for e in subcycle(x, v, u, z, mode))
    A = sp.Matrix([[xn.coeff(x), xn.coeff(v)], [vn.coeff(x), vn.coeff(v)]])
    print(mode, "tr =", sp.factor(A.trace()), " det =", sp.factor(A.det()),
          " 1 - tr + det =", sp.factor(1 - A.trace() + A.det()))


def radius(u, zeta, mode):
    cols = [subcycle(1.0, 0.0, u, zeta, mode), subcycle(0.0, 1.0, u, zeta, mode)]
    return max(abs(np.linalg.eigvals(np.array(cols).T)))


for zeta in (0.0, 0.4, 0.4 * 2 ** 0.5, 1.0, 10.0, 1414.2):
    found = []
    for mode in ("step_start", "subcycle_start"):
        lo, hi = 1e-9, 4.0
        grid = np.linspace(1e-6, 4.0, 4001)
        for a, b in zip(grid[:-1], grid[1:]):
            if radius(b, zeta, mode) > 1 + 1e-13:
                lo, hi = a, b
                break
        for _ in range(60):
            m = 0.5 * (lo + hi)
            lo, hi = (lo, m) if radius(m, zeta, mode) > 1 + 1e-13 else (m, hi)
        found.append(lo)
    print(f"zeta {zeta:8.4f}: 2 (sqrt(1 + zeta^2) - zeta) = {2 / (np.hypot(1, zeta) + zeta):.9g}, "
          f"scanned step_start {found[0]:.9g}, subcycle_start {found[1]:.9g}")
