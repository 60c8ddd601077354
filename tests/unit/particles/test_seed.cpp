// Seeding on 1, 2, 3 ranks: the union of the ranks' particles equals the single-rank seeding
// bit for bit, ids are unique, every particle lies in an owned cell, and the count is
// per_cell_1d^2 times the number of cells whose centre is inside.
#include <gtest/gtest.h>

#include "particle_testing.hpp"
#include "picdem/core/error.hpp"
#include "picdem/particles/particles.hpp"

using namespace picdem;
using namespace picdem::particles;

namespace {
grid::GridSpec tank() {
  grid::GridSpec s;
  s.nx = 23, s.nz = 17, s.h = 0.1, s.origin = {0.3, -0.2};
  return s;
}
// a disc plus a strip: cells whose centre lies in it are seeded
bool inside(core::Vec2 p) {
  const double dx = p.x - 1.2, dz = p.z - 0.6;
  return dx * dx + dz * dz < 0.36 || p.z < 0.1;
}
}  // namespace

TEST(Seed, SameParticlesWhateverTheRankCount) {
  ParticleConfig c;
  c.per_cell_1d = 3;
  c.jitter = 0.8;
  c.max_per_cell = 9;
  const grid::GridSpec s = tank();
  core::Comm comm;
  grid::Decomposition d(s, comm, required_halo(c));
  const ParticleSet p = seed(d, c, inside);
  const auto all = ptest::gather_all(p, comm);

  grid::Decomposition one(s, ptest::self_comm(), required_halo(c));
  const auto ref = ptest::gather_all(seed(one, c, inside), ptest::self_comm());
  long long cells_inside = 0;
  for (int k = 0; k < s.nz; ++k)
    for (int i = 0; i < s.nx; ++i) cells_inside += inside(s.position(grid::Stagger::Cell, i, k));
  ASSERT_EQ(static_cast<long long>(ref.size()), 9 * cells_inside);
  ASSERT_EQ(all.size(), ref.size());
  for (std::size_t n = 0; n < ref.size(); ++n) {
    EXPECT_EQ(all[n].id, ref[n].id);
    EXPECT_EQ(all[n].x, ref[n].x);
    EXPECT_EQ(all[n].z, ref[n].z);
    if (n > 0) {
      EXPECT_LT(all[n - 1].id, all[n].id);  // unique
    }
  }
  for (std::size_t n = 0; n < p.size(); ++n) {
    int i, k;
    s.cell_of({p.x[n], p.z[n]}, i, k);
    EXPECT_TRUE(d.owned_cells().contains(i, k));
    EXPECT_EQ(p.id[n] / 9, s.cell_gid(i, k));  // the id names the cell it was seeded in
  }
}

TEST(Seed, ParametersAreValidated) {
  core::ParamSchema schema;
  declare_parameters(schema);
  const ParticleConfig c = config_from(core::read_case_text(
      "transfer: {scheme: apic}\nadvection: {scheme: rk3}\nparticles: {per_cell_1d: 3, "
      "max_per_cell: 12}\n",
      "test", {}, schema));
  EXPECT_EQ(c.transfer, TransferScheme::Apic);
  EXPECT_EQ(c.advection, AdvectionScheme::Rk3);
  EXPECT_EQ(c.per_cell_1d, 3);
  EXPECT_EQ(c.max_per_cell, 12);
  EXPECT_DOUBLE_EQ(c.flip_ratio, 0.95);
  try {
    core::read_case_text("particles: {min_per_cell: 9, max_per_cell: 8}\n", "test", {}, schema);
    FAIL() << "min_per_cell > max_per_cell accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("particles/min_per_cell"), std::string::npos) << e.what();
  }
  EXPECT_THROW(core::read_case_text("transfer: {scheme: mpm}\n", "test", {}, schema),
               core::InputError);
  EXPECT_THROW(core::read_case_text("transfer: {flip_ratio: 1.5}\n", "test", {}, schema),
               core::InputError);
}
