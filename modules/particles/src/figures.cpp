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

}  // namespace picdem::particles
