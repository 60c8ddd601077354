#pragma once
// The forces phase of the step on the fluid's state: gravity and viscosity -> u~, explicit, or
// implicit at the true boundaries of the solids and obstacles (doc/viscous.md).
#include <cstddef>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/solid_state.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/fluid/viscous_bodies.hpp"
#include "picdem/grid/field.hpp"

namespace picdem::fluid {

/// Explicit: gravity, then the explicit viscosity, then the walls.
void add_forces_explicit(const FluidConfig& cfg, double dt, const grid::Decomposition& d,
                         const grid::Halo& halo, FluidState& f);

/// Implicit: viscosity on u^n at the true boundaries of `bodies` (viscous_bodies of every solid of
/// the run, `solids`, ordered by id, then the obstacles; their free slip from
/// cfg.obstacle_free_slip), the solids' rigid velocities unknowns of it with `rigid_rows` (with
/// fluid/viscous_pressure_predictor on u + dt (g - grad p^n / rho), taken off after; `surface`:
/// the ghost fluid's, as for the projection), then gravity and the walls. Returns the viscous
/// loads by solid id (viscous_exchange; `owned`: this rank's solids). Collective.
ViscousExchange add_forces_implicit(const FluidConfig& cfg, std::vector<ViscousBody> bodies,
                                    const std::vector<core::SolidState>& solids,
                                    const std::vector<core::SolidState>& owned, bool rigid_rows,
                                    double dt, const SurfaceFractions* surface,
                                    const grid::Decomposition& d, const grid::Halo& halo,
                                    const core::Comm& comm, FluidState& f);

}  // namespace picdem::fluid
