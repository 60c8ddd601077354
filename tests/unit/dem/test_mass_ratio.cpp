// The linear spring-dashpot for any mass ratio (doc/dem.md, "Unequal masses"), against its
// definitions: in a case whose heaviest solid has mass m_s, every pair has k_xi = m_s |g| /
// (theta dx), c_xi = 2 alpha sqrt(m_d k_xi) with m_d = 2 m* between solids and m_i at a wall,
// and dt_DEM = dt_paper sqrt(m_min / m_max). With equal masses these are eqs. 10-13 and 18 bit for
// bit. Every pair then has the damping ratio of the paper's equal pair (sqrt(2) alpha between
// solids, alpha at a wall), so its restitution does not depend on the mass ratio, and the lightest
// pair is resolved with the paper's number of steps per period.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dem_fixtures.hpp"
#include "picdem/dem/contact_law.hpp"

using namespace picdem;
using namespace picdem::dem;
using namespace picdem::dem::testing;

namespace {
constexpr double pi = 3.141592653589793;
constexpr double h = 5e-4, rho = 2700.0, r = 0.01, v0 = 0.4;

DemConfig no_gravity() {
  DemConfig c;
  c.h = h;
  c.gravity = {0.0, 0.0};
  c.g_stiffness = 9.81;
  return c;
}

/// Closed-form restitution of a linear spring-dashpot of damping ratio zeta.
double closed_form_e(double zeta) {
  return std::exp(-zeta * pi / std::sqrt(1.0 - zeta * zeta));
}

/// Single DEM steps until the solids have met and separated; false if the contact never ended.
bool run_collision(DemSolver& s) {
  bool met = false;
  for (int n = 0; n < 2000000; ++n) {
    s.advance(s.dt_dem(), {});
    const bool touching = !s.active_contacts().empty();
    met = met || touching;
    if (met && !touching) return true;
  }
  return false;
}

/// Restitution of two bodies (a at rest on the left, b of `ratio` times its density) meeting
/// head-on at +-v0 along x; `rel_p` gets the momentum error relative to (m_a + m_b) v0.
double head_on(double ratio, bool squares, double& rel_p) {
  DemSolver s = solver(no_gravity(), 0.4, 0.2);
  const double half = squares ? 0.5 * 0.02 : r, gap0 = 3e-3;
  const core::Vec2 xa{0.2 - half - gap0, 0.1}, xb{0.2 + half + gap0, 0.1};
  if (squares)
    s.add_solids({square(0, 0.02, rho, xa, 0.0, {v0, 0.0}),
                  square(1, 0.02, ratio * rho, xb, 0.0, {-v0, 0.0})});
  else
    s.add_solids({disk(0, r, rho, xa, {v0, 0.0}), disk(1, r, ratio * rho, xb, {-v0, 0.0})});
  const double m1 = s.owned()[0].mass, m2 = s.owned()[1].mass;
  if (!run_collision(s)) return -1.0;
  const auto& b = s.owned();
  rel_p = std::abs(m1 * b[0].v.x + m2 * b[1].v.x - (m1 - m2) * v0) / ((m1 + m2) * v0);
  return (b[1].v.x - b[0].v.x) / (2.0 * v0);
}

/// Restitution of the light and of the heavy disk (mass ratio `ratio`) both dropped onto the floor
/// at v0 in one case (so the light one's wall contact has the case's stiffness).
std::pair<double, double> against_floor(double ratio) {
  DemConfig cfg = no_gravity();
  DemSolver s = solver(cfg, 0.4, 0.2);
  const double z = r + cfg.gap() + 2e-3;
  s.add_solids(
      {disk(0, r, rho, {0.1, z}, {0.0, -v0}), disk(1, r, ratio * rho, {0.3, z}, {0.0, -v0})});
  bool met = false;
  for (int n = 0; n < 2000000; ++n) {
    s.advance(s.dt_dem(), {});
    const bool touching = !s.active_contacts().empty();
    met = met || touching;
    if (met && !touching) break;
  }
  return {s.owned()[0].v.z / v0, s.owned()[1].v.z / v0};
}
}  // namespace

TEST(MassRatio, EqualMassesGiveEqs10To13And18BitForBit) {
  DemConfig cfg;
  cfg.h = h;
  for (double m : {0.2, 0.8482300164692441, 3.0e-3}) {
    const auto law = linear_spring_dashpot(cfg)->for_masses(m, m);
    const auto k = law->coefficients(m, m), paper = coefficients(cfg, 0.5 * (m + m));
    EXPECT_EQ(k.k_n, paper.k_n);
    EXPECT_EQ(k.c_n, paper.c_n);
    EXPECT_EQ(k.k_t, paper.k_t);
    EXPECT_EQ(k.c_t, paper.c_t);
    const auto w = law->coefficients(m, kFixedMass), wall = coefficients(cfg, m);
    EXPECT_EQ(w.k_n, wall.k_n);
    EXPECT_EQ(w.c_n, wall.c_n);
    EXPECT_EQ(w.k_t, wall.k_t);
    EXPECT_EQ(w.c_t, wall.c_t);
    EXPECT_EQ(law->time_step(m, m), dem_time_step(cfg));
  }
}

TEST(MassRatio, CoefficientsAndTimeStepForUnequalMasses) {
  DemConfig cfg;
  cfg.h = h;
  const double m1 = 0.01, m2 = 0.7, m3 = 10.0;  // the case's masses lie in [m1, m3]
  const auto law = linear_spring_dashpot(cfg)->for_masses(m1, m3);
  const double k_s = m3 * 9.81 / (0.01 * h), m_star = m1 * m2 / (m1 + m2);
  const auto k = law->coefficients(m1, m2);
  EXPECT_NEAR(k.k_n, k_s, 1e-14 * k_s);
  EXPECT_NEAR(k.c_n, 2 * 0.4 * std::sqrt(2 * m_star * k_s), 1e-14 * k.c_n);
  EXPECT_NEAR(k.k_t, k_s / 2.6, 1e-14 * k_s);
  EXPECT_NEAR(k.c_t, k.c_n / std::sqrt(2.6), 1e-14 * k.c_n);
  const auto w = law->coefficients(m1, kFixedMass);
  EXPECT_NEAR(w.k_n, k_s, 1e-14 * k_s);
  EXPECT_NEAR(w.c_n, 2 * 0.4 * std::sqrt(m1 * k_s), 1e-14 * w.c_n);
  // the lightest pair (two solids of m1, m* = m1 / 2, or m1 at a wall): 2 pi / gamma sqrt(m1 / k)
  const double dt = 2 * pi / 150 * std::sqrt(m1 / k_s);
  EXPECT_NEAR(law->time_step(m1, m3), dt, 1e-14 * dt);
  // the law without the case's masses is the paper's
  const auto p = linear_spring_dashpot(cfg)->coefficients(m1, m2);
  EXPECT_EQ(p.k_n, coefficients(cfg, 0.5 * (m1 + m2)).k_n);
}

// mass ratio of the pair
class MassRatioCollision : public ::testing::TestWithParam<double> {};

// Between solids the damping ratio is sqrt(2) alpha for every ratio (e = 0.1159 in closed form at
// alpha = 0.4). The discrete e differs from the closed form by the contact's end inside a step
// (PairCollision in test_contact_law.cpp); the requirement is e within 2% of the equal pair's.
TEST_P(MassRatioCollision, DiskDiskRestitutionDoesNotDependOnTheRatio) {
  const double ratio = GetParam();
  double p1 = 0.0, p = 0.0;
  const double e1 = head_on(1.0, false, p1), e = head_on(ratio, false, p);
  std::printf("disks, ratio %g: e = %.5f, equal pair %.5f (%+.2e), closed form %.5f\n", ratio, e,
              e1, e / e1 - 1.0, closed_form_e(std::sqrt(2.0) * 0.4));
  EXPECT_NEAR(e, e1, 0.02 * e1);
  EXPECT_NEAR(e, closed_form_e(std::sqrt(2.0) * 0.4), 0.05 * e);
  EXPECT_LT(p, 1e-13);
}

TEST_P(MassRatioCollision, PolygonPolygonRestitutionDoesNotDependOnTheRatio) {
  const double ratio = GetParam();
  double p1 = 0.0, p = 0.0;
  const double e1 = head_on(1.0, true, p1), e = head_on(ratio, true, p);
  std::printf("squares, ratio %g: e = %.5f, equal pair %.5f (%+.2e)\n", ratio, e, e1, e / e1 - 1.0);
  EXPECT_NEAR(e, e1, 0.02 * e1);
  EXPECT_LT(p, 1e-13);
}

// At a wall the damping ratio is alpha (e = 0.2538 in closed form) for the light and the heavy
// disk alike, whatever the other masses of the case.
TEST_P(MassRatioCollision, DiskWallRestitutionDoesNotDependOnTheRatio) {
  const double ratio = GetParam();
  const auto [l1, h1] = against_floor(1.0);
  const auto [light, heavy] = against_floor(ratio);
  std::printf("floor, ratio %g: e light %.5f heavy %.5f, equal masses %.5f, closed form %.5f\n",
              ratio, light, heavy, l1, closed_form_e(0.4));
  EXPECT_EQ(l1, h1);
  EXPECT_NEAR(light, l1, 0.02 * l1);
  EXPECT_NEAR(heavy, l1, 0.02 * l1);
}

INSTANTIATE_TEST_SUITE_P(Ratios, MassRatioCollision, ::testing::Values(1.0, 10.0, 100.0, 1000.0));
