// Advection: measured order of convergence on a rigid rotation (the bilinear interpolation of
// the linear rotation field is exact, so the error is the time integrator's): RK2 >= 1.9,
// RK3 >= 2.9; particles that would leave the tank are put back 1e-6 h inside the wall; the
// push-out callback is applied.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "particle_testing.hpp"
#include "picdem/particles/particles.hpp"

using namespace picdem;
using namespace picdem::particles;
using grid::FaceField;
using grid::Stagger;

namespace {

grid::GridSpec unit_tank(int n) {
  grid::GridSpec s;
  s.nx = n, s.nz = n, s.h = 1.0 / n, s.origin = {0.0, 0.0};
  return s;
}

// rigid rotation about c with angular velocity omega: v = omega x (x - c)
constexpr double kOmega = 1.3;
constexpr core::Vec2 kCentre{0.5, 0.5};

struct Fields {
  FaceField u, w;
};

Fields rotation(const grid::Decomposition& d) {
  Fields f{FaceField(d, Stagger::FaceX), FaceField(d, Stagger::FaceZ)};
  const grid::GridSpec& s = d.spec();
  for (auto* g : {&f.u, &f.w}) {
    const core::IndexBox b = g->storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) {
        const core::Vec2 v = core::cross(kOmega, s.position(g->stagger(), i, k) - kCentre);
        (*g)(i, k) = g == &f.u ? v.x : v.z;
      }
  }
  return f;
}

/// Max position error after rotating for time T in `steps` steps.
double rotation_error(AdvectionScheme scheme, int steps) {
  const grid::GridSpec s = unit_tank(32);
  ParticleConfig c;
  c.advection = scheme;
  grid::Decomposition d(s, ptest::self_comm(), required_halo(c));
  const Fields f = rotation(d);
  ParticleSet p = seed(d, c, [](core::Vec2 x) { return norm(x - kCentre) < 0.3; });
  const ParticleSet start = p;
  const double T = 1.0, dt = T / steps;
  for (int n = 0; n < steps; ++n) advect(p, c, f.u, f.w, s, dt);
  double err = 0.0;
  for (std::size_t n = 0; n < p.size(); ++n) {
    const core::Vec2 exact =
        kCentre + rotate(core::Vec2{start.x[n], start.z[n]} - kCentre, kOmega * T);
    err = std::max(err, norm(core::Vec2{p.x[n], p.z[n]} - exact));
  }
  return err;
}

}  // namespace

TEST(Advect, SecondAndThirdOrderOnRigidRotation) {
  for (AdvectionScheme scheme : {AdvectionScheme::Rk2, AdvectionScheme::Rk3}) {
    const bool rk3 = scheme == AdvectionScheme::Rk3;
    double previous = rotation_error(scheme, 8), worst_order = 10.0;
    for (int steps = 16; steps <= 64; steps *= 2) {
      const double e = rotation_error(scheme, steps);
      const double order = std::log2(previous / e);
      std::printf("%s steps %3d error %.3e order %.3f\n", rk3 ? "rk3" : "rk2", steps, e, order);
      worst_order = std::min(worst_order, order);
      previous = e;
    }
    EXPECT_GE(worst_order, rk3 ? 2.9 : 1.9);
  }
}

TEST(Advect, KeepsParticlesInsideTheTankAndPushesOut) {
  const grid::GridSpec s = unit_tank(16);
  ParticleConfig c;
  grid::Decomposition d(s, ptest::self_comm(), required_halo(c));
  FaceField u(d, Stagger::FaceX, 1.0), w(d, Stagger::FaceZ, -0.5);
  ParticleSet p;
  const double zero[4] = {0.0, 0.0, 0.0, 0.0};
  p.push_back(0, {0.99, 0.5}, {0.0, 0.0}, zero);  // leaves through the right wall
  p.push_back(1, {0.5, 0.01}, {0.0, 0.0}, zero);  // leaves through the floor
  p.push_back(2, {0.5, 0.5}, {0.0, 0.0}, zero);   // stays inside
  const double dt = 0.08;                         // |v| dt < 2 h
  advect(p, c, u, w, s, dt);
  const double gap = 1e-6 * s.h;
  EXPECT_NEAR(p.x[0], 1.0 - gap, 1e-15);
  EXPECT_NEAR(p.z[0], 0.5 - 0.5 * dt, 1e-15);
  EXPECT_NEAR(p.x[1], 0.5 + dt, 1e-15);
  EXPECT_NEAR(p.z[1], gap, 1e-15);
  EXPECT_NEAR(p.x[2], 0.5 + dt, 1e-15);
  EXPECT_NEAR(p.z[2], 0.5 - 0.5 * dt, 1e-15);
  // a solid occupying x > 0.55 pushes particles back to its surface; the wall clamp still holds
  advect(p, c, u, w, s, dt, [](double& x, double&) { x = std::min(x, 0.55); });
  EXPECT_NEAR(p.x[2], 0.55, 1e-15);
  EXPECT_NEAR(p.x[0], 0.55, 1e-15);
  EXPECT_GE(p.z[1], gap);
}
