#pragma once
// Cut lines that follow the work (grid/decomposition = weighted): the work of each cell from the
// particles, and the move of the run's state (grid fields, particles, solids) to new cut lines in
// memory. Private to the coupling module; doc/performance.md has the figures.
#include <memory>
#include <vector>

#include "picdem/core/vec2.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/grid/balance.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/particles/particle_set.hpp"

namespace picdem::coupling {

/// Relative work of a cell: every cell kWorkCell (the loops over the whole window), a cell
/// holding particles kWorkFluid more (its pressure row, its share of the fluid passes), and
/// kWorkParticle per particle (P2G, G2P, advection, migration).
constexpr long long kWorkCell = 1, kWorkFluid = 40, kWorkParticle = 10;

/// The work of each owned cell, row-major (i fastest), from the particles' positions only (the
/// state a checkpoint keeps, so that a restart computes the same cut lines).
std::vector<long long> cell_work(const grid::Decomposition& d, const particles::ParticleSet& ps);

/// The region of space each rank owns (its cells), for the DEM.
std::vector<core::Box2> rank_regions(const grid::Decomposition& d);

/// What moves when the cut lines change. fluid: nullptr without water; dem: nullptr without
/// solids.
struct MovableState {
  grid::Decomposition& d;
  std::unique_ptr<grid::Halo>& halo;
  fluid::FluidState* fluid;
  particles::ParticleSet& particles;
  dem::DemSolver* dem;
};

/// Collective: sets the cut lines and moves the state to the new owners: the fields a checkpoint
/// keeps (fluid::FluidState::for_each_saved) with their ghosts, the particles, the solids; the
/// other fields start over as in a new FluidState (the step recomputes them before reading).
/// The caller rebuilds what holds maps of the old blocks (the pressure solvers).
void move_to_cuts(const MovableState& s, const grid::Cuts& cuts);

}  // namespace picdem::coupling
