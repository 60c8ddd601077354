// The step's time step (time_step.hpp).
#include "picdem/fluid/time_step.hpp"

#include <algorithm>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/fluid/viscous.hpp"

namespace picdem::fluid {

double choose_time_step(const TimeStepLimits& set, const FluidConfig& cfg, double t, long long step,
                        const FluidState* fluid, double speed, const core::Comm& comm) {
  // The last step is not shortened to land on time/end: the run ends with the first step that
  // reaches it, so a run continued to a later end takes the steps of one run made to that end.
  const double dt_max = set.dt_max;
  if (!fluid) return dt_max;
  // time/cfl_speed particles: the particles may outrun the grid (FLIP): the fastest of either
  // sets the CFL limit. grid: the particles move with the grid's velocity (advect), so that sets
  // it, with the solids' surfaces, which move the cut cells (doc/coupling.md).
  const double h = set.h;
  double dt = std::min(dt_max, cfl_time_step(fluid->u, fluid->w, h, set.cfl, set.dt_max, comm));
  dt = std::min(dt, viscous_time_limit(cfg));  // explicit viscosity's stability
  if (speed > 0.0) dt = std::min(dt, set.cfl * h / speed);
  if (!(dt >= set.dt_min) && set.t_end - t > set.dt_min) {
    std::ostringstream m;
    m << "step " << step << " at t = " << t << " s: the time step fell to " << dt
      << " s (below time/dt_min): the flow has blown up";
    throw core::SolverError(m.str());
  }
  return dt;
}

}  // namespace picdem::fluid
