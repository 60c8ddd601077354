// The ellipse shape (geometry/src/ellipse.cpp, doc/shapes.md): its arc spline is closed,
// tangent-continuous and convex, lies within the stated bound of the true ellipse (measured here
// independently, both ways), its mass properties equal an independent quadrature of the spline,
// its cut cells hold every invariant on random placements, and the case-file keys build it and
// reject bad values naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "arc_spline_reference.hpp"
#include "cut_cell_checks.hpp"
#include "picdem/core/error.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/geometry/outline.hpp"
#include "picdem/geometry/shape_registry.hpp"

using namespace picdem::geometry;
using namespace cut_cell_checks;
using arc_ref::LD;

namespace {

const double kAspects[] = {1.0, 1.25, 2.0, 3.0, 5.0, 7.0, 10.0};

Vec2 arc_end(const Arc& a, double phi) {
  return a.centre + a.radius * Vec2{std::cos(phi), std::sin(phi)};
}

}  // namespace

TEST(Ellipse, ArcSplineIsClosedTangentContinuousAndConvex) {
  for (const double q : kAspects) {
    for (const bool tall : {false, true}) {
      const double a = tall ? 0.3 : 0.3 * q, b = tall ? 0.3 * q : 0.3;
      const auto pieces = make_ellipse(a, b)->boundary();
      SCOPED_TRACE("a " + std::to_string(a) + " b " + std::to_string(b));
      ASSERT_EQ(pieces.size() % 8, 0u);  // biarcs, four quadrants
      for (std::size_t k = 0; k < pieces.size(); ++k) {
        const Arc& c = std::get<Arc>(pieces[k]);
        const Arc& n = std::get<Arc>(pieces[(k + 1) % pieces.size()]);
        EXPECT_GT(c.radius, 0.0);
        EXPECT_GT(c.phi1 - c.phi0, 0.0);
        EXPECT_LT(c.phi1 - c.phi0, M_PI);
        // the next arc starts where this one ends, with the same tangent (same radial direction)
        EXPECT_LT(picdem::core::norm(arc_end(c, c.phi1) - arc_end(n, n.phi0)),
                  1e-14 * std::max(a, b));
        const Vec2 dc{std::cos(c.phi1), std::sin(c.phi1)}, dn{std::cos(n.phi0), std::sin(n.phi0)};
        EXPECT_NEAR(picdem::core::cross(dc, dn), 0.0, 1e-10);
        EXPECT_GT(picdem::core::dot(dc, dn), 0.0);
      }
    }
  }
}

TEST(Ellipse, ArcSplineIsWithinTheStatedBoundOfTheTrueEllipse) {
  for (const double q : kAspects) {
    const double a = 0.2 * q, b = 0.2;
    const auto pieces = make_ellipse(a, b)->boundary();
    // spline -> ellipse: 400 points on every arc
    LD worst = 0;
    for (const auto& piece : pieces) {
      const Arc& c = std::get<Arc>(piece);
      for (int m = 0; m <= 400; ++m) {
        const LD phi = c.phi0 + (LD(c.phi1) - c.phi0) * m / 400;
        worst =
            std::max(worst, arc_ref::ellipse_distance(a, b, c.centre.x + c.radius * std::cos(phi),
                                                      c.centre.z + c.radius * std::sin(phi)));
      }
    }
    // ellipse -> spline: 5000 points of the ellipse
    LD back = 0;
    for (int m = 0; m < 5000; ++m) {
      const LD t = 2 * M_PI * (m + 0.5L) / 5000;
      back = std::max(back, arc_ref::distance(pieces, a * std::cos(t), b * std::sin(t)));
    }
    std::printf(
        "ellipse a/b = %5.2f: %3zu arcs, max distance spline->ellipse %.3e b, "
        "ellipse->spline %.3e b\n",
        q, pieces.size(), static_cast<double>(worst / b), static_cast<double>(back / b));
    EXPECT_LT(worst, ellipse_tolerance(a, b)) << "a/b " << q;
    EXPECT_LT(back, ellipse_tolerance(a, b)) << "a/b " << q;
  }
}

TEST(Ellipse, MassPropertiesAreThoseOfTheArcSpline) {
  for (const double q : kAspects) {
    const double a = 0.1, b = 0.1 * q;
    const auto e = make_ellipse(a, b);
    const auto ref = arc_ref::moments(e->boundary());
    const auto mp = e->mass_properties();
    SCOPED_TRACE("b/a " + std::to_string(q));
    EXPECT_NEAR(mp.area, static_cast<double>(ref.area), 1e-13 * mp.area);
    // centre of mass at the body origin (the spline is symmetric about both axes)
    EXPECT_NEAR(static_cast<double>(ref.sx / ref.area), 0.0, 1e-15 * b);
    EXPECT_NEAR(static_cast<double>(ref.sz / ref.area), 0.0, 1e-15 * b);
    EXPECT_NEAR(mp.polar_moment, static_cast<double>(ref.j_o), 1e-13 * mp.polar_moment);
    // against the true ellipse: every boundary point within tol, so |A - pi a b| <= tol x perimeter
    const double tol = ellipse_tolerance(a, b), P = static_cast<double>(ref.perimeter);
    EXPECT_LE(std::fabs(mp.area - M_PI * a * b), tol * P);
    // likewise |J - pi a b (a^2 + b^2) / 4| <= tol x P x (R + tol)^2, R the larger semi-axis
    const double J = M_PI * a * b * (a * a + b * b) / 4, R = std::max(a, b);
    EXPECT_LE(std::fabs(mp.polar_moment - J), tol * P * (R + tol) * (R + tol));
    std::printf("ellipse b/a = %5.2f: area / (pi a b) - 1 = %.2e, J / J_ellipse - 1 = %.2e\n", q,
                mp.area / (M_PI * a * b) - 1.0, mp.polar_moment / J - 1.0);
    EXPECT_NEAR(e->bounding_radius(), R, tol);
  }
}

TEST(Ellipse, ContainsAgreesWithTheTrueEllipseAwayFromTheBand) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double a = 0.5, b = 0.125;
  const auto e = make_ellipse(a, b);
  const double tol = ellipse_tolerance(a, b);
  int checked = 0;
  for (int n = 0; n < 200000; ++n) {
    const Vec2 p{0.6 * u(rng), 0.2 * u(rng)};
    const LD d = arc_ref::ellipse_distance(a, b, p.x, p.z);
    if (d < 2 * tol) continue;
    const bool inside = p.x * p.x / (a * a) + p.z * p.z / (b * b) <= 1.0;
    ASSERT_EQ(e->contains(p), inside) << p.x << " " << p.z;
    ++checked;
  }
  EXPECT_GT(checked, 190000);
  EXPECT_TRUE(e->contains({0.0, 0.0}));
}

TEST(Ellipse, CutCellsHoldEveryInvariantOnRandomPlacements) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 800; ++trial) {
    const double h = 0.01 + 0.2 * u(rng);
    const double b = h * (0.3 + 6.0 * u(rng));
    const double a = b * (trial % 4 == 0 ? 1.0 + 9.0 * u(rng) : 1.0 + 3.0 * u(rng));
    const auto shape = trial % 2 ? make_ellipse(a, b) : make_ellipse(b, a);
    const auto ref = arc_ref::moments(shape->boundary());
    const Vec2 origin{-1.0 + 2.0 * u(rng), -1.0 + 2.0 * u(rng)};
    const SolidPlacement s{trial, shape, {{4.0 * u(rng), 3.0 * u(rng)}, 6.0 * u(rng)}};
    const auto w = window_around(bounding_box(*s.shape, s.pose), origin, h, 2);
    const CutCells cc = build_cut_cells(w, {s}, {}, keep_all());
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_invariants(cc, s, static_cast<double>(ref.perimeter), 1e-12);
    // wetted area against the independent quadrature of the spline
    const double area = static_cast<double>(ref.area);
    EXPECT_NEAR(totals(cc).area, area, 1e-12 * area);
    if (HasFailure()) return;
  }
}

TEST(Ellipse, CaseKeysBuildItAndBadValuesNameTheKey) {
  picdem::core::ParamSchema schema;
  const ShapeType& type = shape_type("ellipse");
  type.declare(schema.family("solids", "solids").variant("ellipse", type.doc));
  auto read = [&](const std::string& body) {
    return picdem::core::read_case_text("solids:\n  e:\n    type: ellipse\n" + body, "case.yaml",
                                        {}, schema)
        .sub("solids/e");
  };
  const auto placed =
      type.build(read("    a: 0.2\n    b: 0.05\n    center: [1, 2]\n    theta: 0.5\n"), {});
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_EQ(placed[0].shape->kind(), "ellipse");
  EXPECT_EQ(placed[0].pose.x.x, 1.0);
  EXPECT_EQ(placed[0].pose.x.z, 2.0);
  EXPECT_EQ(placed[0].pose.theta, 0.5);
  // within tol x perimeter of pi a b (the perimeter is below 1 m)
  EXPECT_NEAR(placed[0].shape->mass_properties().area, M_PI * 0.2 * 0.05, 1e-4 * 0.05 * 1.0);
  try {
    type.build(read("    a: 0.5\n    b: 0.01\n    center: [1, 2]\n"), {});
    FAIL() << "an aspect ratio of 50 was accepted";
  } catch (const picdem::core::InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("solids/e/a"), std::string::npos) << m;
    EXPECT_NE(m.find("aspect ratio 50"), std::string::npos) << m;
    EXPECT_NE(m.find("<= 10"), std::string::npos) << m;
  }
  EXPECT_THROW(read("    a: 0\n    b: 0.01\n    center: [1, 2]\n"), picdem::core::InputError);
  EXPECT_THROW(make_ellipse(0.1, -1.0), picdem::core::InputError);
  EXPECT_THROW(make_ellipse(NAN, 1.0), picdem::core::InputError);
}
