// The rounded polygon (geometry/src/rounded_polygon.cpp): the polygon of its arc centres grown by
// r, so Steiner's formula gives its area A_inner + r P_inner + pi r^2 and its perimeter
// P_inner + 2 pi r independently of the shape's code; its mass properties against a quadrature of
// its boundary, its cut cells on random placements, and its case-file keys.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "arc_spline_reference.hpp"
#include "cut_cell_checks.hpp"
#include "picdem/core/error.hpp"
#include "picdem/geometry/outline.hpp"
#include "picdem/geometry/polygon.hpp"
#include "picdem/geometry/shape_registry.hpp"

using namespace picdem::geometry;
using namespace cut_cell_checks;

namespace {

struct Case {
  std::vector<Vec2> sharp;  // the sharp corners
  double r;
  double inner_area, inner_perimeter;  // of the polygon of the arc centres
};

/// A random convex polygon (n corners on a circle of radius R) and a radius that fits. The
/// polygon of the arc centres is the sharp polygon moved in by r: its edges are the sharp edges
/// shortened by the tangent lengths, computed here from the corner angles.
Case random_case(std::mt19937_64& rng, double R) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 3 + static_cast<int>(6 * u(rng));
  Case c;
  for (int j = 0; j < n; ++j) {
    const double phi = 2.0 * M_PI * (j + 0.7 * u(rng)) / n;
    c.sharp.push_back({R * std::cos(phi), R * std::sin(phi)});
  }
  // inradius-like bound: r below a fraction of the shortest edge times the sharpest corner
  double shortest = INFINITY;
  for (int j = 0; j < n; ++j)
    shortest = std::min(shortest, picdem::core::norm(c.sharp[(j + 1) % n] - c.sharp[j]));
  c.r = 0.05 * shortest * (0.2 + 0.8 * u(rng));
  // centres: the intersection of the edges' lines moved in by r
  std::vector<Vec2> centres;
  for (int j = 0; j < n; ++j) {
    const Vec2 a = c.sharp[(j + n - 1) % n], v = c.sharp[j], b = c.sharp[(j + 1) % n];
    const Vec2 e1 = (v - a) / picdem::core::norm(v - a), e2 = (b - v) / picdem::core::norm(b - v);
    const Vec2 p1 = a + c.r * Vec2{-e1.z, e1.x}, p2 = v + c.r * Vec2{-e2.z, e2.x};
    // p1 + s e1 = p2 + u e2
    const double s = picdem::core::cross(p2 - p1, e2) / picdem::core::cross(e1, e2);
    centres.push_back(p1 + s * e1);
  }
  const PolygonProperties ip = polygon_properties(centres);
  c.inner_area = ip.area;
  c.inner_perimeter = 0.0;
  for (int j = 0; j < n; ++j)
    c.inner_perimeter += picdem::core::norm(centres[(j + 1) % n] - centres[j]);
  return c;
}

}  // namespace

TEST(RoundedPolygon, AreaAndPerimeterAreSteinersAndMomentsTheQuadratures) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Case c = random_case(rng, 0.1 + u(rng));
    Vec2 centroid;
    const auto shape = make_rounded_polygon(c.sharp, c.r, &centroid);
    const auto ref = arc_ref::moments(shape->boundary());
    const double A = c.inner_area + c.r * c.inner_perimeter + M_PI * c.r * c.r;
    const auto mp = shape->mass_properties();
    SCOPED_TRACE("trial " + std::to_string(trial));
    EXPECT_NEAR(mp.area, A, 1e-13 * A);
    EXPECT_NEAR(static_cast<double>(ref.area), A, 1e-13 * A);
    EXPECT_NEAR(static_cast<double>(ref.perimeter), c.inner_perimeter + 2 * M_PI * c.r, 1e-13 * A);
    // body frame: centroid at the origin
    EXPECT_NEAR(static_cast<double>(ref.sx / ref.area), 0.0, 1e-14);
    EXPECT_NEAR(static_cast<double>(ref.sz / ref.area), 0.0, 1e-14);
    EXPECT_NEAR(mp.polar_moment, static_cast<double>(ref.j_o), 1e-13 * mp.polar_moment);
    EXPECT_TRUE(shape->contains({0.0, 0.0}));
    EXPECT_FALSE(shape->contains(c.sharp[0] - centroid));  // a sharp corner is cut off
  }
}

TEST(RoundedPolygon, CutCellsHoldEveryInvariantOnRandomPlacements) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 600; ++trial) {
    const double h = 0.01 + 0.2 * u(rng);
    const Case c = random_case(rng, h * (0.5 + 8.0 * u(rng)));
    const auto shape = make_rounded_polygon(c.sharp, c.r, nullptr);
    const double A = c.inner_area + c.r * c.inner_perimeter + M_PI * c.r * c.r;
    const Vec2 origin{-1.0 + 2.0 * u(rng), -1.0 + 2.0 * u(rng)};
    const SolidPlacement s{trial, shape, {{4.0 * u(rng), 3.0 * u(rng)}, 6.0 * u(rng)}};
    const auto w = window_around(bounding_box(*s.shape, s.pose), origin, h, 2);
    const CutCells cc = build_cut_cells(w, {s}, {}, keep_all());
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_invariants(cc, s, c.inner_perimeter + 2 * M_PI * c.r, 1e-12);
    EXPECT_NEAR(totals(cc).area, A, 1e-12 * A);
    if (HasFailure()) return;
  }
}

TEST(RoundedPolygon, CaseKeysBuildItAndBadValuesNameTheKey) {
  picdem::core::ParamSchema schema;
  const ShapeType& type = shape_type("rounded_polygon");
  type.declare(schema.family("solids", "solids").variant("rounded_polygon", type.doc));
  auto read = [&](const std::string& body) {
    return picdem::core::read_case_text("solids:\n  p:\n    type: rounded_polygon\n" + body,
                                        "case.yaml", {}, schema)
        .sub("solids/p");
  };
  // a 2 x 1 rectangle with corners of radius 0.1 at (1, 2)..(3, 3): centroid (2, 2.5)
  const auto placed =
      type.build(read("    vertices: [1, 2, 3, 2, 3, 3, 1, 3]\n    radius: 0.1\n"), {});
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_EQ(placed[0].shape->kind(), "rounded_polygon");
  EXPECT_NEAR(placed[0].pose.x.x, 2.0, 1e-14);
  EXPECT_NEAR(placed[0].pose.x.z, 2.5, 1e-14);
  // 2 - (4 - pi) r^2
  EXPECT_NEAR(placed[0].shape->mass_properties().area, 2.0 - (4.0 - M_PI) * 0.01, 1e-14);
  EXPECT_EQ(placed[0].shape->boundary().size(), 8u);
  try {
    type.build(read("    vertices: [1, 2, 3, 2, 3, 3, 1, 3]\n    radius: 0.6\n"), {});
    FAIL() << "a radius of 0.6 on an edge of length 1 was accepted";
  } catch (const picdem::core::InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("solids/p/radius"), std::string::npos) << m;
    EXPECT_NE(m.find("radius below 0.5"), std::string::npos) << m;
  }
  // a non-convex (L-shaped) polygon
  EXPECT_THROW(make_rounded_polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 0.1, nullptr),
               picdem::core::InputError);
  EXPECT_THROW(make_rounded_polygon({{0, 0}, {1, 0}, {0, 1}}, 0.0, nullptr),
               picdem::core::InputError);
}
