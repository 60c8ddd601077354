// The step's time step (time_step.hpp).
#include "picdem/fluid/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/fluid/viscous.hpp"

namespace picdem::fluid {

double choose_time_step(const TimeStepLimits& set, const FluidConfig& cfg, double t, long long step,
                        const FluidState* fluid, const StepMotion& motion, double last_dt,
                        const core::Comm& comm) {
  // The last step is not shortened to land on time/end: the run ends with the first step that
  // reaches it, so a run continued to a later end takes the steps of one run made to that end.
  const double dt_max = set.dt_max;
  if (!fluid) return dt_max;
  const double reach = set.cfl * set.h;  // the distance anything may move in one step
  double dt = std::min(dt_max, cfl_time_step(fluid->u, fluid->w, set.h, set.cfl, dt_max, comm));
  dt = std::min(dt, viscous_time_limit(cfg));  // explicit viscosity's stability
  const double s = motion.speed;
  if (motion.accel > 0.0)  // (s + a dt) dt = CFL h: dt = 2 CFL h / (s + sqrt(s^2 + 4 a CFL h))
    dt = std::min(dt, 2.0 * reach / (s + std::sqrt(s * s + 4.0 * motion.accel * reach)));
  else if (s > 0.0)
    dt = std::min(dt, reach / s);  // dt = CFL h / s
  if (set.growth > 0.0 && last_dt > 0.0) dt = std::min(dt, set.growth * last_dt);
  if (!(dt >= set.dt_min) && set.t_end - t > set.dt_min) {
    std::ostringstream m;
    m << "step " << step << " at t = " << t << " s: the time step fell to " << dt
      << " s (below time/dt_min): the flow has blown up";
    throw core::SolverError(m.str());
  }
  return dt;
}

}  // namespace picdem::fluid
