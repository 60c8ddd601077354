// The implicit viscosity with a solid on 1, 2 and 3 ranks: a disk of density 2000 sinking in
// cases/neutral_disk at nu = 1e-2 (no-slip walls), 20 steps, with the grid cut through the disk
// (2 ranks: x = 0.08 m, the disk's centre line; 3 ranks: z = 0.04 m, which it crosses as it
// sinks) and every solve to 1e-12. Every rank's replicated viscous solve sees every solid, and the
// viscous loads are taken by solid id from the owner and summed over the ranks: the disk's state
// and its viscous load must agree with 1 rank to the solvers' tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "case_loader.hpp"
#include "first_ranks.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/run/forces.hpp"

using namespace picdem;

namespace {

// x, z, u, w, omega of the disk, then its viscous force (x, z) and torque of the last step.
std::vector<double> run_on(int ranks, const std::vector<std::string>& split) {
  std::vector<double> out;
  test_support::on_first_ranks(ranks, [&](MPI_Comm sub) {
    core::Comm comm(sub);
    std::vector<std::string> o{"solids/disk/density=2000",
                               "solids/disk/center=[0.08, 0.05]",
                               "fluid/viscosity=1e-2",
                               "fluid/viscosity_scheme=implicit",
                               "fluid/walls=no_slip",
                               "solver/tolerance=1e-12",
                               "solver/density_tolerance=1e-12",
                               "grid/decomposition=uniform"};
    o.insert(o.end(), split.begin(), split.end());
    const auto params = test_support::load_case(comm, "cases/neutral_disk/case.yaml", o);
    coupling::Simulation sim(comm, params);
    for (int n = 0; n < 20; ++n) sim.step();
    const auto st = sim.dem()->gather_all().at(0);
    const auto v = run::body_forces(sim).at(0);
    out = {st.x.x, st.x.z, st.v.x, st.v.z, st.omega, v.viscous.x, v.viscous.z, v.torque_viscous};
  });
  test_support::broadcast_from_root(out, MPI_DOUBLE);
  return out;
}

}  // namespace

TEST(ViscousRanks, SinkingDiskOnOneTwoThreeRanks) {
  int size = 0, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  ASSERT_EQ(size, 3) << "run this test on 3 ranks";
  const auto a = run_on(1, {});
  const auto b = run_on(2, {"grid/ranks_x=2", "grid/ranks_z=1"});
  const auto c = run_on(3, {"grid/ranks_x=1", "grid/ranks_z=3"});
  ASSERT_EQ(a.size(), 8u);
  for (const auto* r : {&b, &c}) {
    ASSERT_EQ(r->size(), 8u);
    double dx = 0.0, dv = 0.0, dload = 0.0;
    for (int n = 0; n < 2; ++n) dx = std::max(dx, std::abs((*r)[n] - a[n]));
    for (int n = 2; n < 4; ++n) dv = std::max(dv, std::abs((*r)[n] - a[n]));
    for (int n = 5; n < 7; ++n) dload = std::max(dload, std::abs((*r)[n] - a[n]));
    if (rank == 0)
      std::printf(
          "%s ranks vs 1, 20 steps: disk at (%.9f, %.9f) m, w %.6e m/s, viscous load (%.6e, "
          "%.6e) N/m; differences: position %.3e m, velocity %.3e m/s, omega %.3e rad/s, viscous "
          "force %.3e N/m, torque %.3e N m/m\n",
          r == &b ? "2" : "3", (*r)[0], (*r)[1], (*r)[3], (*r)[5], (*r)[6], dx, dv,
          std::abs((*r)[4] - a[4]), dload, std::abs((*r)[7] - a[7]));
    EXPECT_LT(dx, 1e-8);  // 1e-6 of the radius
    EXPECT_LT(dv, 1e-6);
    EXPECT_LT(std::abs((*r)[4] - a[4]), 1e-4);  // rad/s: 1e-6 m/s at the rim
    EXPECT_LT(dload, 1e-6 * std::abs(a[6]));
  }
  EXPECT_GT(std::abs(a[6]), 0.01);  // the disk feels a viscous load (N/m)
}
