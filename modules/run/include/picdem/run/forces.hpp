#pragma once
// The rows of forces.csv (doc/output.md): the fluid's loads of the last step on every solid and
// obstacle, from the step's loads (coupling::StepLoads) and the DEM's solids.
#include <cstdint>
#include <vector>

#include "picdem/core/vec2.hpp"
#include "picdem/coupling/simulation.hpp"

namespace picdem::run {

/// One row of forces.csv: the fluid's loads on a solid or obstacle over the last step, per unit
/// depth. Pressure: J p^{n+1} + F_q (eq. 6); viscous: fluid::ViscousExchange (zero with the
/// explicit scheme). Torques about the solid's centre of mass, an obstacle's about (0, 0). The
/// viscous force on the tank walls: fluid::FluidState::viscous_wall_force.
struct BodyForces {
  std::int64_t id = 0;                                 ///< solid id, or obstacle index
  bool obstacle = false;                               ///< a fixed obstacle
  core::Vec2 pressure, viscous;                        ///< [N/m]
  double torque_pressure = 0.0, torque_viscous = 0.0;  ///< [N m/m]
};

/// Collective: the fluid's loads of `sim`'s last step on every solid (by id), then every obstacle
/// (the rows of forces.csv).
std::vector<BodyForces> body_forces(const coupling::Simulation& sim);

}  // namespace picdem::run
