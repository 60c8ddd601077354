#include "picdem/particles/transfer.hpp"

#include <algorithm>
#include <sstream>

#include "picdem/core/timer.hpp"
#include "stencil.hpp"

namespace picdem::particles {

using grid::FaceField;
using grid::Stagger;

namespace {

/// Makes f a zeroed field of stagger s on d's storage, reusing its memory when it fits.
template <class T>
void reset(grid::GridArray<T>& f, const grid::Decomposition& d, Stagger s) {
  if (f.stagger() == s && f.storage() == d.storage(s) && f.owned() == d.owned(s))
    f.fill(T{});
  else
    f = grid::GridArray<T>(d, s, T{});
}

/// Scatters the component v (with the APIC row c_x, c_z when given) and the kernel weights.
void scatter(const ParticleSet& p, const grid::GridSpec& s, Stagger st,
             const std::vector<double>& v, const std::vector<double>* c_x,
             const std::vector<double>* c_z, FaceField& momentum, FaceField& weight) {
  const std::size_t row = static_cast<std::size_t>(momentum.storage().nx());
  double* m = momentum.data().data();
  double* wt = weight.data().data();
  const double h = s.h;
  const detail::Axes ax = detail::axes(s, st);
  for (std::size_t n = 0; n < p.size(); ++n) {
    const core::Vec2 pos{p.x[n], p.z[n]};
    detail::Stencil sten = detail::stencil(ax, pos);
    detail::check_in_storage(momentum, sten, pos);
    // kernel clamped to the grid's faces: its centre x_c is p moved onto the outermost row
    const double fx = std::clamp(sten.fx, 0.0, 1.0), fz = std::clamp(sten.fz, 0.0, 1.0);
    // N_f = (1 - |x_f - x_c| / h)(1 - |z_f - z_c| / h)
    const double w00 = (1.0 - fx) * (1.0 - fz), w10 = fx * (1.0 - fz);
    const double w01 = (1.0 - fx) * fz, w11 = fx * fz;
    // APIC: v_f = v_p + C (x_f - x_c); x_f - x_c = ((a - fx) h, (b - fz) h) for face (i+a, k+b)
    double gx = 0.0, gz = 0.0;
    if (c_x) gx = (*c_x)[n] * h, gz = (*c_z)[n] * h;
    const double v00 = v[n] - gx * fx - gz * fz;
    const double v10 = v00 + gx, v01 = v00 + gz, v11 = v00 + gx + gz;
    const std::size_t f = momentum.index(sten.i, sten.k);
    m[f] += w00 * v00;
    m[f + 1] += w10 * v10;
    m[f + row] += w01 * v01;
    m[f + row + 1] += w11 * v11;
    wt[f] += w00;
    wt[f + 1] += w10;
    wt[f + row] += w01;
    wt[f + row + 1] += w11;
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

}  // namespace

void to_grid(const ParticleSet& p, const grid::Decomposition& d, const grid::Halo& halo,
             const ParticleConfig& config, FaceField& u, FaceField& w, FaceField& weight_u,
             FaceField& weight_w) {
  core::ScopedTimer timer("particles: to_grid");
  reset(u, d, Stagger::FaceX);
  reset(weight_u, d, Stagger::FaceX);
  reset(w, d, Stagger::FaceZ);
  reset(weight_w, d, Stagger::FaceZ);
  const bool apic = config.transfer == TransferScheme::Apic;
  scatter(p, d.spec(), Stagger::FaceX, p.u, apic ? &p.cxx : nullptr, apic ? &p.cxz : nullptr, u,
          weight_u);
  scatter(p, d.spec(), Stagger::FaceZ, p.w, apic ? &p.czx : nullptr, apic ? &p.czz : nullptr, w,
          weight_w);
  for (FaceField* f : {&u, &weight_u, &w, &weight_w}) halo.reverse_add(*f);
  divide(u, weight_u);
  divide(w, weight_w);
  for (FaceField* f : {&u, &weight_u, &w, &weight_w}) halo.forward(*f);
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
      // APIC: v_p = u_new(x_p), C_p = grad u_new(x_p)
      p.u[n] = detail::interpolate(u_new, su, h, p.cxx[n], p.cxz[n]);
      p.w[n] = detail::interpolate(w_new, sw, h, p.czx[n], p.czz[n]);
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
  const double vx = detail::interpolate(u, su, s.h, c[0], c[1]);
  const double vz = detail::interpolate(w, sw, s.h, c[2], c[3]);
  return {vx, vz};
}

}  // namespace picdem::particles
