// fluid::viscous_bodies: a solid's inside test at its pose, its rigid velocity
// V + omega x (x - x_c) and area; an obstacle's even-odd inside test (two polygons) at rest.
// fluid::viscous_exchange, fluid::plus_viscous: the loads by solid id from their owners.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "picdem/fluid/viscous_bodies.hpp"
#include "picdem/geometry/circle.hpp"

using namespace picdem;
using core::Vec2;

TEST(ViscousBodies, SolidAndObstacle) {
  std::vector<geometry::SolidPlacement> placements;
  std::vector<core::SolidState> states;
  std::vector<geometry::Obstacle> obstacles;
  geometry::SolidPlacement pl;
  pl.id = 4;
  pl.shape = std::make_shared<geometry::Circle>(0.1);
  pl.pose = {{0.5, 0.3}, 0.7};
  placements.push_back(pl);
  core::SolidState st;
  st.x = pl.pose.x, st.theta = 0.7, st.v = {0.2, -0.1}, st.omega = 3.0;
  states.push_back(st);
  geometry::Obstacle o;
  o.name = "steps";
  o.polygons = {{{0.0, 0.0}, {0.2, 0.0}, {0.2, 0.1}, {0.0, 0.1}},
                {{0.8, 0.0}, {1.0, 0.0}, {1.0, 0.4}, {0.8, 0.4}}};
  obstacles.push_back(o);
  const auto bodies = fluid::viscous_bodies(placements, states, obstacles);
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

// The loads of the bodies (solids 0, 2, 5, then one obstacle) by solid id: each solid's from its
// owner only (this rank owns 2 and 5), zero rows up to the largest id; the obstacle's as given.
// plus_viscous adds them to the loads of the owned solids, one entry per solid, ordered by id.
TEST(ViscousBodies, LoadsByIdFromTheOwners) {
  auto st = [](std::int64_t id) {
    core::SolidState s;
    s.id = id;
    return s;
  };
  const std::vector<core::SolidState> all = {st(0), st(2), st(5)}, owned = {st(5), st(2)};
  fluid::ViscousLoads loads;
  loads.force = {{1.0, 2.0}, {3.0, 4.0}, {5.0, 6.0}, {7.0, 8.0}};
  loads.torque = {0.1, 0.2, 0.3, 0.4};
  const fluid::ViscousExchange ex = fluid::viscous_exchange(all, 1, loads, owned, core::Comm());
  ASSERT_EQ(ex.solids.size(), 6u);  // ids 0..5
  for (std::size_t id = 0; id < 6; ++id) EXPECT_EQ(ex.solids[id].id, static_cast<int>(id));
  EXPECT_EQ(ex.solids[0].force.x, 0.0);  // not owned here: its owner reports it
  EXPECT_EQ(ex.solids[2].force.x, 3.0);
  EXPECT_EQ(ex.solids[2].force.z, 4.0);
  EXPECT_EQ(ex.solids[2].torque, 0.2);
  EXPECT_EQ(ex.solids[5].force.z, 6.0);
  EXPECT_EQ(ex.solids[5].torque, 0.3);
  ASSERT_EQ(ex.obstacles.size(), 1u);
  EXPECT_EQ(ex.obstacles[0].force.x, 7.0);
  EXPECT_EQ(ex.obstacles[0].torque, 0.4);
  // a count that does not match the bodies (zero viscosity computes none): no loads
  EXPECT_TRUE(fluid::viscous_exchange(all, 0, loads, owned, core::Comm()).solids.empty());

  const std::vector<core::SolidLoads> pressure = {{5, {10.0, 20.0}, 1.0}};
  const auto sum = fluid::plus_viscous(pressure, ex, owned);
  ASSERT_EQ(sum.size(), 2u);
  EXPECT_EQ(sum[0].id, 2);
  EXPECT_EQ(sum[0].force.x, 3.0);
  EXPECT_EQ(sum[0].torque, 0.2);
  EXPECT_EQ(sum[1].id, 5);
  EXPECT_EQ(sum[1].force.x, 15.0);
  EXPECT_EQ(sum[1].force.z, 26.0);
  EXPECT_EQ(sum[1].torque, 1.3);
}
