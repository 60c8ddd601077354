// The time-step rule (fluid::choose_time_step) fed by the DEM's surface motion
// (dem::surface_motion), as time/cfl_speed grid does: a solid moving at a known speed gives the dt
// worked by hand, on 1 and 2 ranks (the solid on one of them), and dt grows by at most
// time/dt_growth a step.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/dem/figures.hpp"
#include "picdem/fluid/time_step.hpp"
#include "picdem/geometry/circle.hpp"

using namespace picdem;
using core::Vec2;

namespace {

// A tank [0, 1] x [0, 1] cut in vertical strips, one per rank, holding one disk of radius r at
// x (owned by the rank whose strip holds it), moving with v and omega.
dem::DemSolver one_disk(const core::Comm& comm, double r, Vec2 x, Vec2 v, double omega) {
  dem::DemConfig cfg;
  cfg.h = 0.01;
  std::vector<core::Box2> regions;
  const int n = comm.size();
  for (int k = 0; k < n; ++k) regions.push_back({{double(k) / n, 0.0}, {double(k + 1) / n, 1.0}});
  const core::Box2 tank{{0.0, 0.0}, {1.0, 1.0}};
  dem::DemSolver s(comm, cfg, regions, tank, {});
  dem::SolidSpec d;
  d.shape = std::make_shared<const geometry::Circle>(r);
  d.density = 2000.0;
  d.state.id = 0, d.state.x = x, d.state.v = v, d.state.omega = omega;
  s.add_solids({d});
  return s;
}

// The grid of a 10 x 10 tank of h = 0.01 with u = `u` on every face (w = 0).
struct Grid {
  grid::GridSpec spec;
  core::Comm comm;
  grid::Decomposition d;
  fluid::FluidState f;
  fluid::FluidConfig cfg;
  static grid::GridSpec make_spec() {
    grid::GridSpec s;
    s.nx = 10, s.nz = 10, s.h = 0.01;
    return s;
  }
  explicit Grid(double u = 0.0) : spec(make_spec()), d(spec, comm, 3, 0, 0), f(d) {
    const auto b = f.u.storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) f.u(i, k) = u;
    cfg.h = 0.01;
  }
  double dt(const fluid::TimeStepLimits& lim, fluid::StepMotion m, double last_dt) const {
    return fluid::choose_time_step(lim, cfg, 0.0, 0, &f, m, last_dt, comm);
  }
};

}  // namespace

// |v| = 5 m/s, omega R = 10 * 0.02 = 0.2 m/s: the surface moves at 5.2 m/s; gravity adds 9.81 m/s
// per second. h = 0.01, cfl 0.5, still water: the step with (5.2 + 9.81 dt) dt = 0.005 is
// dt = 2 * 0.005 / (5.2 + sqrt(5.2^2 + 4 * 9.81 * 0.005)) = 9.5980...e-4 s, under dt_max.
TEST(SolidTimeStep, SolidAtKnownSpeedGivesTheWorkedStep) {
  const core::Comm comm;
  const auto dem = one_disk(comm, 0.02, {0.3, 0.5}, {3.0, -4.0}, 10.0);
  const dem::SurfaceMotion m = dem::surface_motion(dem, comm);  // collective
  EXPECT_NEAR(m.speed, 5.2, 1e-14);
  EXPECT_NEAR(m.accel, 9.81, 1e-14);
  const Grid g;
  const fluid::TimeStepLimits rule{0.01, 0.5, 1e-2, 1e-8, 1.0, 0.0};
  const double dt = g.dt(rule, {m.speed, m.accel}, 0.0);
  const double by_hand = 2 * 0.005 / (5.2 + std::sqrt(5.2 * 5.2 + 4 * 9.81 * 0.005));
  EXPECT_NEAR(dt, by_hand, 1e-18);
  EXPECT_NEAR(dt, 9.5980e-4, 1e-8);
  // the surface then moves exactly cfl h in the step, speed and gravity's change together
  EXPECT_NEAR((m.speed + m.accel * dt) * dt, 0.5 * 0.01, 1e-17);
  // without gravity's term the bound is cfl h / 5.2 = 9.615e-4 s: gravity shortens the step
  EXPECT_NEAR(g.dt(rule, {m.speed, 0.0}, 0.0), 0.005 / 5.2, 1e-18);
  EXPECT_LT(dt, 0.005 / 5.2);
}

// The grid's face speed and dt_max bound too; a solid at rest falls under gravity alone:
// dt = sqrt(cfl h / g).
TEST(SolidTimeStep, GridSpeedDtMaxAndASolidAtRest) {
  const core::Comm comm;
  const auto dem = one_disk(comm, 0.02, {0.8, 0.5}, {0.0, 0.0}, 0.0);
  const dem::SurfaceMotion m = dem::surface_motion(dem, comm);
  EXPECT_EQ(m.speed, 0.0);
  const fluid::TimeStepLimits rule{0.01, 0.5, 1.0, 1e-8, 1.0, 0.0};
  EXPECT_NEAR(Grid().dt(rule, {m.speed, m.accel}, 0.0), std::sqrt(0.005 / 9.81), 1e-15);
  const Grid flowing(2.0);  // the grid's 2 m/s binds: 0.005 / 2
  EXPECT_EQ(flowing.dt(rule, {m.speed, m.accel}, 0.0), 0.005 / 2.0);
  fluid::TimeStepLimits capped = rule;
  capped.dt_max = 1e-3;
  EXPECT_EQ(flowing.dt(capped, {m.speed, m.accel}, 0.0), 1e-3);
  EXPECT_EQ(Grid().dt(capped, {}, 0.0), 1e-3);  // nothing moves: dt_max
}

// time/dt_growth: after a short step dt comes back by at most the factor per step; the first
// step (no last dt) is not bounded by it.
TEST(SolidTimeStep, GrowthFromTheLastStepIsBounded) {
  const fluid::TimeStepLimits rule{0.01, 0.5, 1e-3, 1e-8, 1.0, 1.2};
  const Grid calm(1.0);  // CFL: 5e-3 s, so dt_max binds
  EXPECT_EQ(calm.dt(rule, {}, 0.0), 1e-3);
  double dt = 2e-4;
  int steps = 0;
  while (dt < 1e-3) {
    const double next = calm.dt(rule, {}, dt);
    EXPECT_LE(next, 1.2 * dt);
    dt = next, ++steps;
  }
  EXPECT_EQ(steps, 9);  // 2e-4 * 1.2^8 = 8.6e-4 < 1e-3 <= 2e-4 * 1.2^9
  EXPECT_EQ(calm.dt(rule, {}, 1e-3), 1e-3);
  // a faster flow still shortens the step at once
  EXPECT_EQ(Grid(50.0).dt(rule, {}, 1e-3), 0.005 / 50.0);
}
