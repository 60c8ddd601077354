#include "picdem/particles/occupancy.hpp"

#include <cmath>

#include "stencil.hpp"

namespace picdem::particles {

namespace {
// Mass of the 1D tent of half-width 1 centred at c (in cell units) that lies in [0, n].
double tent_mass_inside(double c, double n) {
  auto cdf = [](double t) {  // integral of the tent from -1 to t
    if (t <= -1) return 0.0;
    if (t >= 1) return 1.0;
    return t <= 0 ? 0.5 * (1 + t) * (1 + t) : 1.0 - 0.5 * (1 - t) * (1 - t);
  };
  return cdf(n - c) - cdf(0.0 - c);
}
}  // namespace

void occupancy(const ParticleSet& ps, const grid::Decomposition& d, const grid::Halo& halo,
               int particles_per_cell, grid::CellField& S, grid::GridArray<int>* count) {
  const auto& spec = d.spec();
  S.fill(0.0);
  if (count) count->fill(0);
  const detail::Axes centres = detail::cell_axes(spec);
  for (std::size_t n = 0; n < ps.x.size(); ++n) {
    const detail::Stencil st = detail::unclamped_stencil(centres, {ps.x[n], ps.z[n]});
    // W = (1 - |dx|)(1 - |dz|) on the four surrounding centres
    const double wx[2] = {1.0 - st.fx, st.fx}, wz[2] = {1.0 - st.fz, st.fz};
    for (int b = 0; b < 2; ++b)
      for (int a = 0; a < 2; ++a)
        if (S.in_storage(st.i + a, st.k + b)) S(st.i + a, st.k + b) += wx[a] * wz[b];
    if (count) detail::count_one(ps, n, spec, *count);
  }
  if (count) {
    halo.reverse_add(*count);
    halo.forward(*count);
  }
  halo.reverse_add(S);
  const auto own = d.owned_cells();
  for (int k = own.k0; k < own.k1; ++k) {
    const double mz = tent_mass_inside(k + 0.5, spec.nz);
    for (int i = own.i0; i < own.i1; ++i)
      S(i, k) /= particles_per_cell * tent_mass_inside(i + 0.5, spec.nx) * mz;
  }
  halo.forward(S);
}

}  // namespace picdem::particles
