// coupling::viscous_bodies: a solid's inside test at its pose, its rigid velocity
// V + omega x (x - x_c) and area; an obstacle's even-odd inside test (two polygons) at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "picdem/geometry/circle.hpp"
#include "viscous_bodies.hpp"

using namespace picdem;
using core::Vec2;

TEST(ViscousBodies, SolidAndObstacle) {
  coupling::SolidScene scene;
  geometry::SolidPlacement pl;
  pl.id = 4;
  pl.shape = std::make_shared<geometry::Circle>(0.1);
  pl.pose = {{0.5, 0.3}, 0.7};
  scene.placements.push_back(pl);
  core::SolidState st;
  st.x = pl.pose.x, st.theta = 0.7, st.v = {0.2, -0.1}, st.omega = 3.0;
  scene.states.push_back(st);
  geometry::Obstacle o;
  o.name = "steps";
  o.polygons = {{{0.0, 0.0}, {0.2, 0.0}, {0.2, 0.1}, {0.0, 0.1}},
                {{0.8, 0.0}, {1.0, 0.0}, {1.0, 0.4}, {0.8, 0.4}}};
  scene.obstacles.push_back(o);
  const auto bodies = coupling::viscous_bodies(scene);
  ASSERT_EQ(bodies.size(), 2u);
  EXPECT_TRUE(bodies[0].inside({0.59, 0.3}));
  EXPECT_FALSE(bodies[0].inside({0.61, 0.3}));
  EXPECT_NEAR(bodies[0].area, M_PI * 0.01, 1e-14);
  const Vec2 v = bodies[0].velocity_at({0.6, 0.3});  // 0.1 right of the centre
  EXPECT_NEAR(v.x, 0.2, 1e-14);
  EXPECT_NEAR(v.z, -0.1 + 3.0 * 0.1, 1e-14);
  EXPECT_TRUE(bodies[1].inside({0.1, 0.05}));
  EXPECT_TRUE(bodies[1].inside({0.9, 0.35}));
  EXPECT_FALSE(bodies[1].inside({0.5, 0.05}));
  EXPECT_FALSE(bodies[1].inside({0.1, 0.15}));
  EXPECT_EQ(bodies[1].omega, 0.0);
  EXPECT_EQ(bodies[1].velocity_at({0.9, 0.1}).x, 0.0);
}
