#pragma once
// Particles at the open tank sides (doc/open_boundaries.md): which leave through an outflow,
// which the inflow brings in. Over the particles' plain arrays (fluid does not know the particle
// module); coupling removes and adds them.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "picdem/core/vec2.hpp"
#include "picdem/fluid/open_boundary.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::fluid {

/// Clears keep[n] of the particles at (x[n], z[n]) that advection put onto an open face of an
/// outflow side (particles::advect holds a particle leaving the tank 1e-6 h inside the side).
/// keep: one entry per particle. Returns how many it cleared.
std::size_t mark_outflow_particles(const std::vector<double>& x, const std::vector<double>& z,
                                   const OpenBoundaries& open, const grid::GridSpec& g,
                                   std::vector<char>& keep);

/// How the virtual columns beyond the inflows are seeded: as the initial water
/// (particles/per_cell_1d, particles/jitter, particles/seed).
struct InflowSeeding {
  int per_cell_1d = 2;
  double jitter = 0.5;
  std::uint64_t seed = 1;
};

/// A particle the inflow brought in: its id, position at the step's end and velocity.
struct InflowParticle {
  std::int64_t id = 0;
  core::Vec2 position, velocity;
};

/// The particles the inflow brings in over the step [open.t0, open.t1]. Beyond each inflow
/// face lies a virtual column of cells seeded as the initial water (per_cell_1d^2 jittered
/// particles per cell, positions from counter-based random numbers of the side, the face, the
/// cell's distance from the side and the particle); the column moves inwards by the inflow's
/// displacement S(s, t) (OpenSide::displacement), and a particle is added when it crosses the side
/// during the step, at its position at t1 with the face's velocity. Every particle is made by the
/// rank owning the boundary cell of its face, so the set is the same on any rank count; ids are
/// negative, -(1 + ((column 4 + side) n_max + face) per_cell_1d^2 + particle). `reject`: positions
/// not to fill (inside a body). In the order to add them; migrate them afterwards.
std::vector<InflowParticle> inflow_particles(const InflowSeeding& seeding,
                                             const OpenBoundaries& open,
                                             const grid::Decomposition& d,
                                             const std::function<bool(core::Vec2)>& reject);

}  // namespace picdem::fluid
