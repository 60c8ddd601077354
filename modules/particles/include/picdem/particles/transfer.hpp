#pragma once
// Particle <-> grid transfers on the MAC grid with the bilinear hat kernel.
//
// P2G (to_grid):  m_f = sum_p N_f(x_p),  u_f = sum_p N_f(x_p) (u_p + C_p (x_f - x_p)) / m_f
// G2P (from_grid): FLIP/PIC  v_p = r (v_p + du(x_p)) + (1 - r) u_new(x_p),  du = u_new - u_old
//                  APIC      v_p = u_new(x_p),  C_p = grad u_new(x_p)
// Near the walls the P2G kernel is clamped so that every particle's weight lands on faces of the
// grid (weights sum to 1 per particle: momentum is conserved exactly); G2P interpolates the two
// nearest rows of faces, extrapolating linearly in the half cell next to a wall.
#include "picdem/core/vec2.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/particles/particle_set.hpp"

namespace picdem::particles {

/// P2G: momentum and weight scattered into owned + halo faces, reverse-added to the owners,
/// divided. Faces without weight get u = 0 and weight 0. On return the owned faces and the halo
/// faces that lie on the grid are valid (forwarded); storage outside the grid is zero.
void to_grid(const ParticleSet& particles, const grid::Decomposition& decomposition,
             const grid::Halo& halo, const ParticleConfig& config, grid::FaceField& u,
             grid::FaceField& w, grid::FaceField& weight_u, grid::FaceField& weight_w);

/// to_grid's sums before they are exchanged: momentum and kernel weight per face over owned and
/// halo faces, as one pass over the particles leaves them (the occupancy's pass can take them:
/// picdem/particles/occupancy.hpp).
struct GridSums {
  grid::FaceField u, w, weight_u, weight_w;
};

/// The rest of to_grid after the pass over the particles: the sums are moved into u, w and the
/// weights (their old storage is left in `sums`, to be reused), reverse-added, divided and
/// forwarded. to_grid's result exactly, for sums of the same particles.
void to_grid(GridSums& sums, const grid::Halo& halo, grid::FaceField& u, grid::FaceField& w,
             grid::FaceField& weight_u, grid::FaceField& weight_w);

/// Particles per cell over owned cells, with the halo made valid. Particles may sit in halo
/// cells (before migrate): they are counted by their cell's owner. `count` must be a Cell field
/// of the decomposition behind `halo`; cells are found on particles.spec.
void count_per_cell(const ParticleSet& particles, const grid::Halo& halo,
                    grid::GridArray<int>& count);
void count_per_cell(const ParticleSet& particles, const grid::GridSpec& spec,
                    const grid::Halo& halo, grid::GridArray<int>& count);

/// G2P. The fields' halos must be valid one face beyond the owned cells.
void from_grid(ParticleSet& particles, const ParticleConfig& config, const grid::FaceField& u_old,
               const grid::FaceField& w_old, const grid::FaceField& u_new,
               const grid::FaceField& w_new, const grid::GridSpec& spec);

/// Bilinear interpolation of the staggered velocity at p.
core::Vec2 sample(const grid::FaceField& u, const grid::FaceField& w, const grid::GridSpec& spec,
                  core::Vec2 p);

/// The velocity at p and its gradient c = {du/dx, du/dz, dw/dx, dw/dz} (of the bilinear
/// interpolant: exact for linear fields).
core::Vec2 sample_with_gradient(const grid::FaceField& u, const grid::FaceField& w,
                                const grid::GridSpec& spec, core::Vec2 p, double (&c)[4]);

}  // namespace picdem::particles
