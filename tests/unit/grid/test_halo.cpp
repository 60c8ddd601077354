// Halo exchange at 1, 2 and 3 ranks: forward fills every ghost that lies on the grid with its
// owner's value; reverse_add sums all ranks' ghost contributions into the owners.
#include <gtest/gtest.h>

#include "picdem/grid/field.hpp"

using namespace picdem;
using namespace picdem::grid;

namespace {
double tag(Stagger s, int i, int k) {
  return 1000.0 * static_cast<int>(s) + 100.0 * i + k;
}
}  // namespace

class HaloTest : public ::testing::TestWithParam<Stagger> {};

TEST_P(HaloTest, ForwardFillsGhostsFromOwners) {
  const Stagger st = GetParam();
  GridSpec s;
  s.nx = 23, s.nz = 17, s.h = 1.0;
  core::Comm comm;
  Decomposition d(s, comm, 2);
  Halo halo(d);
  GridArray<double> f(d, st, -1.0);
  const IndexBox own = f.owned();
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) f(i, k) = tag(st, i, k);
  halo.forward(f);
  const IndexBox ext = s.extent(st);
  const IndexBox st_box = f.storage();
  for (int k = st_box.k0; k < st_box.k1; ++k)
    for (int i = st_box.i0; i < st_box.i1; ++i) {
      if (ext.contains(i, k))
        EXPECT_EQ(f(i, k), tag(st, i, k)) << i << "," << k;
      else
        EXPECT_EQ(f(i, k), -1.0);  // off-grid ghosts belong to boundary conditions
    }
}

TEST_P(HaloTest, ReverseAddSumsContributions) {
  const Stagger st = GetParam();
  GridSpec s;
  s.nx = 19, s.nz = 14, s.h = 1.0;
  core::Comm comm;
  Decomposition d(s, comm, 2);
  Halo halo(d);
  GridArray<double> f(d, st, 1.0);  // every rank adds 1 to every sample it stores
  halo.reverse_add(f);
  // Count, for every owned sample, how many ranks store it.
  const IndexBox own = f.owned();
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) {
      int holders = 0;
      for (int r = 0; r < d.size(); ++r) holders += d.storage(st, r).contains(i, k) ? 1 : 0;
      EXPECT_EQ(f(i, k), holders) << i << "," << k;
    }
}

TEST_P(HaloTest, IntegerFieldsToo) {
  const Stagger st = GetParam();
  GridSpec s;
  s.nx = 12, s.nz = 12, s.h = 1.0;
  core::Comm comm;
  Decomposition d(s, comm, 1);
  Halo halo(d);
  GridArray<int> f(d, st, -7);
  const IndexBox own = f.owned();
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) f(i, k) = d.rank();
  halo.forward(f);
  const IndexBox ext = s.extent(st);
  const IndexBox b = f.storage();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i)
      if (ext.contains(i, k)) {
        int owner = -1;
        for (int r = 0; r < d.size(); ++r)
          if (d.owned(st, r).contains(i, k)) owner = r;
        EXPECT_EQ(f(i, k), owner);
      }
}

INSTANTIATE_TEST_SUITE_P(AllStaggers, HaloTest,
                         ::testing::Values(Stagger::Cell, Stagger::FaceX, Stagger::FaceZ));
