#pragma once
// The density correction's displacement (doc/coupling.md): particles crowded above the bulk
// density (S > 1), or thinned inside the water, are moved by d = -grad q, with -L_E q = their
// excess area (free_surface.hpp: excess_area), so that the divergence of the displacement is that
// excess. The caller moves the particles by it (positions only).
#include "picdem/core/comm.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/grid/field.hpp"

namespace picdem::fluid {

/// The displacement (dx, dz) of free_surface/density_correction = `relaxation` from the fluid's
/// occupancy, cells and apertures: solids are fixed walls of the Poisson equation (free-slip, no
/// inflow), q = 0 on the free surface (`surface`: the ghost fluid's, or null) and on the outflows;
/// |S - 1| taken at most 1/2, each component capped at half a cell, then extended beyond the fluid
/// faces (extend_displacement). `solver`: the correction's (Equation::DensityCorrection).
/// Returns false, with dx and dz untouched, when no rank has an excess. Collective.
bool density_displacement(const FluidState& fluid, const geometry::CutCells* cut,
                          const FluidConfig& cfg, double relaxation,
                          const SurfaceFractions* surface, PressureSolver& solver,
                          const grid::Decomposition& d, const grid::Halo& halo,
                          const core::Comm& comm, grid::FaceField& dx, grid::FaceField& dz);

}  // namespace picdem::fluid
