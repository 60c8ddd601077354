#include "picdem/fluid/fluid_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "picdem/grid/axis.hpp"

namespace picdem::fluid {

using grid::CellState;
using grid::Stagger;

FluidState::FluidState(const grid::Decomposition& d)
    : u(d, Stagger::FaceX),
      w(d, Stagger::FaceZ),
      u_old(u),
      w_old(w),
      weight_u(u),
      weight_w(w),
      u_valid(d, Stagger::FaceX, 0),
      w_valid(d, Stagger::FaceZ, 0),
      p(d, Stagger::Cell),
      cells(d, Stagger::Cell, static_cast<signed char>(CellState::Air)),
      occupancy(d, Stagger::Cell),
      phi(d, Stagger::Cell),
      apertures(open_apertures(d)),
      d_(&d) {}

double FluidState::pressure_at(core::Vec2 x) const {
  int i, k;
  d_->spec().cell_of(x, i, k);
  return d_->comm().sum(d_->owned_cells().contains(i, k) ? p(i, k) : 0.0);
}

core::Vec2 FluidState::wall_pressure_force(const FluidConfig& cfg) const {
  const auto& spec = d_->spec();
  const auto own = d_->owned_cells();
  const auto fluid = static_cast<signed char>(CellState::Fluid);
  const double h = spec.h, rho_g = cfg.rho * cfg.g.z;  // g.z < 0
  double fx = 0.0, fz = 0.0;
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) {
      if (cells(i, k) != fluid) continue;
      if (i == 0) fx += p(i, k) * h;
      if (i == spec.nx - 1) fx -= p(i, k) * h;
      if (k == 0) fz += (p(i, k) - 0.5 * h * rho_g) * h;
      if (k == spec.nz - 1) fz -= (p(i, k) + 0.5 * h * rho_g) * h;
    }
  return {d_->comm().sum(fx), d_->comm().sum(fz)};
}

double FluidState::max_grid_speed() const {
  grid::GridArray<signed char> vu(*d_, Stagger::FaceX, 0), vw(*d_, Stagger::FaceZ, 0);
  fluid_faces(cells, apertures, vu, vw);
  double m = 0.0;
  for (const grid::Axis a : grid::kAxes) {
    const grid::FaceField& vel = grid::along(a, u, w);
    const grid::GridArray<signed char>& valid = grid::along(a, vu, vw);
    const auto b = d_->owned(grid::face_stagger(a));
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i)
        if (valid(i, k)) m = std::max(m, std::abs(vel(i, k)));
  }
  return d_->comm().max(m);
}

double FluidState::surface_height(double x) const {
  const auto& spec = d_->spec();
  int i, k;
  spec.cell_of({x, spec.origin.z}, i, k);
  const auto own = d_->owned_cells();
  double best = -std::numeric_limits<double>::infinity();
  if (i >= own.i0 && i < own.i1)
    for (int kk = own.k0; kk < own.k1; ++kk) {
      const double below = occupancy(i, kk), above = occupancy(i, kk + 1);
      if (kk + 1 >= spec.nz || !(below > 0.5) || above > 0.5) continue;
      // S = 1/2 between the two centres, linearly
      const double z0 = spec.position(Stagger::Cell, i, kk).z;
      best = std::max(best, z0 + spec.h * (below - 0.5) / (below - above));
    }
  best = d_->comm().max(best);
  return std::isfinite(best) ? best : std::nan("");
}

FluidState redistributed(const FluidState& f, const grid::Decomposition& from,
                         const grid::Decomposition& to) {
  FluidState moved(to);
  // for_each_saved visits the same fields in the same order on both
  std::vector<const void*> sources;
  f.for_each_saved([&](const char*, const auto& field) { sources.push_back(&field); });
  std::size_t n = 0;
  moved.for_each_saved([&](const char*, auto& field) {
    using A = std::decay_t<decltype(field)>;
    field = grid::redistributed(*static_cast<const A*>(sources[n++]), from, to);
  });
  return moved;
}

}  // namespace picdem::fluid
