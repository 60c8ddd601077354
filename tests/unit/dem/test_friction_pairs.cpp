// Friction by population (doc/dem.md, "Friction by population"): each solid may carry its own
// friction coefficient; a pair takes the smaller of its two (Yade's default for two frictional
// materials), a tank wall or an obstacle has dem/mu. Checked against the rule itself, the case
// file, and blocks on an incline (the tank floor with gravity turned by theta), which slide with
// a = g (sin theta - mu cos theta) for the pair's mu and stick when tan theta < mu.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "dem_fixtures.hpp"
#include "picdem/core/error.hpp"
#include "picdem/dem/contact_law.hpp"
#include "picdem/dem/parameters.hpp"

using namespace picdem;
using namespace picdem::dem;
using namespace picdem::dem::testing;

namespace {
constexpr double pi = 3.141592653589793, g = 9.81, L = 0.05, h = 2.5e-4;

/// Gravity turned by theta, the case's dem/mu `mu`, the accumulated spring (static friction).
DemConfig incline(double theta_deg, double mu) {
  DemConfig c;
  c.h = h;
  c.mu = mu;
  c.tangential = TangentialModel::Accumulated;
  const double t = theta_deg * pi / 180.0;
  c.gravity = {g * std::sin(t), -g * std::cos(t)};
  c.g_stiffness = g;
  return c;
}

SolidSpec block(std::int64_t id, core::Vec2 x, double friction) {
  SolidSpec s = square(id, L, 2700.0, x);
  s.friction = friction;
  return s;
}

/// `seconds` of fluid steps of dt (several subcycles each, or one of dt_DEM).
void run(DemSolver& s, double seconds, double dt = 1e-4) {
  const long long n = std::llround(seconds / dt);
  for (long long k = 0; k < n; ++k) s.advance(dt, {});
}

/// Distance slid in t from rest at a = g (sin theta - mu cos theta).
double slid(double theta_deg, double mu, double t) {
  const double th = theta_deg * pi / 180.0;
  return 0.5 * g * (std::sin(th) - mu * std::cos(th)) * t * t;
}

core::ParamSchema schema() {
  core::ParamSchema s;
  s.real("grid/cell_size", 0.01, "h");
  declare_parameters(s);
  return s;
}
}  // namespace

TEST(PairFriction, IsTheSmallerOfTheTwo) {
  EXPECT_EQ(pair_friction(0.2, 0.4), 0.2);
  EXPECT_EQ(pair_friction(0.4, 0.2), 0.2);
  EXPECT_EQ(pair_friction(0.3, 0.3), 0.3);
  EXPECT_EQ(pair_friction(0.0, 0.5), 0.0);
  // the laws carry dem/mu until the solver applies the rule
  DemConfig c;
  c.h = 1e-3;
  c.mu = 0.37;
  EXPECT_EQ(coefficients(c, 2.0).mu, 0.37);
  EXPECT_EQ(linear_spring_dashpot(c)->coefficients(1.0, 3.0).mu, 0.37);
  EXPECT_EQ(hertz_mindlin(c, 0.5)->coefficients(1.0, kFixedMass).mu, 0.37);
}

TEST(PairFriction, ReadFromTheCaseFile) {
  const std::string base =
      "grid:\n  cell_size: 0.001\nsolids:\n  a:\n    type: disk\n    radius: 0.01\n"
      "    density: 2500\n    center: [0.1, 0.1]\n";
  const auto p = core::read_case_text(base + "    friction: 0.15\n", "case.yaml", {}, schema());
  EXPECT_EQ(solids_from(p).at(0).friction, 0.15);
  // absent: -1, the case's dem/mu
  EXPECT_EQ(solids_from(core::read_case_text(base, "case.yaml", {}, schema())).at(0).friction,
            -1.0);
  // negative values other than -1 are refused, naming the key
  const auto bad = core::read_case_text(base + "    friction: -0.5\n", "case.yaml", {}, schema());
  try {
    solids_from(bad);
    ADD_FAILURE() << "friction -0.5 accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("solids/a/friction"), std::string::npos) << e.what();
  }
}

// A block of friction 0.6 on the floor of dem/mu 0.3 at 25 degrees (tan = 0.466): the pair's mu
// is the floor's 0.3, so it slides at g (sin - 0.3 cos); with its own 0.6 it would stick. A block
// of friction 0.2 on a floor of dem/mu 0.5 at 25 degrees slides at its own 0.2.
TEST(PairFriction, BlockOnTheFloorSlidesAtTheSmallerFriction) {
  const double t_end = 0.5;
  for (const auto& [floor_mu, own_mu] : {std::pair{0.3, 0.6}, std::pair{0.5, 0.2}}) {
    const DemConfig cfg = incline(25.0, floor_mu);
    DemSolver s = solver(cfg, 1.2, 0.3);
    s.add_solids({block(0, {0.1, 0.5 * L + cfg.gap()}, own_mu)});
    run(s, t_end);
    const double moved = s.owned()[0].x.x - 0.1;
    const double expected = slid(25.0, std::min(floor_mu, own_mu), t_end);
    std::printf("floor mu %.1f, block %.1f: slid %.5f m, expected %.5f m\n", floor_mu, own_mu,
                moved, expected);
    EXPECT_NEAR(moved, expected, 0.01 * expected);
  }
}

// Two blocks stacked at 10 degrees (tan = 0.176) on a floor of dem/mu 0.5: the lower block
// (friction 0.5) sticks to the floor, the upper one (friction 0.1) slides on it at
// g (sin - 0.1 cos), the pair's min(0.1, 0.5). With one friction for all (0.5) both stick. The
// upper block starts 0.3 L uphill and ends about 0.2 L downhill of the lower one (never tipping).
TEST(PairFriction, UpperBlockSlidesOnTheLowerAtTheSmallerFriction) {
  const double t_end = 0.2;
  const DemConfig cfg = incline(10.0, 0.5);
  DemSolver s = solver(cfg, 1.2, 0.3);
  const double z0 = 0.5 * L + cfg.gap();
  s.add_solids({block(0, {0.1, z0}, 0.5), block(1, {0.1 - 0.3 * L, z0 + L + cfg.gap()}, 0.1)});
  // steps of dt_DEM: with several subcycles per step the gravity kick at each step start lets
  // the accumulated spring ratchet (doc/dem.md, "Known limits"). Both land and the upper one
  // starts to slide within the first steps; measured from 0.05 s on
  const double dt = s.dt_dem();
  run(s, 0.05, dt);
  const auto start = s.gather_all();
  run(s, t_end, dt);
  const auto end = s.gather_all();
  const double lower = end[0].x.x - start[0].x.x, upper = end[1].x.x - start[1].x.x;
  // x(t) = v0 t + a t^2 / 2 from the state at 0.05 s (the upper block relative to the lower)
  const double th = 10.0 * pi / 180.0, a = g * (std::sin(th) - 0.1 * std::cos(th));
  const double T = static_cast<double>(std::llround(t_end / dt)) * dt;  // the time run
  const double expected = (start[1].v.x - start[0].v.x) * T + 0.5 * a * T * T;
  std::printf("lower block moved %.3e m, upper slid %.5f m on it, expected %.5f m\n", lower,
              upper - lower, expected);
  EXPECT_LT(std::abs(lower), 1e-5);
  EXPECT_NEAR(upper - lower, expected, 0.01 * expected);
}

// Every solid given dem/mu as its own friction: the same bits as solids without one.
TEST(PairFriction, OwnFrictionEqualToTheCasesChangesNothing) {
  const DemConfig cfg = incline(10.0, 0.3);
  std::vector<core::SolidState> out[2];
  for (int pass = 0; pass < 2; ++pass) {
    DemSolver s = solver(cfg, 1.2, 0.3);
    const double f = pass == 0 ? -1.0 : 0.3, z0 = 0.5 * L + cfg.gap();
    s.add_solids({block(0, {0.1, z0}, f), block(1, {0.1 + 0.3 * L, z0 + L + cfg.gap()}, f)});
    run(s, 0.2);
    out[pass] = s.gather_all();
  }
  for (std::size_t n = 0; n < 2; ++n) {
    EXPECT_EQ(out[0][n].x.x, out[1][n].x.x);
    EXPECT_EQ(out[0][n].x.z, out[1][n].x.z);
    EXPECT_EQ(out[0][n].theta, out[1][n].theta);
  }
}
