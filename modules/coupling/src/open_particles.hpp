#pragma once
// Particles at the open tank sides (doc/open_boundaries.md): removed where they leave through an
// outflow, injected where the inflow brings fluid in. Private to the coupling module.
#include <cstddef>
#include <functional>

#include "picdem/core/vec2.hpp"
#include "picdem/fluid/open_boundary.hpp"
#include "picdem/grid/grid.hpp"
#include "picdem/particles/particle_set.hpp"

namespace picdem::coupling {

/// Removes this rank's particles that advection put onto an open face of an outflow side
/// (particles::advect holds a particle leaving the tank 1e-6 h inside the side). Returns how many.
std::size_t remove_outflow_particles(particles::ParticleSet& particles,
                                     const fluid::OpenBoundaries& open, const grid::GridSpec& g);

/// Adds the particles the inflow brought in over the step [open.t0, open.t1]. Beyond each inflow
/// face lies a virtual column of cells seeded as the initial water (per_cell_1d^2 jittered
/// particles per cell, positions from counter-based random numbers of the side, the face, the
/// cell's distance from the side and the particle); the column moves inwards by the inflow's
/// displacement S(s, t) (OpenSide::displacement), and a particle is added when it crosses the side
/// during the step, at its position at t1 with the face's velocity. Every particle is made by the
/// rank owning the boundary cell of its face, so the set is the same on any rank count; ids are
/// negative, -(1 + ((column 4 + side) n_max + face) per_cell_1d^2 + particle). `reject`: positions
/// not to fill (inside a body). Call particles::migrate afterwards. Returns how many.
std::size_t inject_inflow_particles(particles::ParticleSet& particles,
                                    const particles::ParticleConfig& config,
                                    const fluid::OpenBoundaries& open, const grid::Decomposition& d,
                                    const std::function<bool(core::Vec2)>& reject);

}  // namespace picdem::coupling
