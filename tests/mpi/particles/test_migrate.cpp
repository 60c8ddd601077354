// Migration on 1, 2, 3 ranks: after every particle moved up to two cells, migrate conserves the
// particle count and the set of particles (ids, positions, velocities bit for bit), puts every
// particle on the rank owning its cell, and leaves each rank's particles sorted by (cell, id).
#include <gtest/gtest.h>

#include "particle_testing.hpp"
#include "picdem/core/rng.hpp"
#include "picdem/particles/particles.hpp"

using namespace picdem;
using namespace picdem::particles;

namespace {
grid::GridSpec tank() {
  grid::GridSpec s;
  s.nx = 30, s.nz = 20, s.h = 0.1, s.origin = {0.0, 0.0};
  return s;
}
double rnd(std::int64_t id, int what) {
  return core::uniform01(5, static_cast<std::uint64_t>(id), static_cast<std::uint64_t>(what));
}
// moves each particle by up to 1.9 cells in each direction, kept in the tank
void scramble(ParticleSet& p, const grid::GridSpec& s) {
  for (std::size_t n = 0; n < p.size(); ++n) {
    p.x[n] = std::clamp(p.x[n] + 3.8 * s.h * (rnd(p.id[n], 0) - 0.5), 1e-9, s.length() - 1e-9);
    p.z[n] = std::clamp(p.z[n] + 3.8 * s.h * (rnd(p.id[n], 1) - 0.5), 1e-9, s.height() - 1e-9);
    p.u[n] = rnd(p.id[n], 2), p.w[n] = rnd(p.id[n], 3);
  }
}
}  // namespace

TEST(Migrate, ConservesParticlesAndPutsThemOnTheirOwner) {
  const grid::GridSpec s = tank();
  ParticleConfig c;
  core::Comm comm;
  grid::Decomposition d(s, comm, required_halo(c));
  ParticleSet p = seed(d, c, [](core::Vec2 x) { return x.z < 1.4; });
  scramble(p, s);
  const auto before = ptest::gather_all(p, comm);
  long long id_sum = 0;
  for (auto id : p.id) id_sum += id;
  id_sum = comm.sum(id_sum);

  migrate(p, d);

  const auto after = ptest::gather_all(p, comm);
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t n = 0; n < after.size(); ++n) {
    EXPECT_EQ(after[n].id, before[n].id);
    EXPECT_EQ(after[n].x, before[n].x);
    EXPECT_EQ(after[n].z, before[n].z);
    EXPECT_EQ(after[n].u, before[n].u);
    EXPECT_EQ(after[n].w, before[n].w);
  }
  long long id_sum_after = 0, misplaced = 0, unsorted = 0;
  long long previous_cell = -1;
  std::int64_t previous_id = -1;
  for (std::size_t n = 0; n < p.size(); ++n) {
    id_sum_after += p.id[n];
    misplaced += d.owner_of_point({p.x[n], p.z[n]}) != d.rank();
    int i, k;
    s.cell_of({p.x[n], p.z[n]}, i, k);
    const long long cell = s.cell_gid(i, k);
    unsorted += cell < previous_cell || (cell == previous_cell && p.id[n] <= previous_id);
    previous_cell = cell, previous_id = p.id[n];
  }
  EXPECT_EQ(comm.sum(id_sum_after), id_sum);
  EXPECT_EQ(comm.sum(misplaced), 0);
  EXPECT_EQ(comm.sum(unsorted), 0);
  if (comm.size() > 1) {
    // the test moved particles across rank boundaries: some were sent
    long long moved = 0;
    for (std::size_t n = 0; n < p.size(); ++n) {
      int i, k;
      s.cell_of({p.x[n], p.z[n]}, i, k);
      moved += p.id[n] / 4 != s.cell_gid(i, k) &&
               d.owner_of_cell(static_cast<int>((p.id[n] / 4) % s.nx),
                               static_cast<int>((p.id[n] / 4) / s.nx)) != d.rank();
    }
    EXPECT_GT(comm.sum(moved), 0);
  }
}
