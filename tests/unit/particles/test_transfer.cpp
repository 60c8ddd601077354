// Transfers on 1, 2, 3 ranks:
// - APIC P2G of particles carrying a linear field and its gradient gives the field at every
//   face with weight, wall strips included; G2P (APIC, FLIP, PIC) of linear grid fields gives
//   them at every particle (APIC: at its kernel centre, which is the particle away from the
//   walls), wall strips included (tolerance 1e-12 on values of order 1);
// - APIC's G2P then P2G, repeated 60 times on a random grid field, does not raise the grid's
//   kinetic energy (it rose up to 25% a cycle, through the wall rows, when G2P sampled at the particle);
// - P2G conserves momentum: sum_p v_p = sum_f m_f u_f and sum_p 1 = sum_f m_f (1e-12 relative);
// - the grid fields and the counts per cell equal the single-rank ones (1e-13);
// - the occupancy's pass with P2G's sums gives occupancy, count and to_grid bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "particle_testing.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/rng.hpp"
#include "picdem/particles/occupancy.hpp"
#include "picdem/particles/particles.hpp"

using namespace picdem;
using namespace picdem::particles;
using grid::FaceField;
using grid::Stagger;

namespace {

grid::GridSpec tank() {
  grid::GridSpec s;
  s.nx = 21, s.nz = 16, s.h = 0.05, s.origin = {-0.4, 0.1};
  return s;
}

// the linear field v(x) = a + G x
struct Linear {
  double a_u, gxx, gxz, a_w, gzx, gzz;
  double u(core::Vec2 p) const { return a_u + gxx * p.x + gxz * p.z; }
  double w(core::Vec2 p) const { return a_w + gzx * p.x + gzz * p.z; }
};
const Linear kField{0.3, 1.7, -0.6, -0.2, 0.9, -1.7};
const Linear kOld{-0.1, 0.4, 0.25, 0.5, -1.1, -0.4};

void fill_linear(FaceField& u, FaceField& w, const grid::GridSpec& s, const Linear& f) {
  for (auto* g : {&u, &w}) {
    const core::IndexBox b = g->storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) {
        const core::Vec2 x = s.position(g->stagger(), i, k);
        (*g)(i, k) = g == &u ? f.u(x) : f.w(x);
      }
  }
}

// The centre of the clamped kernel of a particle at p for samples of stagger st (stencil.hpp):
// p itself, except in the half cell next to a wall across the samples' half-cell offset, where it
// is p moved onto the outermost row of samples.
core::Vec2 kernel_centre(const grid::GridSpec& s, Stagger st, core::Vec2 p) {
  const double half = 0.5 * s.h;
  if (st == Stagger::FaceX)
    p.z = std::clamp(p.z, s.origin.z + half, s.origin.z + s.height() - half);
  else
    p.x = std::clamp(p.x, s.origin.x + half, s.origin.x + s.length() - half);
  return p;
}

double rnd(std::int64_t id, int what) {
  return core::uniform01(99, static_cast<std::uint64_t>(id), static_cast<std::uint64_t>(what)) -
         0.5;
}

struct Grid {
  FaceField u, w, mu, mw;
};

Grid p2g(const ParticleSet& p, const grid::Decomposition& d, const ParticleConfig& c) {
  grid::Halo halo(d);
  Grid g;
  to_grid(p, d, halo, c, g.u, g.w, g.mu, g.mw);
  return g;
}

}  // namespace

TEST(Transfer, ApicToGridReproducesLinearField) {
  ParticleConfig c;
  c.transfer = TransferScheme::Apic;
  const grid::GridSpec s = tank();
  core::Comm comm;
  grid::Decomposition d(s, comm, required_halo(c));
  // the lower 60% of the tank, wall strips included: there the clamped kernel engages and the
  // particle carries the field at its kernel centre (what APIC's G2P gives it)
  c.jitter = 1.0;
  ParticleSet p = seed(d, c, [&](core::Vec2 x) { return x.z < s.origin.z + 0.6 * s.height(); });
  for (std::size_t n = 0; n < p.size(); ++n) {
    const core::Vec2 x{p.x[n], p.z[n]};
    p.u[n] = kField.u(kernel_centre(s, Stagger::FaceX, x));
    p.w[n] = kField.w(kernel_centre(s, Stagger::FaceZ, x));
    p.cxx[n] = kField.gxx, p.cxz[n] = kField.gxz, p.czx[n] = kField.gzx, p.czz[n] = kField.gzz;
  }
  const Grid g = p2g(p, d, c);
  double err = 0.0;
  long long faces = 0;
  for (const FaceField* f : {&g.u, &g.w}) {
    const FaceField& m = f == &g.u ? g.mu : g.mw;
    const core::IndexBox b = f->owned();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) {
        if (m(i, k) <= 0.0) continue;
        const core::Vec2 x = s.position(f->stagger(), i, k);
        err = std::max(err, std::abs((*f)(i, k) - (f == &g.u ? kField.u(x) : kField.w(x))));
        ++faces;
      }
  }
  err = comm.max(err);
  faces = comm.sum(faces);
  if (comm.is_root())
    std::printf("APIC P2G linear field: max error %.3e over %lld faces\n", err, faces);
  EXPECT_GT(faces, 300);
  EXPECT_LT(err, 1e-12);
}

TEST(Transfer, FromGridReproducesLinearField) {
  const grid::GridSpec s = tank();
  core::Comm comm;
  for (const char* scheme : {"apic", "flip", "pic"}) {
    ParticleConfig c;
    c.transfer = scheme[0] == 'a' ? TransferScheme::Apic : TransferScheme::Flip;
    c.flip_ratio = scheme[0] == 'p' ? 0.0 : 0.95;
    c.jitter = 1.0;
    grid::Decomposition d(s, comm, required_halo(c));
    // every cell, wall strips included
    ParticleSet p = seed(d, c, [](core::Vec2) { return true; });
    for (std::size_t n = 0; n < p.size(); ++n) {
      const core::Vec2 x{p.x[n], p.z[n]};
      // FLIP: v = r (v + u_new - u_old) + (1 - r) u_new = u_new when v = u_old(x);
      // PIC ignores v
      p.u[n] = c.flip_ratio > 0 ? kOld.u(x) : rnd(p.id[n], 0);
      p.w[n] = c.flip_ratio > 0 ? kOld.w(x) : rnd(p.id[n], 1);
    }
    FaceField u_old(d, Stagger::FaceX), w_old(d, Stagger::FaceZ);
    FaceField u_new(d, Stagger::FaceX), w_new(d, Stagger::FaceZ);
    fill_linear(u_old, w_old, s, kOld);
    fill_linear(u_new, w_new, s, kField);
    from_grid(p, c, u_old, w_old, u_new, w_new, s);
    double err = 0.0, err_c = 0.0;
    const bool apic = c.transfer == TransferScheme::Apic;
    for (std::size_t n = 0; n < p.size(); ++n) {
      const core::Vec2 x{p.x[n], p.z[n]};
      const core::Vec2 xu = apic ? kernel_centre(s, Stagger::FaceX, x) : x;
      const core::Vec2 xw = apic ? kernel_centre(s, Stagger::FaceZ, x) : x;
      err = std::max({err, std::abs(p.u[n] - kField.u(xu)), std::abs(p.w[n] - kField.w(xw))});
      if (c.transfer == TransferScheme::Apic)
        err_c = std::max({err_c, std::abs(p.cxx[n] - kField.gxx), std::abs(p.cxz[n] - kField.gxz),
                          std::abs(p.czx[n] - kField.gzx), std::abs(p.czz[n] - kField.gzz)});
    }
    err = comm.max(err);
    err_c = comm.max(err_c);
    if (comm.is_root())
      std::printf("G2P %s linear field: max velocity error %.3e, gradient error %.3e\n", scheme,
                  err, err_c);
    EXPECT_LT(err, 1e-12) << scheme;
    EXPECT_LT(err_c, 1e-11) << scheme;
  }
}

TEST(Transfer, ApicCyclesDoNotRaiseTheGridsEnergy) {
  // A random grid field, particles in every cell (wall strips included), and 60 cycles of APIC's
  // G2P then P2G with no solve between: the grid's kinetic energy sum_f m_f u_f^2 must not rise
  // (APIC's transfers are dissipative). Sampling the value at the particle instead of its kernel
  // centre made P2G hand the outermost rows an extrapolated value: the energy then grew
  // 4.6e4-fold over these cycles, by up to 25% in one.
  const grid::GridSpec s = tank();
  core::Comm comm;
  ParticleConfig c;
  c.transfer = TransferScheme::Apic;
  c.jitter = 1.0;
  grid::Decomposition d(s, comm, required_halo(c));
  grid::Halo halo(d);
  ParticleSet p = seed(d, c, [](core::Vec2) { return true; });
  FaceField u(d, Stagger::FaceX), w(d, Stagger::FaceZ), mu, mw;
  for (auto* g : {&u, &w}) {
    const core::IndexBox b = g->storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i)
        (*g)(i, k) = rnd(static_cast<std::int64_t>(1000 * k + i), g == &u ? 6 : 7);
  }
  const auto energy = [&] {
    double e = 0.0;
    for (int pass = 0; pass < 2; ++pass) {
      const FaceField& f = pass == 0 ? u : w;
      const FaceField& m = pass == 0 ? mu : mw;
      const core::IndexBox b = f.owned();
      for (int k = b.k0; k < b.k1; ++k)
        for (int i = b.i0; i < b.i1; ++i) e += m(i, k) * f(i, k) * f(i, k);
    }
    return comm.sum(e);
  };
  double first = 0.0, last = 0.0, worst_rise = 0.0;
  for (int cycle = 0; cycle < 60; ++cycle) {
    from_grid(p, c, u, w, u, w, s);
    to_grid(p, d, halo, c, u, w, mu, mw);
    const double e = energy();
    if (cycle == 0) first = e;
    if (cycle > 0) worst_rise = std::max(worst_rise, e / last - 1.0);
    last = e;
  }
  if (comm.is_root())
    std::printf("APIC G2P/P2G cycles: grid energy %.4e after the first, %.4e after 60; largest "
                "rise in one cycle %.2e\n",
                first, last, worst_rise);
  EXPECT_GT(first, 0.0);
  EXPECT_LE(worst_rise, 1e-12);
  EXPECT_LE(last, first);
}

TEST(Transfer, ToGridConservesMomentum) {
  const grid::GridSpec s = tank();
  core::Comm comm;
  for (TransferScheme scheme : {TransferScheme::Flip, TransferScheme::Apic}) {
    ParticleConfig c;
    c.transfer = scheme;
    c.jitter = 1.0;
    grid::Decomposition d(s, comm, required_halo(c));
    ParticleSet p = seed(d, c, [](core::Vec2) { return true; });
    double pu = 0.0, pw = 0.0, scale = 0.0;
    for (std::size_t n = 0; n < p.size(); ++n) {
      p.u[n] = 2.0 * rnd(p.id[n], 0), p.w[n] = 2.0 * rnd(p.id[n], 1);
      if (scheme == TransferScheme::Apic) {
        p.cxx[n] = 40.0 * rnd(p.id[n], 2), p.cxz[n] = 40.0 * rnd(p.id[n], 3);
        p.czx[n] = 40.0 * rnd(p.id[n], 4), p.czz[n] = 40.0 * rnd(p.id[n], 5);
      }
      pu += p.u[n], pw += p.w[n], scale += std::abs(p.u[n]) + std::abs(p.w[n]);
    }
    const Grid g = p2g(p, d, c);
    double gu = 0.0, gw = 0.0, mu = 0.0, mw = 0.0;
    for (int pass = 0; pass < 2; ++pass) {
      const FaceField& f = pass == 0 ? g.u : g.w;
      const FaceField& m = pass == 0 ? g.mu : g.mw;
      const core::IndexBox b = f.owned();
      for (int k = b.k0; k < b.k1; ++k)
        for (int i = b.i0; i < b.i1; ++i) {
          (pass == 0 ? gu : gw) += m(i, k) * f(i, k);
          (pass == 0 ? mu : mw) += m(i, k);
        }
    }
    const double total = comm.sum(static_cast<double>(p.size()));
    pu = comm.sum(pu), pw = comm.sum(pw), scale = comm.sum(scale);
    gu = comm.sum(gu), gw = comm.sum(gw), mu = comm.sum(mu), mw = comm.sum(mw);
    const double err = std::max(std::abs(gu - pu), std::abs(gw - pw)) / scale;
    if (comm.is_root())
      std::printf(
          "P2G %s momentum: %zu ranks, relative error %.3e (sum |v_p| = %.1f), "
          "weight error %.3e\n",
          scheme == TransferScheme::Apic ? "apic" : "flip", static_cast<std::size_t>(comm.size()),
          err, scale, std::max(std::abs(mu - total), std::abs(mw - total)) / total);
    EXPECT_LT(err, 1e-12);
    EXPECT_NEAR(mu, total, 1e-12 * total);
    EXPECT_NEAR(mw, total, 1e-12 * total);
  }
}

TEST(Transfer, GridAndCountsMatchSingleRank) {
  const grid::GridSpec s = tank();
  core::Comm comm;
  ParticleConfig c;
  c.transfer = TransferScheme::Apic;
  const auto in_drop = [](core::Vec2 x) { return x.z < 0.4 || (x.x - 0.1) * (x.x - 0.1) < 0.02; };
  grid::Decomposition d(s, comm, required_halo(c));
  grid::Decomposition one(s, ptest::self_comm(), required_halo(c));
  ParticleSet p = seed(d, c, in_drop), q = seed(one, c, in_drop);
  for (ParticleSet* set : {&p, &q})
    for (std::size_t n = 0; n < set->size(); ++n) {
      const std::int64_t id = set->id[n];
      set->u[n] = rnd(id, 0), set->w[n] = rnd(id, 1), set->cxx[n] = rnd(id, 2);
      set->cxz[n] = rnd(id, 3), set->czx[n] = rnd(id, 4), set->czz[n] = rnd(id, 5);
    }
  const Grid g = p2g(p, d, c), r = p2g(q, one, c);
  double err = 0.0;
  for (int pass = 0; pass < 4; ++pass) {
    const FaceField& f = pass == 0 ? g.u : pass == 1 ? g.w : pass == 2 ? g.mu : g.mw;
    const FaceField& ref = pass == 0 ? r.u : pass == 1 ? r.w : pass == 2 ? r.mu : r.mw;
    // owned faces and the halo faces on the grid (forwarded)
    const core::IndexBox b = f.storage().intersect(s.extent(f.stagger()));
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) err = std::max(err, std::abs(f(i, k) - ref(i, k)));
  }
  EXPECT_LT(comm.max(err), 1e-13);

  grid::Halo halo(d), halo_one(one);
  grid::GridArray<int> count(d, Stagger::Cell), count_ref(one, Stagger::Cell);
  count_per_cell(p, halo, count);
  count_per_cell(q, halo_one, count_ref);
  const core::IndexBox b = count.storage().intersect(s.extent(Stagger::Cell));
  long long mismatches = 0, owned_total = 0;
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) mismatches += count(i, k) != count_ref(i, k);
  const core::IndexBox o = count.owned();
  for (int k = o.k0; k < o.k1; ++k)
    for (int i = o.i0; i < o.i1; ++i) owned_total += count(i, k);
  EXPECT_EQ(comm.sum(mismatches), 0);
  EXPECT_EQ(comm.sum(owned_total), static_cast<long long>(q.size()));
  ParticleSet bare;  // no grid attached: counting must refuse rather than guess
  EXPECT_THROW(count_per_cell(bare, halo, count), core::SolverError);
}

namespace {

template <class T>
bool same_bits(const grid::GridArray<T>& a, const grid::GridArray<T>& b) {
  return a.storage() == b.storage() && a.data().size() == b.data().size() &&
         std::memcmp(a.data().data(), b.data().data(), a.data().size() * sizeof(T)) == 0;
}

}  // namespace

TEST(Transfer, OccupancyPassWithSumsIsBitwiseOccupancyAndToGrid) {
  const grid::GridSpec s = tank();
  core::Comm comm;
  for (TransferScheme scheme : {TransferScheme::Flip, TransferScheme::Apic}) {
    ParticleConfig c;
    c.transfer = scheme;
    c.jitter = 1.0;  // particles in the wall strips, where P2G clamps its kernel
    const auto in_drop = [](core::Vec2 x) { return x.z < 0.4 || (x.x - 0.1) * (x.x - 0.1) < 0.02; };
    grid::Decomposition d(s, comm, required_halo(c));
    grid::Halo halo(d);
    ParticleSet p = seed(d, c, in_drop);
    GridSums sums;
    grid::CellField S_ref(d, Stagger::Cell), S(d, Stagger::Cell);
    grid::GridArray<int> count_ref(d, Stagger::Cell), count(d, Stagger::Cell);
    Grid g;
    long long differ = 0;
    for (int round = 0; round < 2; ++round) {  // the second reuses the sums' and fields' memory
      for (std::size_t n = 0; n < p.size(); ++n) {
        const std::int64_t id = p.id[n] + 1000 * round;
        p.u[n] = rnd(id, 0), p.w[n] = rnd(id, 1);
        if (scheme == TransferScheme::Apic)
          p.cxx[n] = 40 * rnd(id, 2), p.cxz[n] = 40 * rnd(id, 3), p.czx[n] = 40 * rnd(id, 4),
          p.czz[n] = 40 * rnd(id, 5);
      }
      const Grid ref = p2g(p, d, c);
      occupancy(p, d, halo, 4, S_ref, &count_ref);
      occupancy(p, d, halo, 4, S, count, c, sums);
      to_grid(sums, halo, g.u, g.w, g.mu, g.mw);
      differ += !same_bits(S, S_ref) + !same_bits(count, count_ref);
      differ += !same_bits(g.u, ref.u) + !same_bits(g.w, ref.w);
      differ += !same_bits(g.mu, ref.mu) + !same_bits(g.mw, ref.mw);
    }
    EXPECT_EQ(comm.sum(differ), 0) << (scheme == TransferScheme::Apic ? "apic" : "flip");
  }
}
