// Grid indexing and ownership: every cell and face has exactly one owner, whatever the rank
// count, and positions of staggered samples are where the MAC layout puts them.
#include <gtest/gtest.h>

#include "picdem/core/error.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/grid/grid.hpp"

using namespace picdem;
using namespace picdem::grid;

namespace {
GridSpec spec(int nx, int nz) {
  GridSpec s;
  s.nx = nx, s.nz = nz, s.h = 0.1, s.origin = {1.0, -2.0};
  return s;
}
}  // namespace

TEST(Grid, StaggeredPositions) {
  const auto s = spec(10, 6);
  const Vec2 c = s.position(Stagger::Cell, 2, 3);
  EXPECT_DOUBLE_EQ(c.x, 1.25);
  EXPECT_DOUBLE_EQ(c.z, -1.65);
  const Vec2 u = s.position(Stagger::FaceX, 2, 3);
  EXPECT_DOUBLE_EQ(u.x, 1.2);
  EXPECT_DOUBLE_EQ(u.z, -1.65);
  const Vec2 w = s.position(Stagger::FaceZ, 2, 3);
  EXPECT_DOUBLE_EQ(w.x, 1.25);
  EXPECT_DOUBLE_EQ(w.z, -1.7);
  EXPECT_EQ(s.extent(Stagger::FaceX), (IndexBox{0, 11, 0, 6}));
  EXPECT_EQ(s.extent(Stagger::FaceZ), (IndexBox{0, 10, 0, 7}));
  int i, k;
  s.cell_of({1.25, -1.65}, i, k);
  EXPECT_EQ(i, 2);
  EXPECT_EQ(k, 3);
  EXPECT_EQ(s.cell_gid(2, 3), 32);
}

TEST(Grid, EverySampleHasExactlyOneOwner) {
  const auto s = spec(37, 23);
  core::Comm comm;
  Decomposition d(s, comm, 2);
  EXPECT_EQ(d.px() * d.pz(), comm.size());
  for (Stagger st : {Stagger::Cell, Stagger::FaceX, Stagger::FaceZ}) {
    const IndexBox ext = s.extent(st);
    long long total = 0;
    for (int r = 0; r < d.size(); ++r) {
      total += d.owned(st, r).size();
      for (int q = r + 1; q < d.size(); ++q)
        EXPECT_TRUE(d.owned(st, r).intersect(d.owned(st, q)).empty());
    }
    EXPECT_EQ(total, ext.size());
  }
  for (int k = 0; k < s.nz; ++k)
    for (int i = 0; i < s.nx; ++i) EXPECT_TRUE(d.owned_cells(d.owner_of_cell(i, k)).contains(i, k));
}

TEST(Grid, ExplicitProcessGridAndErrors) {
  core::Comm comm;
  const auto s = spec(40, 20);
  Decomposition d(s, comm, 2, comm.size(), 1);
  EXPECT_EQ(d.px(), comm.size());
  EXPECT_THROW(Decomposition(s, comm, 2, comm.size() + 1, 1), core::InputError);
  EXPECT_THROW(Decomposition(spec(4, 4), comm, 4), core::InputError);  // blocks thinner than halo
}

TEST(Grid, FieldIndexingCoversStorage) {
  core::Comm comm;
  const auto s = spec(16, 9);
  Decomposition d(s, comm, 2);
  GridArray<double> f(d, Stagger::FaceZ, 1.5);
  const IndexBox b = f.storage();
  EXPECT_EQ(b, d.owned(Stagger::FaceZ).grown(2));
  EXPECT_EQ(f.data().size(), static_cast<std::size_t>(b.size()));
  EXPECT_EQ(f.index(b.i0, b.k0), 0u);
  EXPECT_EQ(f.index(b.i1 - 1, b.k1 - 1), f.data().size() - 1);
  EXPECT_EQ(f(b.i0 + 1, b.k0 + 1), 1.5);
}
