#include "picdem/particles/occupancy.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "picdem/grid/tent.hpp"
#include "stencil.hpp"

namespace picdem::particles {

namespace {

/// S summed over the owned + halo cells -> the occupancy (owned, then forwarded); the count
/// made valid on its halo.
void finish(const grid::Decomposition& d, const grid::Halo& halo, int particles_per_cell,
            grid::CellField& S, grid::GridArray<int>* count) {
  const auto& spec = d.spec();
  if (count) {
    halo.reverse_add(*count);
    halo.forward(*count);
  }
  halo.reverse_add(S);
  const auto own = d.owned_cells();
  std::vector<double> mx(static_cast<std::size_t>(own.nx()));  // the tent's share along x
  for (int i = own.i0; i < own.i1; ++i)
    mx[i - own.i0] = grid::tent_share(-(i + 0.5), spec.nx - (i + 0.5));
  for (int k = own.k0; k < own.k1; ++k) {
    const double mz = grid::tent_share(-(k + 0.5), spec.nz - (k + 0.5));
    for (int i = own.i0; i < own.i1; ++i) S(i, k) /= particles_per_cell * mx[i - own.i0] * mz;
  }
  halo.forward(S);
}

// W = (1 - |dx|)(1 - |dz|) on the four centres around the particle (stencil st); the centres
// outside the storage (beyond a wall) are left out.
inline void add_tent(const detail::Stencil& st, grid::CellField& S) {
  const double wx[2] = {1.0 - st.fx, st.fx}, wz[2] = {1.0 - st.fz, st.fz};
  const core::IndexBox& box = S.storage();
  if (st.i >= box.i0 && st.i + 1 < box.i1 && st.k >= box.k0 && st.k + 1 < box.k1) {
    const std::size_t row = static_cast<std::size_t>(box.nx());
    double* s = S.data().data() + S.index(st.i, st.k);
    s[0] += wx[0] * wz[0];
    s[1] += wx[1] * wz[0];
    s[row] += wx[0] * wz[1];
    s[row + 1] += wx[1] * wz[1];
    return;
  }
  for (int b = 0; b < 2; ++b)
    for (int a = 0; a < 2; ++a)
      if (S.in_storage(st.i + a, st.k + b)) S(st.i + a, st.k + b) += wx[a] * wz[b];
}

}  // namespace

void occupancy(const ParticleSet& ps, const grid::Decomposition& d, const grid::Halo& halo,
               int particles_per_cell, grid::CellField& S, grid::GridArray<int>* count) {
  const auto& spec = d.spec();
  S.fill(0.0);
  if (count) count->fill(0);
  const detail::Axes centres = detail::cell_axes(spec);
  for (std::size_t n = 0; n < ps.x.size(); ++n) {
    add_tent(detail::unclamped_stencil(centres, {ps.x[n], ps.z[n]}), S);
    if (count) detail::count_one(ps, n, spec, *count);
  }
  finish(d, halo, particles_per_cell, S, count);
}

void occupancy(const ParticleSet& ps, const grid::Decomposition& d, const grid::Halo& halo,
               int particles_per_cell, grid::CellField& S, grid::GridArray<int>& count,
               const ParticleConfig& config, GridSums& sums) {
  using grid::Stagger;
  const auto& spec = d.spec();
  S.fill(0.0);
  count.fill(0);
  detail::reset(sums.u, d, Stagger::FaceX);
  detail::reset(sums.weight_u, d, Stagger::FaceX);
  detail::reset(sums.w, d, Stagger::FaceZ);
  detail::reset(sums.weight_w, d, Stagger::FaceZ);
  const detail::Axes centres = detail::cell_axes(spec);
  const detail::Axes ax_u = detail::axes(spec, Stagger::FaceX);
  const detail::Axes ax_w = detail::axes(spec, Stagger::FaceZ);
  if (!detail::shared_lattice(centres, ax_u, ax_w))  // never for the axes of one GridSpec
    throw std::logic_error("particles::occupancy: the cell and face lattices differ");
  const bool apic = config.transfer == TransferScheme::Apic;
  const std::size_t row_u = static_cast<std::size_t>(sums.u.storage().nx());
  const std::size_t row_w = static_cast<std::size_t>(sums.w.storage().nx());
  double *mu = sums.u.data().data(), *wu = sums.weight_u.data().data();
  double *mw = sums.w.data().data(), *ww = sums.weight_w.data().data();
  const double h = spec.h;
  for (std::size_t n = 0; n < ps.x.size(); ++n) {
    const core::Vec2 pos{ps.x[n], ps.z[n]};
    detail::Stencil sc, su, sw;
    detail::three_stencils(centres, ax_u, ax_w, pos, sc, su, sw);
    add_tent(sc, S);
    detail::count_one(ps, n, spec, count);
    // P2G's pass (transfer.cpp, scatter)
    detail::check_in_storage(sums.u, su, pos);
    detail::check_in_storage(sums.w, sw, pos);
    double gxu = 0.0, gzu = 0.0, gxw = 0.0, gzw = 0.0;
    if (apic) gxu = ps.cxx[n] * h, gzu = ps.cxz[n] * h, gxw = ps.czx[n] * h, gzw = ps.czz[n] * h;
    detail::scatter_one(su, ps.u[n], gxu, gzu, mu, wu, sums.u.index(su.i, su.k), row_u);
    detail::scatter_one(sw, ps.w[n], gxw, gzw, mw, ww, sums.w.index(sw.i, sw.k), row_w);
  }
  finish(d, halo, particles_per_cell, S, &count);
}

}  // namespace picdem::particles
