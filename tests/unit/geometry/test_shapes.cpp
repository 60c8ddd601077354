// Shapes: validation of polygons, mass properties against closed forms, the vertex-file polygon
// (the worked example of doc/shapes.md), outlines and bounding boxes.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "picdem/core/error.hpp"
#include "picdem/geometry/circle.hpp"
#include "picdem/geometry/outline.hpp"
#include "picdem/geometry/polygon.hpp"

using namespace picdem::geometry;
using picdem::core::InputError;

namespace {
std::string error_of(const std::vector<Vec2>& v) {
  try {
    Polygon p(v);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Circle, MassPropertiesAndBoundary) {
  const Circle c(0.3);
  EXPECT_DOUBLE_EQ(c.mass_properties().area, M_PI * 0.09);
  EXPECT_DOUBLE_EQ(c.mass_properties().polar_moment, 0.5 * M_PI * 0.0081);
  ASSERT_EQ(c.boundary().size(), 1u);
  EXPECT_TRUE(c.contains({0.3, 0.0}));
  EXPECT_FALSE(c.contains({0.3, 0.01}));
  EXPECT_THROW(Circle(0.0), InputError);
  EXPECT_THROW(Circle(-1.0), InputError);
}

TEST(Polygon, RectangleIsRecentredWithClosedFormProperties) {
  // a 4 x 2 rectangle with its lower left corner at (1, 1)
  const Polygon p({{1, 1}, {5, 1}, {5, 3}, {1, 3}});
  EXPECT_DOUBLE_EQ(p.centroid_offset().x, 3.0);
  EXPECT_DOUBLE_EQ(p.centroid_offset().z, 2.0);
  EXPECT_DOUBLE_EQ(p.vertices()[0].x, -2.0);
  EXPECT_DOUBLE_EQ(p.vertices()[0].z, -1.0);
  EXPECT_NEAR(p.mass_properties().area, 8.0, 1e-14);
  // J = A (a^2 + b^2) / 12
  EXPECT_NEAR(p.mass_properties().polar_moment, 8.0 * (16.0 + 4.0) / 12.0, 1e-13);
  EXPECT_DOUBLE_EQ(p.bounding_radius(), std::sqrt(5.0));
  EXPECT_TRUE(p.contains({2.0, 1.0}));  // a corner: inside or on
  EXPECT_FALSE(p.contains({2.0, 1.0 + 1e-15}));
}

TEST(Polygon, RegularPolygonApproachesTheDisc) {
  std::vector<Vec2> v;
  const int n = 4096;
  for (int j = 0; j < n; ++j) v.push_back({std::cos(2 * M_PI * j / n), std::sin(2 * M_PI * j / n)});
  const Polygon p(v);
  // regular n-gon of circumradius 1: A = n/2 sin(a), J = n/12 sin(a) (2 + cos(a)), a = 2 pi / n
  const double a = 2 * M_PI / n;
  EXPECT_NEAR(p.mass_properties().area, 0.5 * n * std::sin(a), 1e-12);
  EXPECT_NEAR(p.mass_properties().polar_moment, n / 12.0 * std::sin(a) * (2 + std::cos(a)), 1e-12);
  EXPECT_NEAR(p.mass_properties().polar_moment, M_PI / 2, 2e-6);
}

TEST(Polygon, InvalidInputIsRejectedWithAClearMessage) {
  EXPECT_NE(error_of({{0, 0}, {1, 0}}).find("at least 3 vertices"), std::string::npos);
  EXPECT_NE(error_of({{0, 0}, {1, 1}, {1, 0}, {0, 1}}).find("self-intersecting"),
            std::string::npos);
  EXPECT_NE(error_of({{0, 0}, {0, 1}, {1, 1}, {1, 0}}).find("clockwise"), std::string::npos);
  EXPECT_NE(error_of({{0, 0}, {1, 0}, {1, 0}, {0, 1}}).find("repeats vertex"), std::string::npos);
  // collinear: zero area, not simple
  EXPECT_NE(error_of({{0, 0}, {1, 0}, {2, 0}}), "");
  // a vertex touching another edge exactly (decided by exact predicates)
  EXPECT_NE(error_of({{0, 0}, {2, 0}, {2, 2}, {1, 0}, {0, 2}}), "");
  EXPECT_EQ(error_of({{0, 0}, {2, 0}, {2, 2}, {1, 1e-300}, {0, 2}}), "");
}

TEST(Polygon, FromVertexFile) {
  const std::string path = "test_polygon_vertices.txt";
  {
    std::ofstream f(path);
    f << "# an L-shaped block, counter-clockwise\n0 0\n2, 0\n2 1\n\n1 1   # inner corner\n1 2\n0 "
         "2\n";
  }
  const Polygon p = Polygon::from_file(path);
  ASSERT_EQ(p.vertices().size(), 6u);
  EXPECT_NEAR(p.mass_properties().area, 3.0, 1e-14);
  // centroid of the L: (2 * (1, 0.5) + 1 * (0.5, 1.5)) / 3
  EXPECT_NEAR(p.centroid_offset().x, 2.5 / 3.0, 1e-14);
  EXPECT_NEAR(p.centroid_offset().z, 2.5 / 3.0, 1e-14);
  // J about the centroid: sum of the two rectangles' J about their centres + parallel axis
  const Vec2 c{2.5 / 3, 2.5 / 3};
  const double J = 2.0 * (4.0 + 1.0) / 12.0 + 2.0 * picdem::core::norm2(Vec2{1.0, 0.5} - c) +
                   1.0 * (1.0 + 1.0) / 12.0 + 1.0 * picdem::core::norm2(Vec2{0.5, 1.5} - c);
  EXPECT_NEAR(p.mass_properties().polar_moment, J, 1e-13);
  {
    std::ofstream f(path);
    f << "0 0\n1 0\n1 x\n";
  }
  try {
    Polygon::from_file(path);
    FAIL() << "bad line accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
  EXPECT_THROW(Polygon::from_file("no_such_file.txt"), InputError);
}

TEST(Outline, ClosedAndWithinChord) {
  const Circle c(2.0);
  const auto line = outline(c, {{1.0, -1.0}, 0.4}, 0.1);
  ASSERT_GT(line.size(), 100u);
  EXPECT_EQ(line.front(), line.back());
  for (std::size_t j = 0; j + 1 < line.size(); ++j) {
    EXPECT_LE(picdem::core::norm(line[j + 1] - line[j]), 0.1 + 1e-12);
    EXPECT_NEAR(picdem::core::norm(line[j] - Vec2{1.0, -1.0}), 2.0, 1e-12);
  }
  const Polygon sq({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const auto l2 = outline(sq, {{0, 0}, M_PI / 2}, 0.1);
  ASSERT_EQ(l2.size(), 5u);
  EXPECT_NEAR(l2[0].x, 0.5, 1e-15);
  EXPECT_NEAR(l2[0].z, -0.5, 1e-15);
  EXPECT_THROW(outline(sq, {}, 0.0), InputError);
}

TEST(Outline, BoundingBox) {
  const Circle c(2.0);
  const auto b = bounding_box(c, {{1.0, -1.0}, 0.7});
  EXPECT_NEAR(b.lo.x, -1.0, 1e-14);
  EXPECT_NEAR(b.hi.x, 3.0, 1e-14);
  EXPECT_NEAR(b.lo.z, -3.0, 1e-14);
  EXPECT_NEAR(b.hi.z, 1.0, 1e-14);
  // a disk turned 1e12 times and by +-1e20 rad (its arc lost its span to round-off and the
  // quarter-turn count overflowed int: the box was wrong or never returned): the same box
  for (double angle : {2e12 * M_PI + 0.3, 1e20, -1e20}) {
    const auto t = bounding_box(c, {{1.0, -1.0}, angle});
    EXPECT_NEAR(t.lo.x, -1.0, 1e-14) << angle;
    EXPECT_NEAR(t.hi.x, 3.0, 1e-14) << angle;
    EXPECT_NEAR(t.lo.z, -3.0, 1e-14) << angle;
    EXPECT_NEAR(t.hi.z, 1.0, 1e-14) << angle;
  }
  // an angle no longer finite: an empty box (lo above hi), returned
  for (double angle : {double(INFINITY), double(NAN)}) {
    const auto t = bounding_box(c, {{1.0, -1.0}, angle});
    EXPECT_FALSE(t.lo.x <= t.hi.x) << angle;
  }
  const Polygon sq({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
  const auto bs = bounding_box(sq, {{0, 0}, M_PI / 4});
  EXPECT_NEAR(bs.hi.x, std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(bs.lo.z, -std::sqrt(2.0), 1e-14);
}
