// The density correction's displacement (density_correction.hpp).
#include "picdem/fluid/density_correction.hpp"

#include <algorithm>

#include "picdem/fluid/free_surface.hpp"

namespace picdem::fluid {

bool density_displacement(const FluidState& f, const geometry::CutCells* cut,
                          const FluidConfig& cfg, double relaxation,
                          const SurfaceFractions* surface, PressureSolver& solver,
                          const grid::Decomposition& d, const grid::Halo& halo,
                          const core::Comm& comm, grid::FaceField& dx, grid::FaceField& dz) {
  constexpr double cap = 0.5;  // |S - 1| taken at most: half a cell's particles per step
  grid::CellField source(d, grid::Stagger::Cell, 0.0);
  const bool mine = excess_area(f.occupancy, f.cells, cut, relaxation, cap, d, source);
  if (!comm.any(mine)) return false;
  FluidConfig unit = cfg;
  unit.rho = 1.0, unit.no_slip = false, unit.wall_no_slip = {};  // displacements free-slip
  for (auto& side : unit.open.side)  // inflows bring no displacement; outflows keep q = 0
    if (side.kind == OpenKind::Inflow) side.shape = InflowShape::Uniform, side.velocity = 0.0;
  grid::CellField q(d, grid::Stagger::Cell, 0.0);
  solver.solve(f.cells, f.apertures, dx, dz, {}, 1.0, unit, q, surface, &source);
  project(dx, dz, q, f.cells, f.apertures, 1.0, unit, surface);
  // A displacement of more than half a cell would skip the stencil: capped.
  const double most = 0.5 * d.spec().h;
  for (auto* g : {&dx, &dz}) {
    const auto b = g->storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) (*g)(i, k) = std::clamp((*g)(i, k), -most, most);
  }
  extend_displacement(f.cells, f.apertures, unit, d, halo, dx, dz);
  return true;
}

}  // namespace picdem::fluid
