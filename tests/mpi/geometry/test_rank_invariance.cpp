// 1, 2 and 3 ranks give identical cut-cell data: every rank builds its own window (owned cells
// plus halo) and compares the cells and faces it owns with a computation over the whole grid.
#include <gtest/gtest.h>

#include <tuple>

#include "cut_scene.hpp"
#include "picdem/core/comm.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/grid/grid.hpp"

using namespace picdem;
using namespace picdem::geometry;

namespace {

using PieceKey = std::tuple<int, int, int, double, double>;

}  // namespace

TEST(CutCellsRanks, OwnedDataEqualsTheWholeGridComputation) {
  grid::GridSpec spec;
  spec.nx = 64;
  spec.nz = 48;
  spec.h = 1.0 / 64;
  core::Comm comm;
  const grid::Decomposition d(spec, comm, 2);
  const auto obstacles = test_support::perforated_pipe();
  const auto solids = test_support::random_solids(3, 0.05, 9);
  const CutCellOptions opt;  // default tiny-cell rule, so dropping is covered too

  const GridWindow mine{spec.origin, spec.h, d.storage(grid::Stagger::Cell)};
  const GridWindow all{spec.origin, spec.h, spec.extent(grid::Stagger::Cell)};
  const CutCells a = build_cut_cells(mine, solids, obstacles, opt);
  const CutCells b = build_cut_cells(all, solids, obstacles, opt);

  const auto own = d.owned_cells();
  long long dropped = 0;
  for (int k = own.k0; k < own.k1; ++k) {
    for (int i = own.i0; i < own.i1; ++i) {
      ASSERT_EQ(a.E_x(i, k), b.E_x(i, k)) << i << " " << k;
      ASSERT_EQ(a.E_z(i, k), b.E_z(i, k)) << i << " " << k;
      ASSERT_EQ(a.fluid_fraction(i, k), b.fluid_fraction(i, k));
      ASSERT_EQ(a.cutting_body(i, k), b.cutting_body(i, k));
      ASSERT_EQ(a.cutting_obstacle(i, k), b.cutting_obstacle(i, k));
      ASSERT_EQ(a.dropped(i, k), b.dropped(i, k));
      dropped += a.dropped(i, k) ? 1 : 0;
    }
  }
  // The ring just outside the window knows its covering bodies as the whole grid does (faces on
  // the window's edge pick their body from both sides).
  const auto ring = mine.cells.grown(1).intersect(all.cells);
  long long ring_cells = 0;
  for (int k = ring.k0; k < ring.k1; ++k)
    for (int i = ring.i0; i < ring.i1; ++i) {
      if (mine.cells.contains(i, k)) continue;
      ASSERT_EQ(a.cutting_body(i, k), b.cutting_body(i, k)) << "ring " << i << " " << k;
      ASSERT_EQ(a.cutting_obstacle(i, k), b.cutting_obstacle(i, k)) << "ring " << i << " " << k;
      ++ring_cells;
    }
  EXPECT_EQ(ring_cells > 0, comm.size() > 1);
  // Faces owned by the last block along each direction.
  for (int k = own.k0; k < own.k1; ++k) ASSERT_EQ(a.E_x(own.i1, k), b.E_x(own.i1, k));
  for (int i = own.i0; i < own.i1; ++i) ASSERT_EQ(a.E_z(i, own.k1), b.E_z(i, own.k1));
  // Pieces of owned cells, in the same order and bitwise equal.
  auto owned_pieces = [&own](const CutCells& c) {
    std::vector<WettedPiece> v;
    for (const auto& p : c.pieces) {
      if (own.contains(p.i, p.k)) v.push_back(p);
    }
    return v;
  };
  const auto pa = owned_pieces(a), pb = owned_pieces(b);
  ASSERT_EQ(pa.size(), pb.size());
  for (std::size_t j = 0; j < pa.size(); ++j) {
    ASSERT_EQ(pa[j].body, pb[j].body);
    ASSERT_EQ(pa[j].i, pb[j].i);
    ASSERT_EQ(pa[j].k, pb[j].k);
    ASSERT_EQ(pa[j].p0, pb[j].p0);
    ASSERT_EQ(pa[j].p1, pb[j].p1);
    ASSERT_EQ(pa[j].n_dl, pb[j].n_dl);
    ASSERT_EQ(pa[j].r_cross_n_dl, pb[j].r_cross_n_dl);
    ASSERT_EQ(pa[j].length, pb[j].length);
  }
  // Together the ranks hold every piece of the whole grid exactly once.
  EXPECT_EQ(comm.sum(static_cast<long long>(pa.size())), static_cast<long long>(b.pieces.size()));
  // The scene exercises what it should: dropped tiny cells and wetted pieces of every kind.
  EXPECT_GT(comm.sum(dropped), 0);
  EXPECT_GT(b.pieces.size(), 500u);
}
