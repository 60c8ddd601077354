// Rank-count invariance: the dry collapse on 2 or 3 ranks gives a solids.csv identical, byte for
// byte (all 17 digits), to the same run on one rank, for both tangential models (the accumulated
// springs migrate with their solids). Regions cut through the stack so that ghosts, migration and
// ownership changes happen from the first steps.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>

#include "../../validation/dem/dry_collapse_run.hpp"

using namespace picdem;
using namespace picdem::dem;
using namespace picdem::dem::testing;

namespace {

/// solids.csv text; `contacts` gets the number of active contacts over all ranks at each output.
std::string solids_csv(const core::Comm& comm, const CollapseCase& c,
                       std::vector<core::Box2> regions,
                       std::vector<long long>* owned_counts = nullptr,
                       std::vector<long long>* contacts = nullptr) {
  std::string csv = "t,id,x,z,theta,u,w,omega\n";
  run_collapse(comm, c, std::move(regions), [&](double t, const DemSolver& s) {
    append_solids_csv(csv, t, s.gather_all());
    if (owned_counts) owned_counts->push_back(static_cast<long long>(s.owned().size()));
    if (contacts) contacts->push_back(comm.sum(static_cast<long long>(s.active_contacts().size())));
  });
  return csv;
}

std::vector<core::Box2> grid_regions(const core::Comm& comm, const CollapseCase& c) {
  const grid::GridSpec g = grid::spec_from(c.params);
  const grid::Decomposition d(g, comm, 2, comm.size(), 1);
  std::vector<core::Box2> r;
  for (int q = 0; q < comm.size(); ++q) {
    const core::IndexBox b = d.owned_cells(q);
    r.push_back({g.origin + core::Vec2{b.i0 * g.h, b.k0 * g.h},
                 g.origin + core::Vec2{b.i1 * g.h, b.k1 * g.h}});
  }
  return r;
}

}  // namespace

class RankInvariance : public ::testing::TestWithParam<std::string> {};

TEST_P(RankInvariance, SolidsCsvIdenticalToOneRank) {
  const core::Comm world;
  ASSERT_GT(world.size(), 1);
  const CollapseCase c =
      load_collapse(world, {"dem/tangential_model=" + GetParam(), "time/end=0.3"});
  // cuts through the stack (x in [0, 0.067]): 2 ranks at 3 cm, 3 ranks at 2.5 and 4.5 cm
  const std::vector<double> cuts =
      world.size() == 2 ? std::vector<double>{0.03} : std::vector<double>{0.025, 0.045};
  ASSERT_EQ(cuts.size() + 1, static_cast<std::size_t>(world.size()));
  std::vector<long long> counts, contacts;
  const std::string parallel = solids_csv(world, c, strips(c.tank, cuts), &counts, &contacts);
  // every rank owned solids at some output, and the total is always 33
  long long most = 0;
  for (long long n : counts) most = std::max(most, n);
  EXPECT_GT(most, 0) << "rank " << world.rank() << " never owned a solid";
  for (long long n : counts) EXPECT_EQ(world.sum(n), 33);

  const std::string by_grid = solids_csv(world, c, grid_regions(world, c));
  if (world.rank() == 0) {
    const core::Comm self(MPI_COMM_SELF);
    const CollapseCase c1 =
        load_collapse(self, {"dem/tangential_model=" + GetParam(), "time/end=0.3"});
    std::vector<long long> serial_contacts;
    const std::string serial = solids_csv(self, c1, strips(c1.tank, {}), nullptr, &serial_contacts);
    // each active contact is reported once over all ranks
    EXPECT_EQ(contacts, serial_contacts);
    EXPECT_GT(*std::max_element(serial_contacts.begin(), serial_contacts.end()), 20);
    EXPECT_GT(serial.size(), 30000u);
    EXPECT_TRUE(parallel == serial) << "strip regions: solids.csv differs from one rank";
    EXPECT_TRUE(by_grid == serial) << "grid regions: solids.csv differs from one rank";
  }
}

INSTANTIATE_TEST_SUITE_P(TangentialModels, RankInvariance,
                         ::testing::Values(std::string("one_step"), std::string("accumulated")));
