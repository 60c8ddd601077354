#include "picdem/particles/transfer.hpp"

#include <algorithm>
#include <sstream>
#include <utility>

#include "picdem/core/timer.hpp"
#include "stencil.hpp"

namespace picdem::particles {

using grid::FaceField;
using grid::Stagger;

namespace {

/// Scatters both velocity components (with the APIC rows of C when `apic`) and their kernel
/// weights, in one pass over the particles.
void scatter(const ParticleSet& p, const grid::GridSpec& s, bool apic, FaceField& u, FaceField& w,
             FaceField& weight_u, FaceField& weight_w) {
  const std::size_t row_u = static_cast<std::size_t>(u.storage().nx());
  const std::size_t row_w = static_cast<std::size_t>(w.storage().nx());
  double *mu = u.data().data(), *wu = weight_u.data().data();
  double *mw = w.data().data(), *ww = weight_w.data().data();
  const double h = s.h;
  const detail::Axes ax_u = detail::axes(s, Stagger::FaceX), ax_w = detail::axes(s, Stagger::FaceZ);
  for (std::size_t n = 0; n < p.size(); ++n) {
    const core::Vec2 pos{p.x[n], p.z[n]};
    const detail::Stencil su = detail::stencil(ax_u, pos), sw = detail::stencil(ax_w, pos);
    detail::check_in_storage(u, su, pos);
    detail::check_in_storage(w, sw, pos);
    double gxu = 0.0, gzu = 0.0, gxw = 0.0, gzw = 0.0;
    if (apic) gxu = p.cxx[n] * h, gzu = p.cxz[n] * h, gxw = p.czx[n] * h, gzw = p.czz[n] * h;
    detail::scatter_one(su, p.u[n], gxu, gzu, mu, wu, u.index(su.i, su.k), row_u);
    detail::scatter_one(sw, p.w[n], gxw, gzw, mw, ww, w.index(sw.i, sw.k), row_w);
  }
}

/// u_f = momentum_f / m_f on the owned faces; faces without weight get u = 0, m = 0.
void divide(FaceField& u, FaceField& weight) {
  const core::IndexBox b = u.owned();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) {
      double& m = weight(i, k);
      if (m > 0.0) {
        u(i, k) /= m;
      } else {
        u(i, k) = 0.0;
        m = 0.0;
      }
    }
}

// The sums reverse-added to the owners, divided, forwarded.
void exchange_and_divide(const grid::Halo& halo, FaceField& u, FaceField& w, FaceField& weight_u,
                         FaceField& weight_w) {
  halo.reverse_add_all({&u, &weight_u, &w, &weight_w});  // one message per neighbour
  divide(u, weight_u);
  divide(w, weight_w);
  halo.forward_all({&u, &weight_u, &w, &weight_w});
}

}  // namespace

void to_grid(const ParticleSet& p, const grid::Decomposition& d, const grid::Halo& halo,
             const ParticleConfig& config, FaceField& u, FaceField& w, FaceField& weight_u,
             FaceField& weight_w) {
  core::ScopedTimer timer("particles: to_grid");
  detail::reset(u, d, Stagger::FaceX);
  detail::reset(weight_u, d, Stagger::FaceX);
  detail::reset(w, d, Stagger::FaceZ);
  detail::reset(weight_w, d, Stagger::FaceZ);
  scatter(p, d.spec(), config.transfer == TransferScheme::Apic, u, w, weight_u, weight_w);
  exchange_and_divide(halo, u, w, weight_u, weight_w);
}

void to_grid(GridSums& sums, const grid::Halo& halo, FaceField& u, FaceField& w,
             FaceField& weight_u, FaceField& weight_w) {
  core::ScopedTimer timer("particles: to_grid from sums");
  std::swap(sums.u, u), std::swap(sums.w, w);
  std::swap(sums.weight_u, weight_u), std::swap(sums.weight_w, weight_w);
  exchange_and_divide(halo, u, w, weight_u, weight_w);
}

void count_per_cell(const ParticleSet& p, const grid::Halo& halo, grid::GridArray<int>& count) {
  if (p.spec.nx <= 0 || p.spec.nz <= 0 || p.spec.h <= 0.0)
    throw core::SolverError(
        "count_per_cell: the particle set has no grid (ParticleSet::spec is unset; seed() sets "
        "it, a set read from a checkpoint must set it or use the overload taking a GridSpec)");
  count_per_cell(p, p.spec, halo, count);
}

void count_per_cell(const ParticleSet& p, const grid::GridSpec& s, const grid::Halo& halo,
                    grid::GridArray<int>& count) {
  count.fill(0);
  for (std::size_t n = 0; n < p.size(); ++n) detail::count_one(p, n, s, count);
  halo.reverse_add(count);
  halo.forward(count);
}

void from_grid(ParticleSet& p, const ParticleConfig& config, const FaceField& u_old,
               const FaceField& w_old, const FaceField& u_new, const FaceField& w_new,
               const grid::GridSpec& s) {
  core::ScopedTimer timer("particles: from_grid");
  const double h = s.h;
  const detail::Axes ax_u = detail::axes(s, Stagger::FaceX), ax_w = detail::axes(s, Stagger::FaceZ);
  if (config.transfer == TransferScheme::Apic) {
    for (std::size_t n = 0; n < p.size(); ++n) {
      const core::Vec2 pos{p.x[n], p.z[n]};
      const detail::Stencil su = detail::stencil(ax_u, pos);
      const detail::Stencil sw = detail::stencil(ax_w, pos);
      detail::check_in_storage(u_new, su, pos);
      detail::check_in_storage(w_new, sw, pos);
      // APIC: v_p = u_new(x_c), C_p = grad u_new(x_c) at the kernel centre x_c (stencil.hpp)
      p.u[n] = detail::interpolate_at_centre(u_new, su, h, p.cxx[n], p.cxz[n]);
      p.w[n] = detail::interpolate_at_centre(w_new, sw, h, p.czx[n], p.czz[n]);
    }
    return;
  }
  const double r = config.flip_ratio;
  for (std::size_t n = 0; n < p.size(); ++n) {
    const core::Vec2 pos{p.x[n], p.z[n]};
    const detail::Stencil su = detail::stencil(ax_u, pos);
    const detail::Stencil sw = detail::stencil(ax_w, pos);
    detail::check_in_storage(u_new, su, pos);
    detail::check_in_storage(u_old, su, pos);
    detail::check_in_storage(w_new, sw, pos);
    detail::check_in_storage(w_old, sw, pos);
    const double un = detail::interpolate(u_new, su), uo = detail::interpolate(u_old, su);
    const double wn = detail::interpolate(w_new, sw), wo = detail::interpolate(w_old, sw);
    // v_p = r (v_p + u_new(x_p) - u_old(x_p)) + (1 - r) u_new(x_p)
    p.u[n] = r * (p.u[n] + un - uo) + (1.0 - r) * un;
    p.w[n] = r * (p.w[n] + wn - wo) + (1.0 - r) * wn;
  }
}

core::Vec2 sample(const FaceField& u, const FaceField& w, const grid::GridSpec& s, core::Vec2 p) {
  const detail::Stencil su = detail::stencil(s, Stagger::FaceX, p);
  const detail::Stencil sw = detail::stencil(s, Stagger::FaceZ, p);
  detail::check_in_storage(u, su, p);
  detail::check_in_storage(w, sw, p);
  return {detail::interpolate(u, su), detail::interpolate(w, sw)};
}

core::Vec2 sample_with_gradient(const FaceField& u, const FaceField& w, const grid::GridSpec& s,
                                core::Vec2 p, double (&c)[4]) {
  const detail::Stencil su = detail::stencil(s, Stagger::FaceX, p);
  const detail::Stencil sw = detail::stencil(s, Stagger::FaceZ, p);
  detail::check_in_storage(u, su, p);
  detail::check_in_storage(w, sw, p);
  const double vx = detail::interpolate_at_centre(u, su, s.h, c[0], c[1]);
  const double vz = detail::interpolate_at_centre(w, sw, s.h, c[2], c[3]);
  return {vx, vz};
}

}  // namespace picdem::particles
