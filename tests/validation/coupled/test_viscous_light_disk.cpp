// A light disk (density 100) rising in cases/neutral_disk at nu = 1e-2 m^2/s with the implicit
// viscosity and no-slip walls (doc/viscous.md "Rigid rows"). With the split (the fluid's wall value
// the disk's start-of-step velocity) it blows up at step 11; with the disk's rigid velocity an
// unknown of the viscous step (coupling/viscous_rigid_rows) it rises smoothly: over 40 steps
// (0.08 s) its upward speed never falls from one step to the next by more than 1% of its value
// and approaches a terminal speed (the last 10 steps within 5% of each other), far below the
// blow-up's metres per second.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "case_loader.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/dem/dem_solver.hpp"

using namespace picdem;

TEST(ViscousLightDisk, RisesSmoothlyWithRigidRows) {
  core::Comm comm;
  const auto params = test_support::load_case(
      comm, "cases/neutral_disk/case.yaml",
      {"solids/disk/density=100", "fluid/viscosity=1e-2", "fluid/viscosity_scheme=implicit",
       "fluid/walls=no_slip", "coupling/viscous_rigid_rows=true"});
  test_support::print_resolution(comm, "ViscousLightDisk.RisesSmoothlyWithRigidRows", params);
  coupling::Simulation sim(comm, params);
  std::vector<double> w;
  for (int n = 0; n < 40; ++n) {
    sim.step();
    w.push_back(sim.dem()->gather_all().at(0).v.z);
  }
  double worst_drop = 0.0;
  for (std::size_t n = 1; n < w.size(); ++n)
    worst_drop = std::max(worst_drop, (w[n - 1] - w[n]) / std::abs(w[n - 1]));
  const auto last = std::minmax_element(w.end() - 10, w.end());
  if (comm.is_root())
    std::printf(
        "light disk, rigid rows: w after 1, 10, 20, 40 steps %.5f %.5f %.5f %.5f m/s; "
        "largest step-to-step drop %.3f%%; last 10 steps %.5f..%.5f m/s\n",
        w[0], w[9], w[19], w[39], 100 * worst_drop, *last.first, *last.second);
  EXPECT_GT(w[0], 0.0);
  EXPECT_LT(worst_drop, 0.01);
  EXPECT_LT(*last.second - *last.first, 0.05 * *last.second);
  EXPECT_LT(*last.second, 0.1);  // m/s
}
