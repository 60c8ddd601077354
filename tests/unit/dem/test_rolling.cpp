// Rolling resistance (doc/dem.md, "Rolling resistance"): the constant directional torque
// M_r = -mu_r R* |F_n| sign(omega_rel), against its closed forms for a disk (I = m R^2 / 2)
// rolling without slip (mu large enough):
//   flat floor: m a = -F_t, I alpha = F_t R - mu_r R m g, a = R alpha  =>  a = -(2/3) mu_r g,
//               stopping distance v0^2 / (2 |a|) = 3 v0^2 / (4 mu_r g);
//   incline theta: a = (2/3) g (sin(theta) - mu_r cos(theta)) when rolling; at rest F_t = m g
//               sin(theta) and the torque F_t R must not exceed mu_r R m g cos(theta):
//               at rest below tan(theta_c) = mu_r, rolls above.
// The incline is the tank floor with gravity turned by theta.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dem_fixtures.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/params.hpp"
#include "picdem/dem/contact_law.hpp"
#include "picdem/dem/parameters.hpp"

using namespace picdem;
using namespace picdem::dem;
using namespace picdem::dem::testing;

namespace {
constexpr double pi = 3.141592653589793, g = 9.81, R = 0.05, h = 2.5e-4, mu_r = 0.1;

DemConfig rolling_config(double theta_deg) {
  DemConfig c;
  c.h = h;
  c.mu = 0.5;
  c.mu_r = mu_r;
  // the accumulated tangential spring holds a contact point at rest (the one-step spring lets it
  // creep, doc/dem.md "Known limits"), so what is measured is the rolling resistance's
  c.tangential = TangentialModel::Accumulated;
  const double t = theta_deg * pi / 180.0;
  c.gravity = {g * std::sin(t), -g * std::cos(t)};
  c.g_stiffness = g;
  return c;
}
}  // namespace

TEST(RollingResistance, DiskOnAFlatFloorStopsAfterThreeV0SquaredOverFourMuRG) {
  const double v0 = 0.5, x0 = 0.1;
  const DemConfig cfg = rolling_config(0.0);
  DemSolver s = solver(cfg, 0.5, 0.2);
  s.add_solids({disk(0, R, 2700.0, {x0, R + cfg.gap()}, {v0, 0.0}, -v0 / R)});
  const double a = 2.0 / 3.0 * mu_r * g, t1 = 0.3;
  double v_t1 = 0.0;
  const double dt = 1e-4;
  for (int n = 1; n <= 15000; ++n) {
    s.advance(dt, {});
    if (n == static_cast<int>(std::lround(t1 / dt))) v_t1 = s.owned()[0].v.x;
  }
  const auto& d = s.owned()[0];
  const double distance = 3.0 * v0 * v0 / (4.0 * mu_r * g);
  std::printf(
      "v(%.1f s) = %.5f m/s (closed form %.5f), stopped after %.5f m (closed form %.5f), "
      "v = %.2e m/s, omega = %.2e rad/s\n",
      t1, v_t1, v0 - a * t1, d.x.x - x0, distance, d.v.x, d.omega);
  EXPECT_NEAR(v_t1, v0 - a * t1, 0.01 * (v0 - a * t1));
  EXPECT_NEAR(d.x.x - x0, distance, 0.01 * distance);
  // at rest, and never rolled back: the torque does not reverse the rotation
  EXPECT_LT(std::abs(d.v.x), 1e-3);
  EXPECT_LE(d.omega, 1e-9);
}

// theta [deg] on both sides of theta_c = atan(mu_r) = 5.71 degrees
class RollingOnIncline : public ::testing::TestWithParam<double> {};

TEST_P(RollingOnIncline, AtRestBelowTanThetaEqualsMuRRollsAbove) {
  const double theta = GetParam(), th = theta * pi / 180.0, t_end = 0.5, x0 = 0.1;
  const DemConfig cfg = rolling_config(theta);
  DemSolver s = solver(cfg, 0.4, 0.2);
  s.add_solids({disk(0, R, 2700.0, {x0, R + cfg.gap()})});
  const long long steps = std::llround(t_end / 1e-4);
  for (long long n = 0; n < steps; ++n) s.advance(1e-4, {});
  const auto& d = s.owned()[0];
  const double moved = d.x.x - x0;
  if (std::tan(th) < mu_r) {
    // at rest up to a creep: the torque is capped by I |omega| / dt_DEM (so that it never
    // reverses the rotation), so it holds the static torque m g sin(theta) R only once
    // |omega| >= m g sin(theta) R dt_DEM / I: a creep speed of at most 2 g sin(theta) dt_DEM
    const double creep = 2.0 * g * std::sin(th) * s.dt_dem();
    const double free = 0.5 * 2.0 / 3.0 * g * std::sin(th) * t_end * t_end;  // mu_r = 0
    std::printf(
        "%g deg (below): moved %.3e m in %.1f s (%.1e of free rolling), v = %.2e m/s, "
        "creep bound %.2e m/s\n",
        theta, moved, t_end, moved / free, d.v.x, creep);
    EXPECT_LT(std::abs(d.v.x), creep);
    EXPECT_LT(std::abs(moved), creep * t_end);
  } else {
    const double a = 2.0 / 3.0 * g * (std::sin(th) - mu_r * std::cos(th));
    std::printf("%g deg (above): moved %.5f m, closed form %.5f m\n", theta, moved,
                0.5 * a * t_end * t_end);
    EXPECT_NEAR(moved, 0.5 * a * t_end * t_end, 0.01 * 0.5 * a * t_end * t_end);
    EXPECT_NEAR(-d.omega * R, d.v.x, 0.01 * d.v.x) << "no slip";
  }
}

INSTANTIATE_TEST_SUITE_P(BelowAndAbove, RollingOnIncline, ::testing::Values(3.0, 5.0, 7.0, 10.0));

TEST(RollingResistance, ReadFromTheCaseFileAndZeroByDefault) {
  core::ParamSchema schema;
  declare_parameters(schema);
  const auto p =
      core::read_case_text("dem:\n  rolling_resistance: 0.15\n", "case.yaml", {}, schema);
  EXPECT_EQ(config_from(p, 1e-3).mu_r, 0.15);
  EXPECT_EQ(
      config_from(core::read_case_text("dem:\n  mu: 0.3\n", "case.yaml", {}, schema), 1e-3).mu_r,
      0.0);
  EXPECT_THROW(core::read_case_text("dem:\n  rolling_resistance: -0.1\n", "case.yaml", {}, schema),
               core::InputError);
  // no torque without relative rotation or without mu_r
  const ContactKinematics kin{{0.0, 0.0}, {0.0, -1.0}, 1e-5, {0.0, -R}, {}};
  EXPECT_EQ(rolling_torque(0.1, 5.0, kin, {{}, 0.0, 1.0}, {}, 1e-5), 0.0);
  EXPECT_EQ(rolling_torque(0.0, 5.0, kin, {{}, 3.0, 1.0}, {}, 1e-5), 0.0);
  // against a wall: -mu_r R |F_n| sign(omega), or the torque that stops omega within dt
  EXPECT_DOUBLE_EQ(rolling_torque(0.1, 5.0, kin, {{}, 3.0, 1.0}, {}, 1e-5), -0.1 * R * 5.0);
  EXPECT_DOUBLE_EQ(rolling_torque(0.1, 5.0, kin, {{}, -1e-8, 1.0}, {}, 1e-5), 1e-8 / 1e-5);
}
