// Reseeding on 1, 2, 3 ranks: after cells were emptied and overfilled, every cell holds at most
// max_per_cell particles and every interior fluid cell at least min_per_cell; cells at the free
// surface are left alone; ids stay unique; the result equals the single-rank one (positions bit
// for bit, velocities to 1e-15).
#include <gtest/gtest.h>

#include <algorithm>

#include "particle_testing.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/rng.hpp"
#include "picdem/particles/particles.hpp"

using namespace picdem;
using namespace picdem::particles;
using grid::Stagger;

namespace {

grid::GridSpec tank() {
  grid::GridSpec s;
  s.nx = 24, s.nz = 18, s.h = 0.05, s.origin = {0.0, 0.0};
  return s;
}

constexpr double kSurface = 0.6;  // water below, air above
constexpr int kMin = 3, kMax = 6;

bool emptied(long long gid) {
  return gid % 5 == 0;
}
bool overfilled(long long gid) {
  return gid % 7 == 1;
}

/// A water column whose cells gid % 5 == 0 lost their particles and gid % 7 == 1 got 5 extra.
ParticleSet prepare(const grid::Decomposition& d, const ParticleConfig& c) {
  const grid::GridSpec& s = d.spec();
  const ParticleSet seeded = seed(d, c, [](core::Vec2 x) { return x.z < kSurface; });
  ParticleSet p;
  p.spec = s;
  const double zero[4] = {0.0, 0.0, 0.0, 0.0};
  for (std::size_t n = 0; n < seeded.size(); ++n) {
    const long long gid = seeded.id[n] / 4;
    if (!emptied(gid)) p.push_back_from(seeded, n);
    if (overfilled(gid) && seeded.id[n] % 4 == 0)
      for (int m = 1; m <= 5; ++m)
        p.push_back(1000000 + 10 * seeded.id[n] + m,
                    {seeded.x[n] + 0.01 * m * s.h, seeded.z[n] + 0.013 * m * s.h}, {0.0, 0.0},
                    zero);
  }
  return p;
}

struct Result {
  ParticleSet p;
  grid::GridArray<int> count;
  grid::GridArray<signed char> state;
};

Result run(const grid::Decomposition& d, const ParticleConfig& c, long long step) {
  const grid::GridSpec& s = d.spec();
  grid::Halo halo(d);
  Result r{prepare(d, c), grid::GridArray<int>(d, Stagger::Cell),
           grid::GridArray<signed char>(d, Stagger::Cell)};
  migrate(r.p, d);
  count_per_cell(r.p, halo, r.count);
  const core::IndexBox b = r.state.storage();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) {
      const bool water = s.position(Stagger::Cell, i, k).z < kSurface;
      const bool solid = i >= 18 && i < 20 && k < 4;  // a solid block on the floor
      r.state(i, k) = static_cast<signed char>(solid   ? grid::CellState::Solid
                                               : water ? grid::CellState::Fluid
                                                       : grid::CellState::Air);
    }
  grid::FaceField u(d, Stagger::FaceX), w(d, Stagger::FaceZ);
  for (auto* g : {&u, &w}) {
    const core::IndexBox fb = g->storage();
    for (int k = fb.k0; k < fb.k1; ++k)
      for (int i = fb.i0; i < fb.i1; ++i) {
        const core::Vec2 x = s.position(g->stagger(), i, k);
        (*g)(i, k) = g == &u ? 0.5 + x.z : -0.3 * x.x;
      }
  }
  // the solid also covers half of the fluid cells i = 17, k < 4 (cut cells)
  const core::Vec2 solid_lo{0.875, 0.0}, solid_hi{1.0, 0.2};
  reseed(r.p, c, d, r.count, r.state, u, w, step,
         [&](core::Vec2 x) { return x.x >= solid_lo.x && x.x <= solid_hi.x && x.z <= solid_hi.z; });
  count_per_cell(r.p, halo, r.count);
  return r;
}

}  // namespace

TEST(Reseed, KeepsCountsInBoundsIndependentlyOfRanks) {
  const grid::GridSpec s = tank();
  ParticleConfig c;
  c.min_per_cell = kMin;
  c.max_per_cell = kMax;
  c.transfer = TransferScheme::Apic;
  core::Comm comm;
  const long long step = 17;
  grid::Decomposition d(s, comm, required_halo(c));
  const Result r = run(d, c, step);

  long long above = 0, below = 0, surface_changed = 0, interior_fixed = 0, removed_cells = 0;
  const core::IndexBox o = d.owned_cells();
  for (int k = o.k0; k < o.k1; ++k)
    for (int i = o.i0; i < o.i1; ++i) {
      const int n = r.count(i, k);
      const long long gid = s.cell_gid(i, k);
      above += n > kMax;
      const bool fluid = r.state(i, k) == static_cast<signed char>(grid::CellState::Fluid);
      const bool surface = fluid && k + 1 < s.nz &&
                           r.state(i, k + 1) == static_cast<signed char>(grid::CellState::Air);
      if (fluid && !surface) {
        below += n < kMin;
        interior_fixed += emptied(gid) && n == kMin;
      }
      if (surface && emptied(gid)) surface_changed += n != 0;  // left alone: still empty
      removed_cells += overfilled(gid) && !emptied(gid) && fluid && n == kMax;
    }
  EXPECT_EQ(comm.sum(above), 0);
  EXPECT_EQ(comm.sum(below), 0);
  EXPECT_EQ(comm.sum(surface_changed), 0);
  EXPECT_GT(comm.sum(interior_fixed), 10);
  EXPECT_GT(comm.sum(removed_cells), 10);

  const auto all = ptest::gather_all(r.p, comm);
  grid::Decomposition one(s, ptest::self_comm(), required_halo(c));
  const auto ref = ptest::gather_all(run(one, c, step).p, ptest::self_comm());
  ASSERT_EQ(all.size(), ref.size());
  long long added = 0;
  for (std::size_t n = 0; n < all.size(); ++n) {
    EXPECT_EQ(all[n].id, ref[n].id);
    EXPECT_EQ(all[n].x, ref[n].x);
    EXPECT_EQ(all[n].z, ref[n].z);
    EXPECT_NEAR(all[n].u, ref[n].u, 1e-15);
    EXPECT_NEAR(all[n].w, ref[n].w, 1e-15);
    if (n > 0) {
      EXPECT_LT(all[n - 1].id, all[n].id);
    }
    if (all[n].id >= first_reseed_id(s, c) && all[n].id < 1000000) {  // not the extras
      ++added;
      // new particles carry the grid velocity u = 0.5 + z, w = -0.3 x, sampled as APIC's G2P
      // samples it: at the kernel centre, which in the half cell next to a wall is the particle
      // moved onto the outermost row of samples (u's rows at z = h/2 .. H - h/2, w's columns at
      // x = h/2 .. L - h/2)
      const double half = 0.5 * s.h;
      const double zc = std::clamp(all[n].z, half, s.height() - half);
      const double xc = std::clamp(all[n].x, half, s.length() - half);
      EXPECT_NEAR(all[n].u, 0.5 + zc, 1e-14);
      EXPECT_NEAR(all[n].w, -0.3 * xc, 1e-14);
      // and are never inside the solid block
      EXPECT_FALSE(all[n].x >= 0.875 && all[n].x <= 1.0 && all[n].z <= 0.2);
    }
  }
  EXPECT_GT(added, 30);
}

// min_per_cell 0 turns reseeding off, trimming included: the overfilled cells keep their
// particles (issue 14: the cylinder dam breaks run without reseeding and trimming at
// max_per_cell removed 0.55% of their particles by 0.6 s at h = 0.5 mm).
TEST(Reseed, OffAddsAndRemovesNothing) {
  const grid::GridSpec s = tank();
  ParticleConfig c;
  c.min_per_cell = 0;
  c.max_per_cell = kMax;
  core::Comm comm;
  grid::Decomposition d(s, comm, required_halo(c));
  const long long before = comm.sum(static_cast<long long>(prepare(d, c).size()));
  const Result r = run(d, c, 17);
  long long above = 0;
  const core::IndexBox o = d.owned_cells();
  for (int k = o.k0; k < o.k1; ++k)
    for (int i = o.i0; i < o.i1; ++i) above += r.count(i, k) > kMax;
  EXPECT_GT(comm.sum(above), 10);  // the overfilled cells kept their particles
  EXPECT_EQ(comm.sum(static_cast<long long>(r.p.size())), before);
  EXPECT_FALSE(comm.any(reseed_changes(c, d, r.count, r.state)));
}

TEST(Reseed, RejectsStaleCounts) {
  const grid::GridSpec s = tank();
  ParticleConfig c;
  core::Comm comm;
  grid::Decomposition d(s, comm, required_halo(c));
  ParticleSet p = seed(d, c, [](core::Vec2) { return true; });
  grid::GridArray<int> count(d, Stagger::Cell, 3);  // not what the cells hold (4)
  grid::GridArray<signed char> state(d, Stagger::Cell, 1);
  grid::FaceField u(d, Stagger::FaceX), w(d, Stagger::FaceZ);
  EXPECT_THROW(reseed(p, c, d, count, state, u, w, 0), core::SolverError);
}
