// Coefficients (eqs. 10-13, 18) and normal collisions against the closed-form restitution of the
// linear spring-dashpot (closed forms in doc/dem.md), derived from the code's own k and
// c. The force is linear until the overlap returns to zero (tension allowed while delta > 0), so
// e = exp(-zeta pi / sqrt(1 - zeta^2)) with zeta = c / (2 sqrt(k m*)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dem_fixtures.hpp"
#include "picdem/dem/contact_law.hpp"

using namespace picdem;
using namespace picdem::dem;
using namespace picdem::dem::testing;

namespace {
constexpr double pi = 3.141592653589793;

DemConfig no_gravity(double h) {
  DemConfig c;
  c.h = h;
  c.gravity = {0.0, 0.0};
  c.g_stiffness = 9.81;
  return c;
}

double expected_e(double c, double k, double m_star) {
  const double zeta = c / (2.0 * std::sqrt(k * m_star));
  return std::exp(-zeta * pi / std::sqrt(1.0 - zeta * zeta));
}

/// Runs single subcycles (dt = dt_DEM) until the solids have met and separated.
void run_collision(DemSolver& s) {
  bool met = false;
  for (int n = 0; n < 100000; ++n) {
    s.advance(s.dt_dem(), {});
    const bool touching = !s.active_contacts().empty();
    met = met || touching;
    if (met && !touching) return;
  }
  FAIL() << "collision did not end";
}
}  // namespace

TEST(ContactLaw, CoefficientsFollowEqs10To13And18) {
  DemConfig c;
  c.h = 5e-4;
  const double m = 0.2;
  const auto k = coefficients(c, m);
  EXPECT_DOUBLE_EQ(k.k_n, m * 9.81 / (0.01 * 5e-4));
  EXPECT_DOUBLE_EQ(k.c_n, 2 * 0.4 * std::sqrt(m * k.k_n));
  EXPECT_DOUBLE_EQ(k.k_t, k.k_n / 2.6);
  EXPECT_DOUBLE_EQ(k.c_t, k.c_n / std::sqrt(2.6));
  EXPECT_NEAR(dem_time_step(c), 2 * pi / 150 * std::sqrt(m / k.k_n), 1e-18);
}

TEST(ContactLaw, CoulombCapAndTangentialDirection) {
  DemConfig c;
  c.h = 1e-3;
  const auto k = coefficients(c, 1.0);
  ContactKinematics kin{{0.0, 0.0}, {1.0, 0.0}, 1e-5, {-0.1, 0.0}, {0.1, 0.0}};
  // b slides fast in +z past a: friction drags a along +z, capped at mu F_n
  const BodyMotion a{{0.0, 0.0}, 0.0}, b{{0.0, 10.0}, 0.0};
  const auto f = contact_force(c, k, kin, a, b, 0.0, 1e-4);
  EXPECT_NEAR(f.force.x, -k.k_n * 1e-5, 1e-12);
  EXPECT_NEAR(f.force.z, 0.3 * k.k_n * 1e-5, 1e-12);
}

TEST(Restitution, DiskAgainstWallMatchesClosedForm) {
  const double r = 0.01, h = 5e-4, rho = 2700.0, v0 = 0.5;
  DemConfig cfg = no_gravity(h);
  cfg.gamma = 1500.0;
  DemSolver s = solver(cfg, 0.2, 0.2);
  s.add_solids({disk(0, r, rho, {0.1, r + cfg.gap() + 2e-3}, {0.0, -v0})});
  const double m = s.owned()[0].mass;
  run_collision(s);
  // wall: m_ij = m_i and m* = m
  const auto k = coefficients(cfg, m);
  const double e = s.owned()[0].v.z / v0;
  EXPECT_NEAR(e, expected_e(k.c_n, k.k_n, m), 0.01 * expected_e(k.c_n, k.k_n, m));
  EXPECT_NEAR(s.owned()[0].v.x, 0.0, 1e-15);
}

// radius and density of the second disk, gamma, relative tolerance on e
class PairCollision : public ::testing::TestWithParam<std::tuple<double, double, double, double>> {
};

// The contact ends inside a DEM step, where the dashpot pulls with c v_out: the discrete e differs
// from the closed form by O(zeta omega dt_DEM), 1-4 % at gamma = 150 and 10x less at gamma = 1500.
TEST_P(PairCollision, RestitutionMatchesAndMomentumIsConserved) {
  const auto [r2, rho2, gamma, tol] = GetParam();
  const double r1 = 0.01, rho1 = 2700.0, h = 5e-4, v0 = 0.4;
  DemConfig cfg = no_gravity(h);
  cfg.gamma = gamma;
  DemSolver s = solver(cfg, 0.4, 0.2);
  const double gap0 = 3e-3;
  s.add_solids({disk(0, r1, rho1, {0.2 - r1 - gap0, 0.1}, {v0, 0.0}),
                disk(1, r2, rho2, {0.2 + r2 + gap0, 0.1}, {-v0, 0.0})});
  const double m1 = s.owned()[0].mass, m2 = s.owned()[1].mass;
  const double p0 = m1 * v0 - m2 * v0;
  run_collision(s);
  const auto& b = s.owned();
  const double p1 = m1 * b[0].v.x + m2 * b[1].v.x;
  // momentum to round-off
  EXPECT_NEAR(p1, p0, 1e-14 * (m1 + m2) * v0);
  EXPECT_NEAR(m1 * b[0].v.z + m2 * b[1].v.z, 0.0, 1e-14 * (m1 + m2) * v0);
  // k from the heavier mass (the case's largest, doc/dem.md "Unequal masses"), c = 2 alpha
  // sqrt(2 m* k); m* = m1 m2 / (m1 + m2) in the dynamics. Equal masses: eqs. 10-11 with m_ij = m
  const double m_star = m1 * m2 / (m1 + m2);
  const double k_n = coefficients(cfg, std::max(m1, m2)).k_n;
  const double e_expected =
      expected_e(2.0 * cfg.alpha * std::sqrt(2.0 * m_star * k_n), k_n, m_star);
  const double e = (b[1].v.x - b[0].v.x) / (2.0 * v0);
  EXPECT_NEAR(e, e_expected, tol * e_expected);
}

INSTANTIATE_TEST_SUITE_P(EqualAndUnequalMasses, PairCollision,
                         ::testing::Values(std::make_tuple(0.01, 2700.0, 1500.0, 0.01),
                                           std::make_tuple(0.015, 2700.0, 1500.0, 0.01),
                                           std::make_tuple(0.01, 1200.0, 1500.0, 0.01),
                                           std::make_tuple(0.01, 2700.0, 150.0, 0.02),
                                           std::make_tuple(0.015, 2700.0, 150.0, 0.05)));
