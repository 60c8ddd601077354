// Cut cells: the discrete divergence theorem per cell, totals (length, area), shift invariance,
// agreement with an independent slow reference, and the degenerate placements one by one.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>

#include "cut_cell_checks.hpp"
#include "picdem/core/error.hpp"
#include "picdem/geometry/circle.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/geometry/outline.hpp"
#include "picdem/geometry/polygon.hpp"
#include "reference.hpp"

#include <CGAL/Exact_rational.h>

using namespace picdem::geometry;
using picdem::core::Box2;
using namespace cut_cell_checks;

namespace {

ShapePtr random_polygon(std::mt19937_64& rng, double R, int n, bool convex) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> phi(n);
  for (int j = 0; j < n; ++j) phi[j] = 2.0 * M_PI * (j + 0.8 * u(rng)) / n;
  std::vector<Vec2> v;
  for (int j = 0; j < n; ++j) {
    const double r = convex ? R : R * (0.45 + 0.55 * u(rng));
    v.push_back({r * std::cos(phi[j]), r * std::sin(phi[j])});
  }
  return std::make_shared<Polygon>(v);
}

/// Compares every face and cell of `cc` (one solid) with the slow reference: a polygon in exact
/// rational arithmetic (CGAL::Exact_rational) when `exact`, else in long double; a circle by the
/// closed-form disc-rectangle integral in long double.
void expect_matches_reference(const CutCells& cc, const SolidPlacement& s, double tol,
                              bool exact = false) {
  using Q = CGAL::Exact_rational;
  const double h = cc.window.h;
  const Vec2 o = cc.window.origin;
  const auto& b = cc.window.cells;
  const auto* circle = dynamic_cast<const Circle*>(s.shape.get());
  std::vector<ref::P> poly, poly_t;  // poly_t: x and z swapped (for horizontal faces)
  std::vector<ref::PT<Q>> qpoly, qpoly_t;
  if (!circle) {
    for (const auto& v : dynamic_cast<const Polygon&>(*s.shape).vertices()) {
      const Vec2 w = s.pose.to_world(v);
      poly.push_back({w.x, w.z});
      poly_t.push_back({w.z, w.x});
      qpoly.push_back({Q(w.x), Q(w.z)});
      qpoly_t.push_back({Q(w.z), Q(w.x)});
    }
  }
  const bool use_q = exact && !circle;
  // grid line positions, exactly o + i h
  auto qx = [&](int i) -> Q { return Q(o.x) + Q(i) * Q(h); };
  auto qz = [&](int k) -> Q { return Q(o.z) + Q(k) * Q(h); };
  auto face = [&](bool vertical, int i, int k) -> double {
    if (use_q) {
      const Q c = vertical ? ref::polygon_vertical_face(qpoly, qx(i), qz(k), qz(k + 1))
                           : ref::polygon_vertical_face(qpoly_t, qz(k), qx(i), qx(i + 1));
      return CGAL::to_double(c);
    }
    const ref::LD line = vertical ? o.x + ref::LD(i) * h : o.z + ref::LD(k) * h;
    const ref::LD a = vertical ? o.z + ref::LD(k) * h : o.x + ref::LD(i) * h;
    if (circle) {
      return static_cast<double>(
          vertical
              ? ref::disc_vertical_face(s.pose.x.x, s.pose.x.z, circle->radius(), line, a, a + h)
              : ref::disc_vertical_face(s.pose.x.z, s.pose.x.x, circle->radius(), line, a, a + h));
    }
    return static_cast<double>(vertical ? ref::polygon_vertical_face(poly, line, a, a + h)
                                        : ref::polygon_vertical_face(poly_t, line, a, a + h));
  };
  for (int k = b.k0; k < b.k1; ++k) {
    for (int i = b.i0; i <= b.i1; ++i) {
      ASSERT_NEAR(cc.E_x(i, k), h - face(true, i, k), tol * h) << "FaceX " << i << " " << k;
    }
  }
  for (int k = b.k0; k <= b.k1; ++k) {
    for (int i = b.i0; i < b.i1; ++i) {
      ASSERT_NEAR(cc.E_z(i, k), h - face(false, i, k), tol * h) << "FaceZ " << i << " " << k;
    }
  }
  for (int k = b.k0; k < b.k1; ++k) {
    for (int i = b.i0; i < b.i1; ++i) {
      double a;
      if (use_q) {
        a = CGAL::to_double(Q(ref::polygon_rect(qpoly, qx(i), qx(i + 1), qz(k), qz(k + 1))) /
                            (Q(h) * Q(h)));
      } else {
        const ref::LD x0 = o.x + ref::LD(i) * h, z0 = o.z + ref::LD(k) * h;
        a = static_cast<double>((circle ? ref::disc_rect(s.pose.x.x, s.pose.x.z, circle->radius(),
                                                         x0, x0 + h, z0, z0 + h)
                                        : ref::polygon_rect(poly, x0, x0 + h, z0, z0 + h)) /
                                (ref::LD(h) * h));
      }
      ASSERT_NEAR(1.0 - cc.fluid_fraction(i, k), a, tol) << "cell " << i << " " << k;
    }
  }
}

double polygon_perimeter(const Polygon& p) {
  double L = 0;
  const auto& v = p.vertices();
  for (std::size_t j = 0; j < v.size(); ++j) L += picdem::core::norm(v[(j + 1) % v.size()] - v[j]);
  return L;
}

}  // namespace

TEST(CutCells, RandomCirclesHoldEveryInvariant) {
  std::mt19937_64 rng(20190301);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double h = 0.01 + 0.2 * u(rng);
    const double r = h * (0.2 + 15.0 * u(rng));
    const Vec2 origin{-1.0 + 2.0 * u(rng), -1.0 + 2.0 * u(rng)};
    SolidPlacement s{
        trial, std::make_shared<Circle>(r), {{4.0 * u(rng), 3.0 * u(rng)}, 6.0 * u(rng)}};
    const auto w = window_around(bounding_box(*s.shape, s.pose), origin, h, 2);
    const CutCells cc = build_cut_cells(w, {s}, {}, keep_all());
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_invariants(cc, s, 2.0 * M_PI * r, 1e-12);
    if (trial % 10 == 0) expect_matches_reference(cc, s, 1e-12);
    if (HasFailure()) return;
  }
}

TEST(CutCells, RandomPolygonsHoldEveryInvariant) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double h = 0.01 + 0.2 * u(rng);
    const int n = 3 + static_cast<int>(60 * u(rng));
    const auto shape = random_polygon(rng, h * (0.3 + 12.0 * u(rng)), n, trial % 2 == 0);
    const Vec2 origin{-1.0 + 2.0 * u(rng), -1.0 + 2.0 * u(rng)};
    SolidPlacement s{trial, shape, {{4.0 * u(rng), 3.0 * u(rng)}, 6.0 * u(rng)}};
    const auto w = window_around(bounding_box(*s.shape, s.pose), origin, h, 2);
    const CutCells cc = build_cut_cells(w, {s}, {}, keep_all());
    SCOPED_TRACE("trial " + std::to_string(trial) + " n " + std::to_string(n));
    expect_invariants(cc, s, polygon_perimeter(dynamic_cast<const Polygon&>(*shape)), 1e-12);
    if (trial % 10 == 0) expect_matches_reference(cc, s, 1e-12, /*exact=*/trial % 100 == 0);
    if (HasFailure()) return;
  }
}

TEST(CutCells, ShiftByWholeCellsGivesIdenticalData) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double h = 0.125;
  for (int trial = 0; trial < 400; ++trial) {
    const ShapePtr shape = trial % 2 ? random_polygon(rng, 1.0, 12, false)
                                     : ShapePtr(std::make_shared<Circle>(0.2 + u(rng)));
    const Pose pose{{3.0 + u(rng), 3.0 + u(rng)}, 6.0 * u(rng)};
    const int m = static_cast<int>(20 * u(rng)) - 10, n = static_cast<int>(20 * u(rng)) - 10;
    const auto w = window_around(bounding_box(*shape, pose), {0, 0}, h, 1);
    GridWindow w2 = w;
    w2.cells = {w.cells.i0 + m, w.cells.i1 + m, w.cells.k0 + n, w.cells.k1 + n};
    const Pose pose2{pose.x + Vec2{m * h, n * h}, pose.theta};
    const CutCells a = build_cut_cells(w, {{0, shape, pose}}, {}, keep_all());
    const CutCells b = build_cut_cells(w2, {{0, shape, pose2}}, {}, keep_all());
    const double tol = 1e-12 * h;
    for (int k = w.cells.k0; k < w.cells.k1; ++k) {
      for (int i = w.cells.i0; i < w.cells.i1; ++i) {
        ASSERT_NEAR(a.E_x(i, k), b.E_x(i + m, k + n), tol);
        ASSERT_NEAR(a.E_z(i, k), b.E_z(i + m, k + n), tol);
        ASSERT_NEAR(a.fluid_fraction(i, k), b.fluid_fraction(i + m, k + n), 1e-12);
        ASSERT_EQ(a.cutting_body(i, k), b.cutting_body(i + m, k + n));
      }
    }
    ASSERT_EQ(a.pieces.size(), b.pieces.size());
    for (std::size_t j = 0; j < a.pieces.size(); ++j) {
      const auto &p = a.pieces[j], &q = b.pieces[j];
      ASSERT_EQ(p.i + m, q.i);
      ASSERT_EQ(p.k + n, q.k);
      ASSERT_NEAR(p.n_dl.x, q.n_dl.x, tol);
      ASSERT_NEAR(p.n_dl.z, q.n_dl.z, tol);
      ASSERT_NEAR(p.r_cross_n_dl, q.r_cross_n_dl, tol * h);
      ASSERT_NEAR(p.length, q.length, tol);
      ASSERT_NEAR(p.p0.x + m * h, q.p0.x, tol);
      ASSERT_NEAR(p.p1.z + n * h, q.p1.z, tol);
    }
  }
}

// ---- degenerate placements (h = 1, origin 0: grid lines are the integers) -------------------

namespace {
GridWindow unit_window(int n) {
  return {{0.0, 0.0}, 1.0, {0, n, 0, n}};
}
}  // namespace

TEST(CutCellsDegenerate, CircleTangentToVerticalLines) {
  // centre 5.5 +/- 1.5 touches x = 4 and x = 7 exactly
  const SolidPlacement s{0, std::make_shared<Circle>(1.5), {{5.5, 5.3}, 0.3}};
  const CutCells cc = build_cut_cells(unit_window(12), {s}, {}, keep_all());
  expect_invariants(cc, s, 3.0 * M_PI, 1e-12);
  expect_matches_reference(cc, s, 1e-12);
  for (int k = 0; k < 12; ++k) {
    EXPECT_EQ(cc.E_x(4, k), 1.0);
    EXPECT_EQ(cc.E_x(7, k), 1.0);
    EXPECT_EQ(cc.fluid_fraction(3, k), 1.0);
    EXPECT_EQ(cc.fluid_fraction(7, k), 1.0);
  }
}

TEST(CutCellsDegenerate, CircleTangentToHorizontalLines) {
  const SolidPlacement s{0, std::make_shared<Circle>(1.5), {{5.3, 5.5}, 0.0}};
  const CutCells cc = build_cut_cells(unit_window(12), {s}, {}, keep_all());
  expect_invariants(cc, s, 3.0 * M_PI, 1e-12);
  expect_matches_reference(cc, s, 1e-12);
  for (int i = 0; i < 12; ++i) {
    EXPECT_EQ(cc.E_z(i, 4), 1.0);
    EXPECT_EQ(cc.E_z(i, 7), 1.0);
  }
}

TEST(CutCellsDegenerate, CircleNearlyTangent) {
  // 2^-40 left of the tangent position: it misses x = 7 by 2^-40 and crosses x = 4 on a chord of
  // ~3e-6 whose arc bulges ~1e-12 into column 3.
  const double eps = std::ldexp(1.0, -40);
  const SolidPlacement s{0, std::make_shared<Circle>(1.5), {{5.5 - eps, 5.3}, 0.0}};
  const CutCells cc = build_cut_cells(unit_window(12), {s}, {}, keep_all());
  expect_invariants(cc, s, 3.0 * M_PI, 1e-12);
  expect_matches_reference(cc, s, 1e-12);
  for (int k = 0; k < 12; ++k) EXPECT_EQ(cc.E_x(7, k), 1.0);
  EXPECT_LT(cc.E_x(4, 5), 1.0);
  EXPECT_GT(cc.E_x(4, 5), 1.0 - 1e-5);
  bool beyond = false;
  for (const auto& p : cc.pieces) beyond = beyond || (p.i == 3 && p.k == 5 && p.length > 0);
  EXPECT_TRUE(beyond);
  EXPECT_EQ(cc.cutting_body(3, 5), 0);
  EXPECT_EQ(cc.cutting_body(7, 5), -1);
}

TEST(CutCellsDegenerate, CircleThroughGridCorners) {
  // radius 5 about (6, 6) passes through the corners (9, 10), (10, 9), (2, 3), ... (3-4-5)
  const SolidPlacement s{0, std::make_shared<Circle>(5.0), {{6.0, 6.0}, 0.0}};
  const CutCells cc = build_cut_cells(unit_window(13), {s}, {}, keep_all());
  expect_invariants(cc, s, 10.0 * M_PI, 1e-12);
  expect_matches_reference(cc, s, 1e-12);
}

TEST(CutCellsDegenerate, TinyCircleInsideOneCell) {
  const SolidPlacement s{0, std::make_shared<Circle>(0.2), {{3.5, 2.5}, 0.0}};
  const CutCells cc = build_cut_cells(unit_window(6), {s}, {}, keep_all());
  expect_invariants(cc, s, 0.4 * M_PI, 1e-12);
  ASSERT_EQ(cc.pieces.size(), 1u);
  EXPECT_EQ(cc.pieces[0].i, 3);
  EXPECT_EQ(cc.pieces[0].k, 2);
  EXPECT_EQ(cc.cutting_body(3, 2), 0);
  EXPECT_EQ(cc.cutting_body(2, 2), -1);
}

TEST(CutCellsDegenerate, PolygonVerticesOnGridLinesAndCorners) {
  // a diamond whose left and right apexes are grid corners, the others on vertical lines
  const std::vector<Vec2> v{{2.0, 5.0}, {3.5, 3.7}, {5.0, 5.0}, {3.5, 6.3}};
  const auto poly = std::make_shared<Polygon>(v);
  const SolidPlacement s{0, poly, {poly->centroid_offset(), 0.0}};
  const CutCells cc = build_cut_cells(unit_window(8), {s}, {}, keep_all());
  expect_invariants(cc, s, polygon_perimeter(*poly), 1e-12);
  expect_matches_reference(cc, s, 1e-12, /*exact=*/true);
  // The apex (2, 5) only touches the line x = 2: the face stays open.
  EXPECT_EQ(cc.E_x(2, 4), 1.0);
  EXPECT_EQ(cc.E_x(2, 5), 1.0);
  EXPECT_EQ(cc.cutting_body(1, 4), -1);
}

TEST(CutCellsDegenerate, PolygonEdgesOnGridLines) {
  // an axis-aligned rectangle covering cells [2, 5) x [2, 4) exactly
  const std::vector<Vec2> v{{2, 2}, {5, 2}, {5, 4}, {2, 4}};
  const auto poly = std::make_shared<Polygon>(v);
  const SolidPlacement s{0, poly, {poly->centroid_offset(), 0.0}};
  const CutCells cc = build_cut_cells(unit_window(8), {s}, {}, keep_all());
  expect_invariants(cc, s, 10.0, 1e-12);
  for (int k = 2; k < 4; ++k) {
    for (int i = 2; i < 5; ++i) EXPECT_EQ(cc.fluid_fraction(i, k), 0.0);
    for (int i = 2; i <= 5; ++i) EXPECT_EQ(cc.E_x(i, k), 0.0) << i << " " << k;
    EXPECT_EQ(cc.E_x(1, k), 1.0);
    EXPECT_EQ(cc.E_x(6, k), 1.0);
    EXPECT_EQ(cc.fluid_fraction(1, k), 1.0);
  }
  // The left edge lies on x = 2: it belongs to the fluid cells (1, k), normal -x.
  int left = 0;
  for (const auto& p : cc.pieces) {
    if (p.i == 1) {
      ++left;
      EXPECT_EQ(p.n_dl.x, -1.0);
      EXPECT_EQ(p.n_dl.z, 0.0);
      EXPECT_EQ(p.body, 0);
    }
  }
  EXPECT_EQ(left, 2);
  EXPECT_EQ(cc.cutting_body(1, 2), 0);
  EXPECT_EQ(cc.cutting_body(3, 3), 0);
}

TEST(CutCellsDegenerate, SquareRotatedOntoGridCorners) {
  const std::vector<Vec2> v{{3, 1}, {5, 3}, {3, 5}, {1, 3}};
  const auto poly = std::make_shared<Polygon>(v);
  const SolidPlacement s{0, poly, {poly->centroid_offset(), 0.0}};
  const CutCells cc = build_cut_cells(unit_window(7), {s}, {}, keep_all());
  expect_invariants(cc, s, 8.0 * std::sqrt(2.0), 1e-12);
  expect_matches_reference(cc, s, 1e-12, /*exact=*/true);
  EXPECT_EQ(cc.fluid_fraction(2, 2), 0.0);
  EXPECT_EQ(cc.fluid_fraction(1, 1), 1.0);
  EXPECT_EQ(cc.fluid_fraction(2, 1), 0.5);
}

TEST(CutCellsDegenerate, EdgeOnHorizontalLineOffsetInX) {
  const std::vector<Vec2> v{{2.5, 3}, {4.5, 3}, {4.5, 5.5}, {2.5, 5.5}};
  const auto poly = std::make_shared<Polygon>(v);
  const SolidPlacement s{0, poly, {poly->centroid_offset(), 0.0}};
  const CutCells cc = build_cut_cells(unit_window(8), {s}, {}, keep_all());
  expect_invariants(cc, s, 9.0, 1e-12);
  EXPECT_EQ(cc.E_z(2, 3), 0.5);
  EXPECT_EQ(cc.E_z(3, 3), 0.0);
  EXPECT_EQ(cc.fluid_fraction(2, 2), 1.0);
}

TEST(CutCells, TinyCellsAreDroppedConsistently) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  CutCellOptions opt;
  opt.tiny_fraction = 0.05;
  int dropped = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const ShapePtr shape = trial % 2 ? random_polygon(rng, 3.0, 9, true)
                                     : ShapePtr(std::make_shared<Circle>(1.0 + 3.0 * u(rng)));
    const SolidPlacement s{0, shape, {{10.0 + u(rng), 10.0 + u(rng)}, 6.0 * u(rng)}};
    const auto w = window_around(bounding_box(*shape, s.pose), {0, 0}, 1.0, 2);
    const CutCells cc = build_cut_cells(w, {s}, {}, opt);
    EXPECT_LT(divergence_residual(cc), 1e-12);
    const Totals t = totals(cc);
    EXPECT_NEAR(t.n_dl.x, 0.0, 1e-12);
    EXPECT_NEAR(t.n_dl.z, 0.0, 1e-12);
    EXPECT_NEAR(t.r_cross_n, 0.0, 1e-11);
    const auto& b = w.cells;
    for (int k = b.k0; k < b.k1; ++k) {
      for (int i = b.i0; i < b.i1; ++i) {
        const double f = cc.fluid_fraction(i, k);
        EXPECT_TRUE(f == 0.0 || f >= opt.tiny_fraction) << f;
        if (cc.dropped(i, k)) {
          ++dropped;
          EXPECT_EQ(cc.E_x(i, k) + cc.E_x(i + 1, k) + cc.E_z(i, k) + cc.E_z(i, k + 1), 0.0);
        }
      }
    }
    if (HasFailure()) return;
  }
  EXPECT_GT(dropped, 100);
}

TEST(CutCells, OverlappingSolidsGiveTheUnionWithoutNegativeLengths) {
  const double h = 0.05;
  const auto c = std::make_shared<Circle>(1.0);
  const std::vector<SolidPlacement> solids{{0, c, {{2.0, 2.0}, 0.0}}, {1, c, {{3.0, 2.0}, 0.0}}};
  const std::vector<Obstacle> obstacles{
      {"slab", {{{1.0, 0.0}, {4.0, 0.0}, {4.0, 1.5}, {1.0, 1.5}}}}};
  const GridWindow w{{0, 0}, h, {0, 100, -4, 80}};
  const CutCells cc = build_cut_cells(w, solids, obstacles, keep_all());
  for (int k = 0; k < 80; ++k) {
    for (int i = 0; i <= 100; ++i) {
      EXPECT_GE(cc.E_x(i, k), 0.0);
      EXPECT_LE(cc.E_x(i, k), h);
    }
    for (int i = 0; i < 100; ++i) {
      EXPECT_GE(cc.fluid_fraction(i, k), 0.0);
      EXPECT_LE(cc.fluid_fraction(i, k), 1.0);
    }
  }
  // The covered face at x = 2.5 (inside both circles and the slab) is closed.
  EXPECT_EQ(cc.E_x(50, 40), 0.0);
  EXPECT_EQ(cc.cutting_body(50, 40), 0);
  // Pieces inside the other body are hidden: the wetted length is that of the union's outline,
  // to within the pieces that straddle a crossing of two outlines (a few cells).
  double length = 0;
  for (const auto& p : cc.pieces) length += p.length;
  auto inside = [](int self, const Vec2& p) {
    const bool in0 = picdem::core::norm(p - Vec2{2.0, 2.0}) <= 1.0;
    const bool in1 = picdem::core::norm(p - Vec2{3.0, 2.0}) <= 1.0;
    const bool in2 = p.x >= 1.0 && p.x <= 4.0 && p.z >= 0.0 && p.z <= 1.5;
    return (self != 0 && in0) || (self != 1 && in1) || (self != 2 && in2);
  };
  double union_length = 0;
  const std::vector<Vec2> lines[3] = {outline(*c, solids[0].pose, 1e-4),
                                      outline(*c, solids[1].pose, 1e-4),
                                      {{1.0, 0.0}, {4.0, 0.0}, {4.0, 1.5}, {1.0, 1.5}, {1.0, 0.0}}};
  for (int b = 0; b < 3; ++b) {
    const int n = b == 2 ? 20000 : 1;
    for (std::size_t j = 0; j + 1 < lines[b].size(); ++j) {
      for (int q = 0; q < n; ++q) {
        const Vec2 p0 = lines[b][j] + (double(q) / n) * (lines[b][j + 1] - lines[b][j]);
        const Vec2 p1 = lines[b][j] + (double(q + 1) / n) * (lines[b][j + 1] - lines[b][j]);
        if (!inside(b, 0.5 * (p0 + p1))) union_length += picdem::core::norm(p1 - p0);
      }
    }
  }
  EXPECT_NEAR(length, union_length, 6 * h);
  // The covered area is that of the union (overlaps counted once), to within the few cells
  // where two outlines cross; reference by midpoint sampling on a 1/800 lattice.
  double covered = 0;
  for (int k = -4; k < 80; ++k) {
    for (int i = 0; i < 100; ++i) covered += (1.0 - cc.fluid_fraction(i, k)) * h * h;
  }
  double sampled = 0;
  const double d = 1.0 / 800;
  for (double z = 0.5 * d; z < 4.0; z += d) {
    for (double x = 0.5 * d; x < 5.0; x += d) sampled += inside(-1, {x, z}) ? d * d : 0.0;
  }
  EXPECT_NEAR(covered, sampled, 4 * h * h);
}

TEST(CutCellsDegenerate, LatticePlacementsEverywhere) {
  // Vertices, centres and radii on a lattice of h/4: vertices on grid lines and corners, edges
  // along grid lines, circles tangent to lines and through corners, all at once.
  using Q = CGAL::Exact_rational;
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<int> q(0, 40);
  const GridWindow w{{0.0, 0.0}, 1.0, {-2, 14, -2, 14}};
  int tangent = 0, polygons = 0;
  for (int trial = 0; trial < 600; ++trial) {
    SolidPlacement s;
    double perimeter = 0;
    if (trial % 2 == 0) {
      const double r = 0.25 * (2 + q(rng) % 14);
      const Vec2 c{5.0 + 0.25 * (q(rng) % 12), 5.0 + 0.25 * (q(rng) % 12)};
      s = {0, std::make_shared<Circle>(r), {c, 0.0}};
      perimeter = 2 * M_PI * r;
      tangent += std::fmod(c.x + r, 1.0) == 0.0 ? 1 : 0;
    } else {
      // a star-shaped polygon about (6, 6) with lattice vertices, kept if valid
      std::vector<Vec2> v;
      const int n = 3 + q(rng) % 8;
      for (int j = 0; j < n; ++j) {
        const double phi = 2 * M_PI * (j + 0.5) / n;
        const double r = 1.0 + 0.25 * (q(rng) % 16);
        v.push_back({6.0 + 0.25 * std::round(4 * r * std::cos(phi)),
                     6.0 + 0.25 * std::round(4 * r * std::sin(phi))});
      }
      std::shared_ptr<Polygon> poly;
      try {
        poly = std::make_shared<Polygon>(v);
      } catch (const picdem::core::InputError&) {
        continue;
      }
      s = {0, poly, {poly->centroid_offset(), 0.0}};
      perimeter = polygon_perimeter(*poly);
      ++polygons;
      // exact covered area per cell
      std::vector<ref::PT<Q>> qp;
      for (const auto& p : v) qp.push_back({Q(p.x), Q(p.z)});
      const CutCells cc = build_cut_cells(w, {s}, {}, keep_all());
      for (int k = w.cells.k0; k < w.cells.k1; ++k) {
        for (int i = w.cells.i0; i < w.cells.i1; ++i) {
          const double a =
              CGAL::to_double(Q(ref::polygon_rect(qp, Q(i), Q(i + 1), Q(k), Q(k + 1))));
          ASSERT_NEAR(1.0 - cc.fluid_fraction(i, k), a, 1e-12) << trial << ": " << i << " " << k;
        }
      }
    }
    const CutCells cc = build_cut_cells(w, {s}, {}, keep_all());
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_invariants(cc, s, perimeter, 1e-12);
    for (int k = w.cells.k0; k < w.cells.k1; ++k) {
      for (int i = w.cells.i0; i <= w.cells.i1; ++i) {
        ASSERT_GE(cc.E_x(i, k), 0.0);
        ASSERT_LE(cc.E_x(i, k), 1.0);
      }
    }
    if (HasFailure()) return;
  }
  EXPECT_GT(tangent, 10);
  EXPECT_GT(polygons, 200);
}
