#pragma once
// The step's time step (time/*, doc/coupling.md): the CFL bound on the grid's face velocities and
// on what else moves in the step (the particles, or the solids' surfaces with the cut cells and
// rigid face velocities they carry: time/cfl_speed), the explicit viscosity's stability limit,
// dt_max, and how fast dt may grow from the last step; a collapse below dt_min is a blown-up run.
#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/fluid_state.hpp"

namespace picdem::fluid {

/// Declares the `time` section: time/end (also read by the time loop), the CFL number and the
/// source of its speed, dt_max, dt_growth and dt_min.
void declare_time_parameters(core::ParamSchema& schema);

/// The rule's settings: the cell size and time/cfl, time/dt_max, time/dt_min, time/end, and
/// time/dt_growth (dt <= growth * the last dt; 0: no bound); time/cfl_speed.
struct TimeStepLimits {
  double h = 0.0;
  double cfl = 0.5, dt_max = 0.0, dt_min = 0.0, t_end = 0.0;
  double growth = 0.0;
  /// time/cfl_speed particles: the added speed is the particles' (else the solids' surfaces)
  bool cfl_from_particles = true;
};

/// The time/ keys of a validated case and grid/cell_size. time/dt_growth bounds the grid rule
/// only: with time/cfl_speed particles growth is 0, as before issue 13.
TimeStepLimits time_step_limits_from(const core::Params& params);

/// What besides the grid moves in the step, at its start, from the module that owns it.
struct StepMotion {
  double speed = 0.0;  ///< the fastest particle (time/cfl_speed particles) or solid surface (grid)
  double accel = 0.0;  ///< the predicted change of `speed` per second (dem::SurfaceMotion)
};

/// dt = min(dt_max, cfl h / max|u|, the largest dt with (speed + accel dt) dt <= cfl h,
/// viscous_time_limit(cfg), growth * last_dt (last_dt <= 0, the first step: no such bound),
/// and under time/cfl_speed grid sqrt(cfl h / |g|), the water's fall from rest over the step);
/// dt_max without water (fluid: nullptr). Throws core::SolverError when dt falls below dt_min
/// before time/end (t, step: the step's start, named in the message). Collective.
double choose_time_step(const TimeStepLimits& limits, const FluidConfig& cfg, double t,
                        long long step, const FluidState* fluid, const StepMotion& motion,
                        double last_dt, const core::Comm& comm);

}  // namespace picdem::fluid
