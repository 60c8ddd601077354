// The step's time step (time_step.hpp).
#include "picdem/fluid/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/fluid/viscous.hpp"

namespace picdem::fluid {

// The time step's keys (the time loop reads time/end as well).
void declare_time_parameters(core::ParamSchema& s) {
  s.section("time", "Simulated time and the adaptive time step.");
  s.real("time/end", 1.0,
         "simulated time to reach [s]; the run ends with the first step at or past it (the last "
         "step is not shortened, so continuing to a later end follows the same trajectory)")
      .positive()
      .is_required();
  s.real("time/cfl", 0.5, "CFL number: dt <= cfl h / max|u| on the grid").positive().at_most(5.0);
  s.string(
      "time/cfl_speed", "grid", {"particles", "grid"},
      "the speed of the CFL bound: the largest of the grid's face velocities, which move the "
      "particles, and the solids' surface speeds with gravity's change over the step, with dt at "
      "most sqrt(cfl h / |g|) (grid), or of the grid's face velocities and the particles' own "
      "speeds (particles; doc/coupling.md)");
  s.real("time/dt_max", 1e-3, "largest time step [s]").positive();
  s.real("time/dt_growth", 1.2,
         "time/cfl_speed grid: largest ratio of a time step to the last one: after a short step "
         "(a fast flow, an impact) dt grows back gradually; a large value lifts the bound")
      .at_least(1.0);
  s.real("time/dt_min", 1e-8, "smallest time step [s]; a step below it stops the run as blown up")
      .positive();
  // Bounds that put every step below dt_min whatever the flow: the run would stop at its first
  // step saying the flow has blown up, which would send the user to the wrong key.
  s.check([](const core::Params& p, std::vector<std::string>& errors) {
    const double dt_max = p.real("time/dt_max"), dt_min = p.real("time/dt_min");
    std::ostringstream m;
    if (dt_max < dt_min) {
      m << "key 'time/dt_max' = " << dt_max
        << " is not allowed: it is below time/dt_min = " << dt_min
        << ", so every step would stop the run as blown up; allowed: dt_max >= dt_min";
      errors.push_back(m.str());
      return;
    }
    if (p.sublist_names("water").empty() || p.string("time/cfl_speed") != "grid") return;
    const auto g = p.reals("fluid/gravity");
    const double h = p.real("grid/cell_size"), cfl = p.real("time/cfl");
    const double g_norm = std::hypot(g.at(0), g.at(1));
    if (g_norm > 0.0 && std::sqrt(cfl * h / g_norm) < dt_min) {
      m << "key 'time/cfl' = " << cfl << " is not allowed here: water accelerated by gravity "
        << "takes steps of at most sqrt(cfl h / |g|) = " << std::sqrt(cfl * h / g_norm)
        << " s (grid/cell_size = " << h << " m), below time/dt_min = " << dt_min
        << " s, so the first step would stop the run as blown up; allowed: cfl >= "
        << dt_min * dt_min * g_norm / h << " (or a smaller time/dt_min)";
      errors.push_back(m.str());
    }
  });
}

TimeStepLimits time_step_limits_from(const core::Params& params) {
  TimeStepLimits t{params.real("grid/cell_size"), params.real("time/cfl"),
                   params.real("time/dt_max"), params.real("time/dt_min"), params.real("time/end")};
  t.cfl_from_particles = params.string("time/cfl_speed") == "particles";
  // time/dt_growth bounds the grid rule; particles is kept as it was before issue 13
  t.growth = t.cfl_from_particles ? 0.0 : params.real("time/dt_growth");
  return t;
}

double choose_time_step(const TimeStepLimits& set, const FluidConfig& cfg, double t, long long step,
                        const FluidState* fluid, const StepMotion& motion, double last_dt,
                        const core::Comm& comm) {
  // The last step is not shortened to land on time/end: the run ends with the first step that
  // reaches it, so a run continued to a later end takes the steps of one run made to that end.
  const double dt_max = set.dt_max;
  if (!fluid) return dt_max;
  const double reach = set.cfl * set.h;  // the distance anything may move in one step
  const double dt_grid = cfl_time_step(fluid->u, fluid->w, set.h, set.cfl, dt_max, comm);
  double dt = std::min(dt_max, dt_grid);
  if (const double in = cfg.open.max_inflow_speed(t); in > 0.0)
    dt = std::min(dt, reach / in);  // the inflow's speed (time/cfl), known before the grid has it
  dt = std::min(dt, viscous_time_limit(cfg));  // explicit viscosity's stability
  // The grid rule sees the faces' velocities before the step, not gravity's change over it: water
  // at rest would take dt_max. Water accelerated from rest by g moves |g| dt^2 in the step (the
  // faces reach |g| dt): dt <= sqrt(cfl h / |g|) keeps that within cfl h.
  if (const double g = std::hypot(cfg.g.x, cfg.g.z); !set.cfl_from_particles && g > 0.0)
    dt = std::min(dt, std::sqrt(reach / g));
  const double s = motion.speed;
  if (motion.accel > 0.0)  // (s + a dt) dt = CFL h: dt = 2 CFL h / (s + sqrt(s^2 + 4 a CFL h))
    dt = std::min(dt, 2.0 * reach / (s + std::sqrt(s * s + 4.0 * motion.accel * reach)));
  else if (s > 0.0)
    dt = std::min(dt, reach / s);  // dt = CFL h / s
  if (set.growth > 0.0 && last_dt > 0.0) dt = std::min(dt, set.growth * last_dt);
  if (!(dt >= set.dt_min) && set.t_end - t > set.dt_min) {
    std::ostringstream m;
    m << "step " << step << " at t = " << t << " s: the time step fell to " << dt
      << " s (below time/dt_min): the flow has blown up"
      << (cfg.open.any_inflow() ? " or the inflow speed (open/<side>/velocity or table) is "
                                  "too fast for time/dt_min"
                                : "")
      << " (fastest on the grid " << (dt_grid < dt_max ? "" : "below ") << reach / dt_grid
      << " m/s; particles or solids " << s << " m/s, accelerating at " << motion.accel
      << " m/s^2). Inputs that make a flow this fast: fluid/density = " << cfg.rho
      << " kg/m^3 far from the solids' densities, gravity, an inflow, solids' initial velocities";
    throw core::SolverError(m.str());
  }
  return dt;
}

}  // namespace picdem::fluid
