// The time-step rule (fluid::choose_time_step) fed by the DEM's surface motion
// (dem::surface_motion), as time/cfl_speed grid does: a solid moving at a known speed gives the dt
// worked by hand, on 1 and 2 ranks (the solid on one of them), and dt grows by at most
// time/dt_growth a step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/dem/figures.hpp"
#include "picdem/fluid/time_step.hpp"
#include "picdem/geometry/circle.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/grid/grid.hpp"
#include "picdem/particles/figures.hpp"

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

// Only the solids whose surface can reach water within dt_max bound the step (the coupled step's
// filter, step_phases.cpp cfl_extra_motion): a disk falling at 5 m/s 0.48 m above the water does
// not, a disk at 0.5 m/s 3 cm above it does. particles::near_particles reads the particles' count
// of this rank's owned and halo cells and answers true where the square leaves them.
TEST(SolidTimeStep, OnlySolidsNearTheWaterBound) {
  const core::Comm comm;
  dem::DemConfig cfg;
  cfg.h = 0.01;
  grid::GridSpec spec;
  spec.nx = 100, spec.nz = 100, spec.h = 0.01;  // the tank [0, 1] x [0, 1]
  const grid::Decomposition d(spec, comm, 3, 0, 0);
  dem::DemSolver dem(comm, cfg, grid::owned_regions(d), {{0.0, 0.0}, {1.0, 1.0}}, {});
  std::vector<dem::SolidSpec> disks(2);
  const Vec2 at[2] = {{0.3, 0.8}, {0.7, 0.33}}, v[2] = {{0.0, -5.0}, {0.0, -0.5}};
  for (int n = 0; n < 2; ++n) {
    disks[n].shape = std::make_shared<const geometry::Circle>(0.02);
    disks[n].density = 2000.0;
    disks[n].state.id = n, disks[n].state.x = at[n], disks[n].state.v = v[n];
  }
  dem.add_solids(disks);
  grid::GridArray<int> count(d, grid::Stagger::Cell, 0);  // water up to z = 0.3: 4 per cell
  const auto b = count.storage();
  for (int k = std::max(b.k0, 0); k < std::min(b.k1, 30); ++k)
    for (int i = b.i0; i < b.i1; ++i) count(i, k) = 4;
  const double dt_max = 1e-3, cfl = 0.5, g = 9.81;
  const auto near_water = [&](const core::SolidState& s, double radius, double speed) {
    const double reach = radius + (speed + g * dt_max) * dt_max + (1.0 + cfl) * spec.h;
    return particles::near_particles(count, spec, s.x, reach);
  };
  EXPECT_NEAR(dem::surface_motion(dem, comm).speed, 5.0, 1e-14);  // every solid
  EXPECT_NEAR(dem::surface_motion(dem, comm, near_water).speed, 0.5, 1e-14);
  // 0.48 m above the water at 5 m/s: the fall within dt_max (5 mm) is far from the water
  const Vec2 high{0.3, 0.8}, low{0.7, 0.33};
  int i, k;
  spec.cell_of(high, i, k);
  EXPECT_EQ(particles::near_particles(count, spec, high, 0.0405), !count.in_storage(i, k));
  spec.cell_of(low, i, k);
  EXPECT_EQ(particles::near_particles(count, spec, low, 0.0405), true);  // in its halo or past it
  spec.cell_of({0.9, 0.9}, i, k);  // a dry corner: false where this rank sees it
  EXPECT_EQ(particles::near_particles(count, spec, {0.9, 0.9}, 0.05), !count.in_storage(i, k));
}
