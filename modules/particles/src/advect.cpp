#include <algorithm>
#include <cmath>

#include "picdem/core/timer.hpp"
#include "picdem/particles/motion.hpp"
#include "picdem/particles/transfer.hpp"
#include "stencil.hpp"

namespace picdem::particles {

double advect(ParticleSet& p, const ParticleConfig& config, const grid::FaceField& u,
              const grid::FaceField& w, const grid::GridSpec& s, double dt,
              const std::function<void(double& x, double& z)>& push_out) {
  core::ScopedTimer timer("particles: advect");
  // a position that would leave the tank is put back this far inside the wall
  const double gap = 1e-6 * s.h;
  const double x_lo = s.origin.x + gap, x_hi = s.origin.x + s.length() - gap;
  const double z_lo = s.origin.z + gap, z_hi = s.origin.z + s.height() - gap;
  const auto in_tank = [&](core::Vec2 q) {
    return core::Vec2{std::clamp(q.x, x_lo, x_hi), std::clamp(q.z, z_lo, z_hi)};
  };
  const detail::Axes ax_u = detail::axes(s, grid::Stagger::FaceX);
  const detail::Axes ax_w = detail::axes(s, grid::Stagger::FaceZ);
  const auto v = [&](core::Vec2 q) {
    const detail::Stencil su = detail::stencil(ax_u, q), sw = detail::stencil(ax_w, q);
    detail::check_in_storage(u, su, q);
    detail::check_in_storage(w, sw, q);
    return core::Vec2{detail::interpolate(u, su), detail::interpolate(w, sw)};
  };
  const bool rk3 = config.advection == AdvectionScheme::Rk3;
  double moved2 = 0.0;  // the largest |x^{n+1} - x^n|^2 the grid velocity gave
  for (std::size_t n = 0; n < p.size(); ++n) {
    const core::Vec2 x0{p.x[n], p.z[n]};
    const core::Vec2 k1 = v(x0);
    core::Vec2 x1;
    if (!rk3) {
      // midpoint: x^{n+1} = x + dt v(x + dt/2 v(x))
      const core::Vec2 k2 = v(in_tank(x0 + 0.5 * dt * k1));
      x1 = x0 + dt * k2;
    } else {
      // Ralston: k2 = v(x + dt/2 k1), k3 = v(x + 3 dt/4 k2), x^{n+1} = x + dt (2 k1 + 3 k2 + 4
      // k3)/9
      const core::Vec2 k2 = v(in_tank(x0 + 0.5 * dt * k1));
      const core::Vec2 k3 = v(in_tank(x0 + 0.75 * dt * k2));
      x1 = x0 + (dt / 9.0) * (2.0 * k1 + 3.0 * k2 + 4.0 * k3);
    }
    const core::Vec2 d = x1 - x0;
    moved2 = std::max(moved2, d.x * d.x + d.z * d.z);
    x1 = in_tank(x1);
    if (push_out) {
      push_out(x1.x, x1.z);
      x1 = in_tank(x1);
    }
    p.x[n] = x1.x;
    p.z[n] = x1.z;
  }
  return std::sqrt(moved2);
}

}  // namespace picdem::particles
