#pragma once
// The rows of forces.csv (doc/output.md) from the fluid's pressure loads on the solids
// (PressureSolver::solid_loads) and obstacles (fluid::obstacle_pressure_loads) and the viscous
// loads.
#include <vector>

#include "picdem/core/solid_state.hpp"
#include "picdem/coupling/simulation.hpp"
#include "viscous_bodies.hpp"

namespace picdem::coupling {

/// The rows of forces.csv: every solid of `solids` (by id; its pressure load from `pressure`,
/// zero when absent; viscous from `viscous`, zero when empty), then every obstacle
/// (`obstacles`, by index).
std::vector<BodyForces> body_forces(const std::vector<core::SolidState>& solids,
                                    const std::vector<core::SolidLoads>& pressure,
                                    const std::vector<core::SolidLoads>& obstacles,
                                    const ViscousExchange& viscous);

}  // namespace picdem::coupling
