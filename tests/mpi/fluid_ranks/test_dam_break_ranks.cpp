// The dam break on 1, 2 and 3 ranks gives the same front position and fluid volume within 1e-6
// relative after 100 steps (solver tolerance tightened to 1e-12 so that only round-off differs).
#include <gtest/gtest.h>

#include <cmath>

#include "case_loader.hpp"
#include "picdem/coupling/simulation.hpp"

using namespace picdem;

namespace {
coupling::Diagnostics run_on(int ranks) {
  MPI_Group world, group;
  MPI_Comm_group(MPI_COMM_WORLD, &world);
  std::vector<int> members(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r) members[static_cast<std::size_t>(r)] = r;
  MPI_Group_incl(world, ranks, members.data(), &group);
  MPI_Comm sub;
  MPI_Comm_create(MPI_COMM_WORLD, group, &sub);
  coupling::Diagnostics d;
  if (sub != MPI_COMM_NULL) {
    core::Comm comm(sub);
    const auto params = test_support::load_case(comm, "cases/dam_break/case.yaml",
                                           {"solver/tolerance=1e-12", "time/end=10"});
    coupling::Simulation sim(comm, params, "");
    for (int n = 0; n < 100; ++n) sim.step();
    d = sim.diagnostics();
    MPI_Comm_free(&sub);
  }
  MPI_Group_free(&group);
  MPI_Group_free(&world);
  // Everyone gets rank 0's figures.
  double v[3] = {d.front_x, d.fluid_volume, d.t};
  MPI_Bcast(v, 3, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  d.front_x = v[0], d.fluid_volume = v[1], d.t = v[2];
  return d;
}
}  // namespace

TEST(DamBreakRanks, SameFrontAndVolumeOnOneTwoThreeRanks) {
  int size = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  ASSERT_EQ(size, 3) << "run this test on 3 ranks";
  const auto d1 = run_on(1), d2 = run_on(2), d3 = run_on(3);
  for (const auto* d : {&d2, &d3}) {
    EXPECT_NEAR(d->t, d1.t, 1e-6 * d1.t);
    EXPECT_NEAR(d->front_x, d1.front_x, 1e-6 * d1.front_x);
    EXPECT_NEAR(d->fluid_volume, d1.fluid_volume, 1e-6 * d1.fluid_volume);
  }
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("after 100 steps: t = %.9g / %.9g / %.9g, front = %.12g / %.12g / %.12g\n", d1.t,
                d2.t, d3.t, d1.front_x, d2.front_x, d3.front_x);
}
