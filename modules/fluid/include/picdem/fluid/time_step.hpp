#pragma once
// The step's time step (time/*, doc/coupling.md): the CFL bound on the grid's face velocities and
// on a speed the caller adds (the particles' or the solids' surfaces', time/cfl_speed), the
// explicit viscosity's stability limit, dt_max; a collapse below dt_min is a blown-up run.
#include "picdem/core/comm.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/fluid_state.hpp"

namespace picdem::fluid {

/// The rule's settings: the cell size and time/cfl, time/dt_max, time/dt_min, time/end.
struct TimeStepLimits {
  double h = 0.0;
  double cfl = 0.5, dt_max = 0.0, dt_min = 0.0, t_end = 0.0;
};

/// dt = min(dt_max, cfl h / max|u|, cfl h / speed, viscous_time_limit(cfg)); dt_max without water
/// (fluid: nullptr). Throws core::SolverError when dt falls below dt_min before time/end (t, step:
/// the step's start, named in the message). Collective.
double choose_time_step(const TimeStepLimits& limits, const FluidConfig& cfg, double t,
                        long long step, const FluidState* fluid, double speed,
                        const core::Comm& comm);

}  // namespace picdem::fluid
