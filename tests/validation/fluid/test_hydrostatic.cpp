// Still water 0.1 m deep (40 cells) in a closed tank, run for 1 s: the pressure equals rho g depth
// within 1% at every depth below the top quarter, and no fluid speed exceeds 1e-3 m/s. The
// particles are seeded with the default jitter, not on a lattice (doc/validation.md, Still water).
#include <gtest/gtest.h>

#include <cmath>

#include "case_loader.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/run/run.hpp"

using namespace picdem;

TEST(Hydrostatic, PressureAndSpuriousCurrentsAfterOneSecond) {
  core::Comm comm;
  const auto params = test_support::load_case(comm, "cases/hydrostatic_tank/case.yaml");
  test_support::print_resolution(comm, "Hydrostatic.PressureAndSpuriousCurrentsAfterOneSecond",
                                 params);
  ASSERT_GT(params.real("particles/jitter"), 0.0) << "still water with jittered seeding";
  coupling::Simulation sim(comm, params);
  run::Run(sim).run();
  ASSERT_NEAR(sim.time(), 1.0, 1e-12);

  const double rho = params.real("fluid/density"), g = 9.81, level = 0.1;
  const double h = params.real("grid/cell_size");
  const double x = 0.1 + 0.5 * h;
  double worst = 0.0;
  for (double depth_fraction : {0.25, 0.5, 0.75, 0.99}) {
    // Cell centre nearest to the depth.
    const int k = static_cast<int>((level - depth_fraction * level) / h);
    const double z = (k + 0.5) * h;
    const double expected = rho * g * (level - z);
    const double p = sim.fluid().pressure_at({x, z});
    const double rel = std::abs(p - expected) / expected;
    worst = std::max(worst, rel);
    EXPECT_LT(rel, 0.01) << "depth " << level - z << " m: p = " << p << ", rho g d = " << expected;
  }
  if (comm.is_root()) std::printf("hydrostatic: worst relative pressure error %.3e\n", worst);
  const double grid_speed = sim.fluid().max_grid_speed();  // collective: on every rank
  EXPECT_LT(sim.diagnostics().max_speed, 1e-3);
  EXPECT_LT(grid_speed, 1e-3);
  if (comm.is_root())
    std::printf("hydrostatic: max particle speed %.3e m/s, max grid speed %.3e m/s\n",
                sim.diagnostics().max_speed, grid_speed);
}
