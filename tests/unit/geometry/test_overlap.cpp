// Overlap depth (overlap.hpp) against depths computed by hand: squares, a square and a circle
// (edge and corner), a triangle's tip, a rounded square, a circle inside a square, apart and
// touching outlines, and a circle in the notch of an L-shaped polygon (convex partition).
#include <gtest/gtest.h>

#include <cmath>

#include "picdem/geometry/overlap.hpp"
#include "picdem/geometry/shape_registry.hpp"

using namespace picdem::geometry;

namespace {

std::vector<BoundaryPiece> box(double x0, double z0, double x1, double z1) {
  return polygon_loop({{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}});
}

std::vector<BoundaryPiece> circle(Vec2 c, double r, double phi0 = 0.3) {
  return {Arc{c, r, phi0, phi0 + 2.0 * M_PI}};
}

// A circle as four quarter arcs starting at an odd angle (breaks inside the circle's normals).
std::vector<BoundaryPiece> circle_quarters(Vec2 c, double r) {
  std::vector<BoundaryPiece> loop;
  for (int k = 0; k < 4; ++k) {
    const double phi0 = 0.1 + k * M_PI / 2;
    loop.emplace_back(Arc{c, r, phi0, phi0 + M_PI / 2});
  }
  return loop;
}

}  // namespace

constexpr double tol = 1e-14;

TEST(OverlapDepth, Squares) {
  // x overlap 1 - 0.8 = 0.2, z overlap 0.8: the shortest way out is 0.2 along x.
  EXPECT_NEAR(convex_penetration_depth(box(0, 0, 1, 1), box(0.8, 0.1, 1.8, 0.9)), 0.2, tol);
  EXPECT_NEAR(convex_penetration_depth(box(0.8, 0.1, 1.8, 0.9), box(0, 0, 1, 1)), 0.2, tol);
  // 0.3 apart along x: minus the distance.
  EXPECT_NEAR(convex_penetration_depth(box(0, 0, 1, 1), box(1.3, 0.2, 2, 0.5)), -0.3, tol);
  // Touching along an edge.
  EXPECT_NEAR(convex_penetration_depth(box(0, 0, 1, 1), box(1, 0.2, 2, 0.5)), 0.0, tol);
}

TEST(OverlapDepth, SquareAndCircle) {
  // Centre (1.3, 0.5) is 0.3 from the right edge: 0.5 - 0.3 = 0.2.
  EXPECT_NEAR(convex_penetration_depth(box(0, 0, 1, 1), circle({1.3, 0.5}, 0.5)), 0.2, tol);
  // Centre (1.2, 1.2) is 0.2 sqrt(2) from the corner (1, 1): 0.5 - 0.2 sqrt(2).
  const double corner = 0.5 - 0.2 * std::sqrt(2.0);
  EXPECT_NEAR(convex_penetration_depth(box(0, 0, 1, 1), circle({1.2, 1.2}, 0.5)), corner, tol);
  EXPECT_NEAR(convex_penetration_depth(circle_quarters({1.2, 1.2}, 0.5), box(0, 0, 1, 1)), corner,
              tol);
  // Centre inside, 0.1 from the top edge, r = 0.05: moved up by 0.1 + 0.05.
  EXPECT_NEAR(convex_penetration_depth(box(0, 0, 1, 1), circle({0.5, 0.9}, 0.05)), 0.15, tol);
  // Two circles: r_a + r_b - d.
  EXPECT_NEAR(convex_penetration_depth(circle({0, 0}, 0.5), circle_quarters({0.6, 0.8}, 0.3)),
              0.5 + 0.3 - 1.0, tol);
}

TEST(OverlapDepth, TriangleTip) {
  // The tip (0.5, 0.9) is 0.1 below the square's top; every other axis separates by more
  // (the triangle's slanted edges: 0.4373, computed by hand from their normals).
  const auto triangle = polygon_loop({{0.5, 0.9}, {1.5, 2.0}, {-0.5, 2.0}});
  EXPECT_NEAR(convex_penetration_depth(box(0, 0, 1, 1), triangle), 0.1, tol);
  EXPECT_NEAR(convex_penetration_depth(triangle, box(0, 0, 1, 1)), 0.1, tol);
}

TEST(OverlapDepth, RoundedSquare) {
  // The square [-0.5, 0.5]^2 with corners rounded by r = 0.1: the corner arc's centre (0.4, 0.4)
  // is 0.2 sqrt(2) from a circle's centre (0.6, 0.6), radius 0.2, on the diagonal: depth
  // 0.1 + 0.2 - 0.2 sqrt(2) = 0.0172 (along x it would be 0.5 - 0.4 = 0.1).
  Vec2 centroid;
  const auto shape =
      make_rounded_polygon({{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}, 0.1, &centroid);
  const auto loop = shape->boundary();
  ASSERT_TRUE(is_convex_loop(loop));
  EXPECT_NEAR(convex_penetration_depth(loop, circle({0.6, 0.6}, 0.2)), 0.3 - 0.2 * std::sqrt(2.0),
              1e-13);
  // Against a wall at x = 0.45: the flat side reaches x = 0.5, 0.05 deep.
  EXPECT_NEAR(convex_penetration_depth(loop, box(0.45, -2, 3, 2)), 0.05, 1e-13);
}

TEST(OverlapDepth, Convexity) {
  EXPECT_TRUE(is_convex_loop(box(0, 0, 1, 1)));
  EXPECT_TRUE(is_convex_loop(circle({0, 0}, 1)));
  EXPECT_FALSE(is_convex_loop(polygon_loop({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})));
}

TEST(OverlapDepth, NonConvexPolygonByPartition) {
  // An L: [0, 2] x [0, 1] and [0, 1] x [1, 2]. A circle of r = 0.3 centred at (1.5, 1.5), in the
  // notch, is 0.5 from both arms (the inner corner is 0.5 sqrt(2) away): apart by 0.2.
  const std::vector<Vec2> l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  std::vector<std::vector<BoundaryPiece>> pieces;
  for (const auto& p : convex_partition(l)) {
    pieces.push_back(polygon_loop(p));
    EXPECT_TRUE(is_convex_loop(pieces.back()));
  }
  EXPECT_GE(pieces.size(), 2u);
  EXPECT_NEAR(overlap_depth(pieces, {circle({1.5, 1.5}, 0.3)}), -0.2, 1e-13);
  // Moved to (1.5, 1.2): 0.2 above the lower arm's top, r = 0.3: 0.1 deep.
  EXPECT_NEAR(overlap_depth(pieces, {circle({1.5, 1.2}, 0.3)}), 0.1, 1e-13);
  // The same circle against the bounding box would be 0.8 deep: the notch is not solid.
  EXPECT_NEAR(convex_penetration_depth(box(0, 0, 2, 2), circle({1.5, 1.2}, 0.3)), 0.8, 1e-13);
}
