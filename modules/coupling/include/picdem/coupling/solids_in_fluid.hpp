#pragma once
// The solids as the fluid sees them (METHOD.md sections 3 and 6): the DEM's snapshot of its
// solids at one instant (dem/scene.hpp), the cut cells at their poses (fluid::cut_cells) and
// damping the fluid trapped in contact gaps (eq. 20). The solid couplings of the pressure
// equation and the loads J p are the fluid's (fluid/body_loads.hpp, PressureSolver::solid_loads).
#include <vector>

#include "picdem/dem/dem_solver.hpp"
#include "picdem/particles/particle_set.hpp"

namespace picdem::coupling {

/// Eq. 20: the particles' velocities (and APIC matrices) scaled by the gap damping factor C of
/// `contacts` (dem::GapDamping: the bands of the active contacts, gathered from all ranks by
/// dem::all_contacts). Returns the number of particles damped on this rank.
long long damp_gap_particles(particles::ParticleSet& ps, const std::vector<dem::Contact>& contacts,
                             double h, double beta);

}  // namespace picdem::coupling
