// The check after every step that the run has not blown up (check_step.hpp).
#include "picdem/run/check_step.hpp"

#include <sstream>
#include <string>

#include "picdem/core/error.hpp"

namespace picdem::run {

void check_step(const coupling::Diagnostics& g, double h, bool has_fluid, bool grid_speed,
                const dem::DemSolver* dem, const core::Comm& comm) {
  // CFL far exceeded: |v| dt > 2 h for the fastest particle, or the distance the grid velocity
  // moved a particle (what the particles met; a fast face no particle samples moves none). The
  // faces' speeds the step leaves are not checked: the next step's dt follows them
  // (doc/restart.md).
  const double moved = grid_speed ? g.advected : g.max_speed * g.dt;
  if (has_fluid && moved > 2.0 * h) {
    std::ostringstream m;
    m << "step " << g.step << " at t = " << g.t
      << " s: " << (grid_speed ? "the grid velocity moved a particle " : "a particle moved ")
      << moved / h << " cells in one step (speed " << moved / g.dt << " m/s, dt " << g.dt
      << " s); more than 2 cells means the CFL condition is far exceeded: the run has "
      << "blown up (the step is bounded by time/cfl and time/dt_max)";
    throw core::SolverError(m.str());
  }
  if (!dem) return;
  // Real boundaries overlapping: delta beyond the imaginary gap (eq. 19: delta = gap - distance).
  const double gap = dem->config().gap();
  std::string mine;
  for (const auto& c : dem->active_contacts())
    if (c.delta >= gap && mine.empty()) {
      std::ostringstream m;
      m << "step " << g.step << " at t = " << g.t << " s: solid " << c.id_i << " lies inside "
        << (c.id_j >= 0 ? "solid " + std::to_string(c.id_j) : std::string("a wall or obstacle"))
        << " (overlap of the real boundaries " << c.delta - gap << " m at (" << c.point.x << ", "
        << c.point.z << ")): the run has blown up; the contacts are too soft for the loads "
        << "they carry (eq. 10 lets the heaviest solid's weight press a contact by dem/theta = "
        << dem->config().theta << " cells of the gap's " << dem->config().gap_cells
        << "; a stack or an impact presses many times that): lower dem/theta or raise "
        << "dem/gap_cells";
      mine = m.str();
    }
  const long long bad = comm.max(mine.empty() ? -1LL : static_cast<long long>(comm.rank()));
  if (bad >= 0) throw core::SolverError(comm.broadcast(mine, static_cast<int>(bad)));
}

}  // namespace picdem::run
