#pragma once
// Particle motion: advection through the grid velocity, reseeding to keep the number of
// particles per cell in range, and migration to the owning rank.
#include <functional>

#include "picdem/core/vec2.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/particles/particle_set.hpp"

namespace picdem::particles {

/// Moves the particles through the (divergence-free) grid velocity with RK2 (midpoint) or RK3
/// (Ralston) over dt. Every stage is kept inside the tank: a position that would leave is put
/// back just inside the wall (1e-6 h). push_out, if given, then moves a particle out of solids,
/// and the result is kept inside the tank again. Needs |v| dt <= 2 h (see required_halo);
/// throws core::SolverError when a stage leaves the halo. Returns the largest distance the grid
/// velocity moved one of this rank's particles (before the tank's walls and push_out act).
double advect(ParticleSet& particles, const ParticleConfig& config, const grid::FaceField& u,
              const grid::FaceField& w, const grid::GridSpec& spec, double dt,
              const std::function<void(double& x, double& z)>& push_out = {});

/// Keeps the particles per cell within [min_per_cell, max_per_cell]; min_per_cell 0 turns
/// reseeding off, trimming included (nothing is added or removed: the particles are conserved):
/// - in every owned cell above max_per_cell, the particles with the largest ids are removed;
/// - in every interior fluid cell (Fluid, its four neighbours not Air) below min_per_cell,
///   particles are added at uniformly random positions (counter-based rng of seed, step, cell
///   gid), with the grid velocity (and its gradient under APIC); positions where reject(p) is
///   true (inside a solid) are skipped.
/// `count` must be current (count_per_cell after migrate) and `cell_state` forwarded (halo 1).
/// New ids: first_reseed_id + (step * cells + cell_gid) * max_per_cell + n, unique over the run
/// as long as reseed is called at most once per step. The result does not depend on the
/// decomposition.
void reseed(ParticleSet& particles, const ParticleConfig& config,
            const grid::Decomposition& decomposition, const grid::GridArray<int>& count,
            const grid::GridArray<signed char>& cell_state, const grid::FaceField& u,
            const grid::FaceField& w, long long step,
            const std::function<bool(core::Vec2)>& reject = {});

/// True when reseed would change this rank's particles: with min_per_cell > 0, an owned cell's
/// count is above max_per_cell, or an interior fluid cell's below min_per_cell (from the counts
/// alone, without visiting the particles; `count` current as for reseed).
bool reseed_changes(const ParticleConfig& config, const grid::Decomposition& decomposition,
                    const grid::GridArray<int>& count,
                    const grid::GridArray<signed char>& cell_state);

/// Sends every particle to the rank owning its cell (one all-to-all), then sorts the particles
/// by cell and id (sort_by_cell).
void migrate(ParticleSet& particles, const grid::Decomposition& decomposition);

}  // namespace picdem::particles
