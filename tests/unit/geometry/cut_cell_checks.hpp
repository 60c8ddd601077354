#pragma once
// Checks shared by the cut-cell tests: the discrete divergence theorem per cell and the totals
// (length, area, n dl, first moments) of a single solid against its perimeter and area.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "picdem/geometry/cut_cells.hpp"

namespace cut_cell_checks {

using picdem::core::Box2;
using picdem::geometry::CutCellOptions;
using picdem::geometry::CutCells;
using picdem::geometry::GridWindow;
using picdem::geometry::SolidPlacement;
using picdem::geometry::Vec2;

inline GridWindow window_around(const Box2& b, Vec2 origin, double h, int margin) {
  GridWindow w;
  w.origin = origin;
  w.h = h;
  w.cells = {static_cast<int>(std::floor((b.lo.x - origin.x) / h)) - margin,
             static_cast<int>(std::floor((b.hi.x - origin.x) / h)) + 1 + margin,
             static_cast<int>(std::floor((b.lo.z - origin.z) / h)) - margin,
             static_cast<int>(std::floor((b.hi.z - origin.z) / h)) + 1 + margin};
  return w;
}

/// Largest |sum_f E_f n_f - sum integral n dl| / h over the non-dropped cells of the window.
inline double divergence_residual(const CutCells& cc) {
  const auto& b = cc.window.cells;
  std::map<std::pair<int, int>, Vec2> ndl;
  for (const auto& p : cc.pieces) ndl[{p.i, p.k}] += p.n_dl;
  double worst = 0.0;
  for (int k = b.k0; k < b.k1; ++k) {
    for (int i = b.i0; i < b.i1; ++i) {
      if (cc.dropped(i, k)) continue;
      const Vec2 faces{cc.E_x(i + 1, k) - cc.E_x(i, k), cc.E_z(i, k + 1) - cc.E_z(i, k)};
      const Vec2 r = faces - ndl[{i, k}];
      worst = std::max(worst, std::max(std::fabs(r.x), std::fabs(r.z)) / cc.window.h);
    }
  }
  return worst;
}

struct Totals {
  double length = 0, area = 0;
  Vec2 n_dl;
  double r_cross_n = 0;
  // int x n dl, int z n dl, (int x (r x n) dl, int z (r x n) dl) over the whole boundary, from the
  // pieces' first moments about their cells' centres
  Vec2 x_n, z_n, x_r_cross_n;
};
inline Totals totals(const CutCells& cc) {
  Totals t;
  for (const auto& p : cc.pieces) {
    t.length += p.length;
    t.n_dl += p.n_dl;
    t.r_cross_n += p.r_cross_n_dl;
    const Vec2 xc = cc.window.origin + cc.window.h * Vec2{p.i + 0.5, p.k + 0.5};
    t.x_n += p.dx_n_dl + xc.x * p.n_dl;
    t.z_n += p.dz_n_dl + xc.z * p.n_dl;
    t.x_r_cross_n += p.d_r_cross_n_dl + p.r_cross_n_dl * xc;
  }
  const auto& b = cc.window.cells;
  for (int k = b.k0; k < b.k1; ++k) {
    for (int i = b.i0; i < b.i1; ++i)
      t.area += (1.0 - cc.fluid_fraction(i, k)) * cc.window.h * cc.window.h;
  }
  return t;
}

inline CutCellOptions keep_all() {
  CutCellOptions o;
  o.tiny_fraction = 0.0;
  return o;
}

/// The common invariants of a single solid fully inside the window.
inline void expect_invariants(const CutCells& cc, const SolidPlacement& s, double perimeter,
                              double tol) {
  EXPECT_LT(divergence_residual(cc), tol);
  const Totals t = totals(cc);
  const double A = s.shape->mass_properties().area;
  EXPECT_NEAR(t.length, perimeter, tol * perimeter);
  EXPECT_NEAR(t.area, A, tol * A);
  const double L = std::sqrt(A);
  EXPECT_NEAR(t.n_dl.x, 0.0, tol * L);
  EXPECT_NEAR(t.n_dl.z, 0.0, tol * L);
  EXPECT_NEAR(t.r_cross_n, 0.0, tol * A);
  // Divergence theorem: int x_a n_b dl = delta_ab A, and int x_a (r x n) dl = (-int r_z dA,
  // int r_x dA) = 0 about the centre of mass. These make the hydrostatic quadrature exact.
  const double scale = A * (1.0 + picdem::core::norm(s.pose.x) / L);
  EXPECT_NEAR(t.x_n.x, A, tol * scale);
  EXPECT_NEAR(t.x_n.z, 0.0, tol * scale);
  EXPECT_NEAR(t.z_n.x, 0.0, tol * scale);
  EXPECT_NEAR(t.z_n.z, A, tol * scale);
  EXPECT_NEAR(t.x_r_cross_n.x, 0.0, tol * scale * L);
  EXPECT_NEAR(t.x_r_cross_n.z, 0.0, tol * scale * L);
}

}  // namespace cut_cell_checks
