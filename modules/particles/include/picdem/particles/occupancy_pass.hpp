#pragma once
// The particles' occupancy kept from the pass that computed it to the phases that read it, while
// the particles stay where they are (the coupled step: doc/architecture.md, "The step").
#include <vector>

#include "picdem/grid/field.hpp"
#include "picdem/particles/particle_set.hpp"
#include "picdem/particles/transfer.hpp"

namespace picdem::particles {

/// The particles' occupancy before the open-share correction (particles::occupancy) and their
/// count per cell, computed in one pass for the particles where a step leaves them: by the
/// diagnostics, then read by the next step's cells. `current` is cleared when the particles move
/// (the cells of a step take it). The same pass also takes P2G's sums (`sums`, `sums_current`)
/// when the particles stay as they are until the step's P2G: always in the cells of a step, in
/// the diagnostics when the next step has no density correction (which moves them, and is
/// followed by the cells again); P2G takes them and clears `sums_current`.
struct OccupancyPass {
  grid::CellField S;
  grid::GridArray<int> count;
  GridSums sums;
  bool current = false;
  bool sums_current = false;

  /// S and count of `ps` (with `with_sums`, also P2G's sums of `config`'s transfer) in one pass
  /// over the particles; nothing when current. Sets current, and sums_current = with_sums.
  void update(const ParticleSet& ps, const grid::Decomposition& d, const grid::Halo& halo,
              const ParticleConfig& config, bool with_sums);
};

/// Relative work of a cell for the cut lines that follow the work (grid/decomposition =
/// weighted): every cell kWorkCell (the loops over the whole window), a cell holding particles
/// kWorkFluid more (its pressure row, its share of the fluid passes), and kWorkParticle per
/// particle (P2G, G2P, advection, migration).
constexpr long long kWorkCell = 1, kWorkFluid = 40, kWorkParticle = 10;

/// The work of each owned cell, row-major (i fastest), from the particles' positions only (the
/// state a checkpoint keeps, so that a restart computes the same cut lines).
std::vector<long long> cell_work(const grid::Decomposition& d, const ParticleSet& ps);

}  // namespace picdem::particles
