#pragma once
// Figures of the particles: the speed that bounds the coupled step (time/cfl_speed particles) and
// what the step's diagnostics record of them.
#include "picdem/core/comm.hpp"
#include "picdem/core/vec2.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/grid/grid.hpp"
#include "picdem/particles/particle_set.hpp"

namespace picdem::particles {

/// Collective: the largest particle speed |v| over all ranks (0 without particles).
double max_speed(const ParticleSet& particles, const core::Comm& comm);

/// This rank's particles (not collective); without particles front is -infinity.
struct LocalFigures {
  double kinetic_energy = 0.0;  ///< sum of mass |v|^2 / 2, `mass` per particle
  double front = 0.0;           ///< largest x
  double max_speed = 0.0;       ///< largest |v|
  bool finite = true;           ///< every velocity and position finite
};
LocalFigures local_figures(const ParticleSet& particles, double mass);

/// Whether the square of half-side `reach` about `centre` meets a cell of the grid that holds
/// particles (`count`: particles per cell over this rank's owned and halo cells, as
/// OccupancyPass::count), or a cell of the grid beyond this rank's halo, about which this rank
/// cannot tell (then true). Not collective.
bool near_particles(const grid::GridArray<int>& count, const grid::GridSpec& spec,
                    core::Vec2 centre, double reach);

}  // namespace picdem::particles
