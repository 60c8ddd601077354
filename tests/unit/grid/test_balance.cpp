// Cut lines that follow the work (grid/balance.hpp) and the move of a field to new cut lines
// (grid::redistributed): the strips carry equal shares of the work within one column's weight,
// the heaviest block is lighter than with equal strips, and every sample keeps its value.
#include <gtest/gtest.h>

#include <numeric>

#include "picdem/grid/balance.hpp"
#include "picdem/grid/field.hpp"

using namespace picdem;
using namespace picdem::grid;

namespace {
GridSpec spec(int nx, int nz) {
  GridSpec s;
  s.nx = nx, s.nz = nz, s.h = 0.1, s.origin = {0.0, 0.0};
  return s;
}

// A "water column": cells with i < nx / 4 and k < nz / 2 weigh 81, the others 1.
std::vector<long long> column_work(const Decomposition& d) {
  const IndexBox own = d.owned_cells();
  std::vector<long long> w;
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i)
      w.push_back(i < d.spec().nx / 4 && k < d.spec().nz / 2 ? 81 : 1);
  return w;
}
}  // namespace

TEST(Balance, SplitWeightedGivesEqualShares) {
  // 3 heavy entries then 7 light ones, in 2 parts: the cut falls inside the heavy run
  const std::vector<long long> w{10, 10, 10, 1, 1, 1, 1, 1, 1, 1};
  EXPECT_EQ(split_weighted(w, 2, 1), (std::vector<int>{0, 2, 10}));
  // the minimum width pushes the cut out
  EXPECT_EQ(split_weighted(w, 2, 3), (std::vector<int>{0, 3, 10}));
  // uniform weights: equal strips
  EXPECT_EQ(split_weighted(std::vector<long long>(12, 5), 3, 2), (std::vector<int>{0, 4, 8, 12}));
  // an empty tail still gets its minimum width
  EXPECT_EQ(split_weighted({100, 0, 0, 0, 0, 0}, 3, 2), (std::vector<int>{0, 2, 4, 6}));
}

TEST(Balance, CutsFollowTheWorkOnEveryRankCount) {
  core::Comm comm;
  const auto s = spec(64, 40);
  Decomposition d(s, comm, 2);
  const auto work = column_work(d);
  const Cuts c = balanced_cuts(d, work, 0, 0);
  ASSERT_EQ((c.xs.size() - 1) * (c.zs.size() - 1), static_cast<std::size_t>(comm.size()));
  // total work 16 * 20 * 81 + (64 * 40 - 320) = 28160; the heaviest block within one
  // column (20 * 81) or row (16 * 81) of its share, and never heavier than with equal strips
  const long long total = 16 * 20 * 81 + (64 * 40 - 320);
  EXPECT_LE(c.heaviest, total / comm.size() + 20 * 81);
  EXPECT_LE(c.heaviest, heaviest_block(d, work));
  if (comm.size() > 1) {
    // every strip of the chosen direction cuts through the heavy column
    if (c.zs.size() == 2) {
      for (std::size_t j = 1; j + 1 < c.xs.size(); ++j) EXPECT_LT(c.xs[j], 16);
    }
    d.set_cuts(c.xs, c.zs);
    EXPECT_EQ(heaviest_block(d, column_work(d)), c.heaviest);
    for (int r = 0; r < d.size(); ++r)
      EXPECT_TRUE(d.owned_cells(r).intersect({0, 16, 0, 20}).size() > 0) << "rank " << r;
  }
  // the cut lines of the blocks are found back from the boxes
  std::vector<IndexBox> boxes;
  for (int r = 0; r < d.size(); ++r) boxes.push_back(d.owned_cells(r));
  const Cuts back = cuts_of_boxes(s, boxes);
  EXPECT_EQ(back.xs, d.x_cuts());
  EXPECT_EQ(back.zs, d.z_cuts());
  boxes.back().i0 += 1;  // not a tiling
  EXPECT_TRUE(cuts_of_boxes(s, boxes).xs.empty());
}

TEST(Balance, SetCutsRejectsBadLines) {
  core::Comm comm;
  Decomposition d(spec(20, 10), comm, 2);
  const int p = comm.size();
  if (p == 1) {
    EXPECT_NO_THROW(d.set_cuts({0, 20}, {0, 10}));
  } else {
    EXPECT_THROW(d.set_cuts({0, 20}, {0, 10}), std::invalid_argument);  // 1 block for p ranks
  }
  EXPECT_THROW(d.set_cuts({0, 19}, {0, 10}), std::invalid_argument);  // short of nx
  if (p == 2) {
    EXPECT_THROW(d.set_cuts({0, 2, 20}, {0, 10}), std::invalid_argument);  // thin
  }
}

TEST(Balance, RedistributedKeepsEveryValue) {
  core::Comm comm;
  const auto s = spec(30, 17);
  Decomposition from(s, comm, 2);
  const Cuts c = balanced_cuts(from, column_work(from), 0, 0);
  Decomposition to = from;
  to.set_cuts(c.xs, c.zs);
  // value of a sample: its global position, ghosts beyond the walls included
  auto value = [](int i, int k) { return 1000.0 * k + i + 0.5; };
  for (Stagger st : {Stagger::Cell, Stagger::FaceX, Stagger::FaceZ}) {
    GridArray<double> f(from, st, -1.0);
    const IndexBox b = f.storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) f(i, k) = value(i, k);
    const GridArray<double> g = redistributed(f, from, to);
    EXPECT_EQ(g.storage(), to.storage(st));
    const IndexBox n = g.storage();
    for (int k = n.k0; k < n.k1; ++k)
      for (int i = n.i0; i < n.i1; ++i) ASSERT_EQ(g(i, k), value(i, k)) << i << ", " << k;
  }
}
