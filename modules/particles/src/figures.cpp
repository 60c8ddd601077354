#include "picdem/particles/figures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace picdem::particles {

double max_speed(const ParticleSet& P, const core::Comm& comm) {
  double vmax = 0.0;
  for (std::size_t n = 0; n < P.x.size(); ++n)
    vmax = std::max(vmax, std::sqrt(P.u[n] * P.u[n] + P.w[n] * P.w[n]));
  return comm.max(vmax);
}

LocalFigures local_figures(const ParticleSet& P, double mass) {
  LocalFigures f;
  f.front = -std::numeric_limits<double>::infinity();
  for (std::size_t n = 0; n < P.x.size(); ++n) {
    const double v2 = P.u[n] * P.u[n] + P.w[n] * P.w[n];
    f.kinetic_energy += 0.5 * mass * v2;
    f.front = std::max(f.front, P.x[n]);
    f.max_speed = std::max(f.max_speed, std::sqrt(v2));
    f.finite = f.finite && std::isfinite(v2) && std::isfinite(P.x[n]) && std::isfinite(P.z[n]);
  }
  return f;
}

bool near_particles(const grid::GridArray<int>& count, const grid::GridSpec& spec,
                    core::Vec2 centre, double reach) {
  int i0, k0, i1, k1;
  spec.cell_of({centre.x - reach, centre.z - reach}, i0, k0);
  spec.cell_of({centre.x + reach, centre.z + reach}, i1, k1);
  i0 = std::max(i0, 0), k0 = std::max(k0, 0);  // cells of the grid only
  i1 = std::min(i1, spec.nx - 1), k1 = std::min(k1, spec.nz - 1);
  for (int k = k0; k <= k1; ++k)
    for (int i = i0; i <= i1; ++i)
      if (!count.in_storage(i, k) || count(i, k) > 0) return true;
  return false;
}

}  // namespace picdem::particles
