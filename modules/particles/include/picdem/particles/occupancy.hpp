#pragma once
// The particles' occupancy of the cells: the bilinear tent of the P2G transfer, scattered from
// every particle onto the cell centres and counted in full cells' worth of particles. The fluid
// module reads it as the free surface (picdem/fluid/free_surface.hpp).
#include "picdem/grid/field.hpp"
#include "picdem/particles/particle_set.hpp"
#include "picdem/particles/transfer.hpp"

namespace picdem::particles {

/// S(x_c) = sum_p W(x_c - x_p) / (n_ppc m(x_c)) over owned + halo cells (reverse-added, then
/// forwarded): W the bilinear tent of half-width h between cell centres, n_ppc the particles per
/// full cell, m(x_c) the share of the tent's mass inside the tank (1 away from the walls). S = 1
/// in the bulk and 1/2 on a flat free surface. With `count`, also the particles per cell of
/// count_per_cell (the same values) in the same pass over the particles.
void occupancy(const ParticleSet& ps, const grid::Decomposition& d, const grid::Halo& halo,
               int particles_per_cell, grid::CellField& S, grid::GridArray<int>* count = nullptr);

/// occupancy with the count, and to_grid's pass over the particles in the same pass: `sums`
/// holds P2G's momentum and weights (of `config`'s transfer) before their exchange, for
/// to_grid(sums, ...), which then gives bitwise what to_grid of the same particles gives.
void occupancy(const ParticleSet& ps, const grid::Decomposition& d, const grid::Halo& halo,
               int particles_per_cell, grid::CellField& S, grid::GridArray<int>& count,
               const ParticleConfig& config, GridSums& sums);

}  // namespace picdem::particles
