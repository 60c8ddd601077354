// run::check_step on made-up diagnostics: h = 0.01 m, dt = 1e-3 s, so 2 cells in the step is a
// speed of 20 m/s. Under time/cfl_speed particles the particles' speed counts; under grid the
// distance the grid velocity moved them during the step (a fast face the step leaves does not
// stop the run: the next step's dt follows it). On 1 or 2 ranks, the same figures on every rank
// (as the diagnostics are).
#include <gtest/gtest.h>

#include <string>

#include "picdem/core/error.hpp"
#include "picdem/run/check_step.hpp"

using namespace picdem;

namespace {

coupling::Diagnostics figures(double particle_speed, double advected) {
  coupling::Diagnostics g;
  g.t = 0.5, g.dt = 1e-3, g.step = 12;
  g.max_speed = particle_speed, g.advected = advected;
  return g;
}

// The message of the SolverError check_step throws, or "" when it passes.
std::string stop(const coupling::Diagnostics& g, bool grid_speed, bool has_fluid = true) {
  const core::Comm comm;
  try {
    run::check_step(g, 0.01, has_fluid, grid_speed, nullptr, comm);
  } catch (const core::SolverError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CheckStep, ParticlesRuleStopsAParticleFasterThanTwoCellsPerStep) {
  EXPECT_EQ(stop(figures(19.0, 0.0), false), "");
  EXPECT_EQ(stop(figures(19.0, 0.05), false), "");  // the grid's distance does not count here
  const std::string m = stop(figures(30.0, 0.0), false);
  EXPECT_NE(m.find("step 12 at t = 0.5 s: a particle moved 3 cells in one step (speed 30 m/s"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("the run has blown up"), std::string::npos) << m;
  EXPECT_EQ(stop(figures(30.0, 0.0), false, false), "");  // dry: no particles
}

TEST(CheckStep, GridRuleStopsWhatTheGridMovedAParticle) {
  EXPECT_EQ(stop(figures(100.0, 0.015), true),
            "");  // fast particles do not count: the grid moves them
  const std::string m = stop(figures(0.0, 0.025), true);
  EXPECT_NE(m.find("step 12 at t = 0.5 s: the grid velocity moved a particle 2.5 cells in one "
                   "step (speed 25 m/s"),
            std::string::npos)
      << m;
}
