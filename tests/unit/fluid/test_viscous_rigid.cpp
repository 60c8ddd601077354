// Rigid rows of the implicit viscous step (fluid::solve_viscous_rigid_rows, doc/viscous.md): a
// free disk moving and rotating in a closed no-slip box of fluid.
// - the disk's equation M (s - s^n) / dt = F(u_new, s) holds and the fluid's momentum gain is
//   minus the loads on the disk and the walls, both to the solver tolerance;
// - a light disk (density 10 in water, dt = 0.05 s, nu = 1e-2) slows without reversing, where
//   the split (the fluid solved with the disk at s^n, then the disk given that load) reverses;
// - rotation_only: the translation kept, the spin solved with the fluid, the exchange exact.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "picdem/core/rng.hpp"
#include "picdem/fluid/viscous.hpp"
#include "picdem/geometry/circle.hpp"

using namespace picdem;
using core::Vec2;
using fluid::ViscousBody;

namespace {

struct Box {
  fluid::ViscousGrid g{{0.0, 0.0}, 0.05, 20, 16};
  std::vector<ViscousBody> bodies;
  fluid::ViscousStencil su, sw;
  std::vector<double> u, w;
  Box(double density, bool rough) {
    const double r = 0.17;
    auto disk = std::make_shared<geometry::Circle>(r);
    const geometry::Pose pose{{0.43, 0.37}, 0.0};
    const double area = M_PI * r * r, mass = density * area;
    bodies.push_back({[=](const Vec2& x) { return disk->contains(pose.to_body(x)); },
                      {0.3, -0.1},
                      2.0,
                      pose.x,
                      area,
                      mass,
                      0.5 * mass * r * r});
    su = fluid::build_viscous_stencil(0, g, bodies, {});
    sw = fluid::build_viscous_stencil(1, g, bodies, {});
    u.assign(su.unknown_of.size(), 0.0);
    w.assign(sw.unknown_of.size(), 0.0);
    if (rough) {
      for (int n : su.node_of) u[n] = 2.0 * core::uniform01(7, 0, n) - 1.0;
      for (int n : sw.node_of) w[n] = 2.0 * core::uniform01(7, 1, n) - 1.0;
    }
  }
  Vec2 momentum_rate(const std::vector<double>& u1, const std::vector<double>& w1, double rho,
                     double dt) const {
    Vec2 m;
    for (int n : su.node_of) m.x += rho * g.h * g.h * (u1[n] - u[n]) / dt;
    for (int n : sw.node_of) m.z += rho * g.h * g.h * (w1[n] - w[n]) / dt;
    return m;
  }
};

const double rho = 1000.0, nu = 1e-2, dt = 0.05;

}  // namespace

TEST(ViscousRigidRows, BodyEquationAndMomentumExchange) {
  const Box box(100.0, true);
  std::vector<double> u1 = box.u, w1 = box.w;
  std::vector<ViscousBody> bodies = box.bodies;
  int iterations = 0;
  const auto loads =
      fluid::solve_viscous_rigid_rows(box.su, box.sw, nu, rho, dt, u1, w1, bodies, iterations);
  const ViscousBody &before = box.bodies[0], &after = bodies[0];
  const Vec2 body_rate = (after.mass / dt) * (after.velocity - before.velocity);
  const double spin_rate = after.inertia * (after.omega - before.omega) / dt;
  const Vec2 gain = box.momentum_rate(u1, w1, rho, dt);
  const double scale = std::abs(loads.force[0].x) + std::abs(loads.force[0].z);
  std::printf(
      "rigid rows: V (%.6f, %.6f) -> (%.6f, %.6f) m/s, omega %.4f -> %.4f; body equation "
      "residual (%.2e, %.2e, %.2e), exchange residual (%.2e, %.2e) of %.3e N/m; %d CG "
      "iterations\n",
      before.velocity.x, before.velocity.z, after.velocity.x, after.velocity.z, before.omega,
      after.omega, body_rate.x - loads.force[0].x, body_rate.z - loads.force[0].z,
      spin_rate - loads.torque[0], gain.x + loads.force[0].x + loads.wall_force.x,
      gain.z + loads.force[0].z + loads.wall_force.z, scale, iterations);
  EXPECT_GT(scale, 1e-2);
  EXPECT_NEAR(body_rate.x, loads.force[0].x, 1e-8 * scale);
  EXPECT_NEAR(body_rate.z, loads.force[0].z, 1e-8 * scale);
  EXPECT_NEAR(spin_rate, loads.torque[0], 1e-8 * std::abs(loads.torque[0]) + 1e-12);
  EXPECT_NEAR(gain.x + loads.force[0].x + loads.wall_force.x, 0.0, 1e-8 * scale);
  EXPECT_NEAR(gain.z + loads.force[0].z + loads.wall_force.z, 0.0, 1e-8 * scale);
}

TEST(ViscousRigidRows, LightDiskSlowsWithoutReversing) {
  const Box box(10.0, false);  // fluid at rest, the disk moving and spinning
  const ViscousBody& before = box.bodies[0];
  // rigid rows
  std::vector<double> u1 = box.u, w1 = box.w;
  std::vector<ViscousBody> bodies = box.bodies;
  int iterations = 0;
  fluid::solve_viscous_rigid_rows(box.su, box.sw, nu, rho, dt, u1, w1, bodies, iterations);
  const ViscousBody& rows = bodies[0];
  // the split: the fluid with the disk at s^n, then the disk given that load
  std::vector<double> u2 = box.u, w2 = box.w;
  fluid::solve_viscous_implicit(box.su, nu, dt, std::vector<double>(u2.size(), 0.0), u2);
  fluid::solve_viscous_implicit(box.sw, nu, dt, std::vector<double>(w2.size(), 0.0), w2);
  const auto split = fluid::viscous_loads(box.su, box.sw, u2, w2, rho * nu, box.bodies);
  const Vec2 v_split = before.velocity + (dt / before.mass) * split.force[0];
  const double omega_split = before.omega + dt / before.inertia * split.torque[0];
  std::printf(
      "light disk (density 10), dt = %.2f s: V (%.3f, %.3f) m/s, omega %.3f rad/s -> rigid "
      "rows (%.5f, %.5f), %.5f; split (%.3f, %.3f), %.3f\n",
      dt, before.velocity.x, before.velocity.z, before.omega, rows.velocity.x, rows.velocity.z,
      rows.omega, v_split.x, v_split.z, omega_split);
  EXPECT_GT(rows.velocity.x, 0.0);
  EXPECT_LT(rows.velocity.x, before.velocity.x);
  EXPECT_LT(rows.velocity.z, 0.0);
  EXPECT_GT(rows.velocity.z, before.velocity.z);
  EXPECT_GT(rows.omega, 0.0);
  EXPECT_LT(rows.omega, before.omega);
  EXPECT_LT(v_split.x, 0.0);  // the split reverses the disk
}

TEST(ViscousRigidRows, RotationOnlyKeepsTheTranslationAndSolvesTheSpin) {
  // rotation_only (fluid/viscous_rotation_rows): omega alone is an unknown; the translation keeps
  // V^n (the split), the spin's equation I (omega - omega^n) / dt = T(u_new, s) holds, and the
  // fluid's momentum gain is still minus the loads on the disk and the walls.
  Box box(10.0, true);
  box.bodies[0].rotation_only = true;
  const ViscousBody before = box.bodies[0];
  std::vector<double> u1 = box.u, w1 = box.w;
  std::vector<ViscousBody> bodies = box.bodies;
  int iterations = 0;
  const auto loads =
      fluid::solve_viscous_rigid_rows(box.su, box.sw, nu, rho, dt, u1, w1, bodies, iterations);
  const ViscousBody& after = bodies[0];
  const double spin_rate = after.inertia * (after.omega - before.omega) / dt;
  const Vec2 gain = box.momentum_rate(u1, w1, rho, dt);
  const double scale = std::abs(loads.force[0].x) + std::abs(loads.force[0].z);
  std::printf("rotation only: omega %.4f -> %.4f rad/s, spin residual %.2e of %.3e N m/m\n",
              before.omega, after.omega, spin_rate - loads.torque[0], loads.torque[0]);
  EXPECT_EQ(after.velocity.x, before.velocity.x);
  EXPECT_EQ(after.velocity.z, before.velocity.z);
  EXPECT_GT(std::abs(loads.torque[0]), 1e-6);
  EXPECT_NEAR(spin_rate, loads.torque[0], 1e-8 * std::abs(loads.torque[0]) + 1e-12);
  // the light disk's spin slows without reversing (the split reverses it: the test above)
  EXPECT_GT(after.omega, 0.0);
  EXPECT_LT(after.omega, before.omega);
  EXPECT_NEAR(gain.x + loads.force[0].x + loads.wall_force.x, 0.0, 1e-8 * scale);
  EXPECT_NEAR(gain.z + loads.force[0].z + loads.wall_force.z, 0.0, 1e-8 * scale);
}
