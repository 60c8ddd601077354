// fluid::choose_time_step against values worked by hand: h = 0.01 m, time/cfl 0.5, the largest
// face speed 2 m/s (w = -2 on every face, u = 1), on 1 or 2 ranks (the speed is every rank's).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "picdem/core/error.hpp"
#include "picdem/fluid/time_step.hpp"

using namespace picdem;

namespace {

struct Tank {
  grid::GridSpec spec;
  core::Comm comm;
  grid::Decomposition d;
  fluid::FluidState f;
  static grid::GridSpec make_spec() {
    grid::GridSpec s;
    s.nx = 8, s.nz = 4, s.h = 0.01;
    return s;
  }
  Tank() : spec(make_spec()), d(spec, comm, 3, 0, 0), f(d) { fill(1.0, -2.0); }
  /// u and w on every face
  void fill(double u, double w) {
    for (auto [field, value] : {std::pair{&f.u, u}, std::pair{&f.w, w}}) {
      const auto b = field->storage();
      for (int k = b.k0; k < b.k1; ++k)
        for (int i = b.i0; i < b.i1; ++i) (*field)(i, k) = value;
    }
  }
};

}  // namespace

// dt = min(dt_max, cfl h / max|u|, cfl h / speed, h^2 / (4 nu) with explicit viscosity).
TEST(TimeStep, SmallestOfTheBounds) {
  Tank t;
  const fluid::TimeStepLimits limits{0.01, 0.5, 0.01, 1e-6, 1.0};
  fluid::FluidConfig cfg;
  cfg.h = 0.01, cfg.nu = 1e-6;  // h^2 / (4 nu) = 25 s: not the bound
  const double tol = 1e-18;
  // without water: dt_max, whatever the speed
  EXPECT_EQ(fluid::choose_time_step(limits, cfg, 0.0, 0, nullptr, {7.0}, 0.0, t.comm), 0.01);
  // the grid: 0.5 0.01 / 2 = 2.5e-3
  EXPECT_NEAR(fluid::choose_time_step(limits, cfg, 0.0, 0, &t.f, {0.0}, 0.0, t.comm), 2.5e-3, tol);
  // a particle or solid surface at 5 m/s: 0.5 0.01 / 5 = 1e-3
  EXPECT_NEAR(fluid::choose_time_step(limits, cfg, 0.0, 0, &t.f, {5.0}, 0.0, t.comm), 1e-3, tol);
  // one slower than the grid changes nothing
  EXPECT_NEAR(fluid::choose_time_step(limits, cfg, 0.0, 0, &t.f, {1.0}, 0.0, t.comm), 2.5e-3, tol);
  // dt_max below them all
  fluid::TimeStepLimits capped = limits;
  capped.dt_max = 4e-4;
  EXPECT_EQ(fluid::choose_time_step(capped, cfg, 0.0, 0, &t.f, {5.0}, 0.0, t.comm), 4e-4);
  // explicit viscosity nu = 0.5: h^2 / (4 nu) = 5e-5; none with the implicit scheme
  cfg.nu = 0.5;
  EXPECT_NEAR(fluid::choose_time_step(limits, cfg, 0.0, 0, &t.f, {0.0}, 0.0, t.comm), 5e-5, tol);
  cfg.implicit_viscosity = true;
  EXPECT_NEAR(fluid::choose_time_step(limits, cfg, 0.0, 0, &t.f, {0.0}, 0.0, t.comm), 2.5e-3, tol);
}

// Below time/dt_min the run has blown up, unless the end is nearer than dt_min.
TEST(TimeStep, CollapseBelowDtMinStopsTheRun) {
  Tank t;
  const fluid::TimeStepLimits limits{0.01, 0.5, 0.01, 1e-3, 1.0};
  fluid::FluidConfig cfg;
  cfg.h = 0.01;
  // a speed of 50 m/s: 1e-4 < dt_min
  try {
    fluid::choose_time_step(limits, cfg, 0.25, 7, &t.f, {50.0}, 0.0, t.comm);
    ADD_FAILURE() << "no SolverError";
  } catch (const core::SolverError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("step 7 at t = 0.25 s"), std::string::npos) << what;
    EXPECT_NE(what.find("below time/dt_min"), std::string::npos) << what;
    // what is fast (the grid at 2 m/s, the particles or solids at 50 m/s) and the inputs that
    // make flows this fast, with fluid/density's value
    EXPECT_NE(what.find("fastest on the grid 2 m/s; particles or solids 50 m/s"), std::string::npos)
        << what;
    EXPECT_NE(what.find("fluid/density = 1000 kg/m^3"), std::string::npos) << what;
  }
  // 5e-4 before the end (less than dt_min): the short step is taken
  EXPECT_NEAR(fluid::choose_time_step(limits, cfg, 0.9995, 7, &t.f, {50.0}, 0.0, t.comm), 1e-4,
              1e-18);
}

// An inflow bounds the step before the grid carries its speed (a tank at rest, step 1): a
// uniform 4 m/s inflow, 0.5 0.01 / 4 = 1.25e-3; a table whose largest speed at t = 1 is 10 m/s
// (between 6 and 14 at times 0.5 and 1.5, at its second height), 5e-4; an outflow, none.
TEST(TimeStep, InflowSpeedBoundsTheStepFromRest) {
  Tank t;
  t.fill(0.0, 0.0);
  const fluid::TimeStepLimits limits{0.01, 0.5, 0.01, 1e-6, 2.0};
  fluid::FluidConfig cfg;
  cfg.h = 0.01;
  EXPECT_EQ(fluid::choose_time_step(limits, cfg, 1.0, 0, &t.f, {0.0}, 0.0, t.comm), 0.01);
  fluid::OpenSide& left = cfg.open.side[0];
  left.kind = fluid::OpenKind::Inflow, left.from = 0.0, left.to = 0.04, left.velocity = 4.0;
  EXPECT_NEAR(fluid::choose_time_step(limits, cfg, 1.0, 0, &t.f, {0.0}, 0.0, t.comm), 1.25e-3,
              1e-18);
  left.shape = fluid::InflowShape::Table;
  left.heights = {0.0, 0.04}, left.times = {0.5, 1.5}, left.table = {1.0, 6.0, 2.0, 14.0};
  EXPECT_NEAR(fluid::choose_time_step(limits, cfg, 1.0, 0, &t.f, {0.0}, 0.0, t.comm), 5e-4, 1e-18);
  left.kind = fluid::OpenKind::Outflow;
  EXPECT_EQ(fluid::choose_time_step(limits, cfg, 1.0, 0, &t.f, {0.0}, 0.0, t.comm), 0.01);
}

// Under time/cfl_speed grid the faces' velocities are those before the step: water at rest would
// take dt_max. Water that gravity accelerates from rest moves |g| dt^2 in the step: dt <=
// sqrt(cfl h / |g|). h = 0.01, cfl 0.5, g = (3, -4) (|g| = 5): sqrt(0.005 / 5) = 0.0316... s; with
// a grid at 2 m/s (2.5e-3) or dt_max below it, those bind; the particles rule has no such bound.
TEST(TimeStep, GridRuleBoundsTheFluidsStepByGravity) {
  Tank t;
  t.fill(0.0, 0.0);
  fluid::TimeStepLimits grid{0.01, 0.5, 1.0, 1e-6, 10.0};
  grid.cfl_from_particles = false;
  fluid::FluidConfig cfg;
  cfg.h = 0.01, cfg.nu = 0.0, cfg.g = {3.0, -4.0};
  const double bound = std::sqrt(0.005 / 5.0);
  EXPECT_NEAR(fluid::choose_time_step(grid, cfg, 0.0, 0, &t.f, {0.0}, 0.0, t.comm), bound, 1e-17);
  fluid::TimeStepLimits particles = grid;
  particles.cfl_from_particles = true;
  EXPECT_EQ(fluid::choose_time_step(particles, cfg, 0.0, 0, &t.f, {0.0}, 0.0, t.comm), 1.0);
  // no gravity, no bound
  cfg.g = {0.0, 0.0};
  EXPECT_EQ(fluid::choose_time_step(grid, cfg, 0.0, 0, &t.f, {0.0}, 0.0, t.comm), 1.0);
  cfg.g = {3.0, -4.0};
  grid.dt_max = 0.02;
  EXPECT_EQ(fluid::choose_time_step(grid, cfg, 0.0, 0, &t.f, {0.0}, 0.0, t.comm), 0.02);
  Tank moving;  // faces at 2 m/s: 0.5 0.01 / 2 = 2.5e-3
  EXPECT_NEAR(fluid::choose_time_step(grid, cfg, 0.0, 0, &moving.f, {0.0}, 0.0, moving.comm),
              2.5e-3, 1e-18);
}
