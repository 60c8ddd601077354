#pragma once
// The check after every step that the run has not blown up (run::Runner calls it; a test calls it
// with made-up diagnostics).
#include "picdem/core/comm.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/dem/dem_solver.hpp"

namespace picdem::run {

/// Collective, after every step (g: its diagnostics): throws core::SolverError naming the step
/// when the step blew up: a particle moved more than 2 h (CFL far exceeded; the particles' speed
/// times dt, or with `grid_speed` (time/cfl_speed: grid) the distance the grid velocity moved
/// them, Diagnostics::advected), or a
/// solid's real boundary overlaps another solid, a wall or an obstacle (DEM overlap delta beyond
/// the imaginary gap, eq. 19).
void check_step(const coupling::Diagnostics& g, double h, bool has_fluid, bool grid_speed,
                const dem::DemSolver* dem, const core::Comm& comm);

}  // namespace picdem::run
