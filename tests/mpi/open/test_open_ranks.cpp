// Open sides on 1 and 2 ranks: cases/channel_poiseuille for 100 steps (1 s: the inflow has
// brought 0.25 of the channel's volume), on 2 ranks split at x = 0.2 m so that the inflow (left)
// and the outflow (right) belong to different ranks, every solve to 1e-12. The particles injected
// and removed, and so the whole particle set by id, must be the same on both rank counts (the
// injection depends on the side, face and time only), their positions and the volumes through the
// sides equal to the solvers' tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "case_loader.hpp"
#include "first_ranks.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/particles/particle_set.hpp"

using namespace picdem;

namespace {

struct Result {
  std::vector<double> ids, x, z;  // every rank's particles, sorted by id
  double in = 0.0, out = 0.0;
  int ranks_x = 0;
};

Result run_on(int ranks, const std::vector<std::string>& split) {
  Result res;
  test_support::on_first_ranks(ranks, [&](MPI_Comm sub) {
    core::Comm comm(sub);
    std::vector<std::string> o{"solver/tolerance=1e-12", "solver/density_tolerance=1e-12",
                               "grid/decomposition=uniform"};
    o.insert(o.end(), split.begin(), split.end());
    const auto params = test_support::load_case(comm, "cases/channel_poiseuille/case.yaml", o);
    coupling::Simulation sim(comm, params);
    for (int n = 0; n < 100; ++n) sim.step();
    const auto& p = sim.particles();
    std::vector<double> mine;
    for (std::size_t n = 0; n < p.size(); ++n)
      mine.insert(mine.end(), {static_cast<double>(p.id[n]), p.x[n], p.z[n]});
    const auto all = comm.all_gather(mine);
    std::vector<std::size_t> order(all.size() / 3);
    for (std::size_t n = 0; n < order.size(); ++n) order[n] = n;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return all[3 * a] < all[3 * b]; });
    for (std::size_t n : order) {
      res.ids.push_back(all[3 * n]);
      res.x.push_back(all[3 * n + 1]);
      res.z.push_back(all[3 * n + 2]);
    }
    res.in = sim.diagnostics().open_volumes.at(0);
    res.out = sim.diagnostics().open_volumes.at(1);
    res.ranks_x = static_cast<int>(sim.grid_split().x_cuts.size()) - 1;
  });
  for (auto* v : {&res.ids, &res.x, &res.z}) test_support::broadcast_from_root(*v, MPI_DOUBLE);
  std::vector<double> s{res.in, res.out, static_cast<double>(res.ranks_x)};
  test_support::broadcast_from_root(s, MPI_DOUBLE);
  res.in = s[0], res.out = s[1], res.ranks_x = static_cast<int>(s[2]);
  return res;
}

}  // namespace

TEST(OpenRanks, ChannelOnOneAndTwoRanks) {
  int size = 0, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  ASSERT_EQ(size, 2) << "run this test on 2 ranks";
  const auto a = run_on(1, {});
  const auto b = run_on(2, {"grid/ranks_x=2", "grid/ranks_z=1"});
  ASSERT_EQ(b.ranks_x, 2);
  long long injected = 0;
  for (double id : a.ids) injected += id < 0.0;
  ASSERT_EQ(a.ids, b.ids) << "the particle sets differ";
  double dx = 0.0;
  for (std::size_t n = 0; n < a.x.size(); ++n)
    dx = std::max({dx, std::abs(a.x[n] - b.x[n]), std::abs(a.z[n] - b.z[n])});
  if (rank == 0)
    std::printf(
        "channel, 100 steps: %zu particles (%lld injected) on 1 and 2 ranks, the same ids; "
        "largest position difference %.3e m; in %.10f / %.10f, out %.10f / %.10f m^2\n",
        a.ids.size(), injected, dx, a.in, b.in, a.out, b.out);
  EXPECT_GT(injected, 1000);  // 0.01 m^2 in at 4 particles per 2.5e-5 m^2: 1600
  EXPECT_LT(dx, 1e-9);
  EXPECT_NEAR(a.in, b.in, 1e-14);
  EXPECT_NEAR(a.out, b.out, 1e-10);
  EXPECT_NEAR(a.in, 0.1 * 0.1 * 1.0, 1e-12);
}
