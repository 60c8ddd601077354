#pragma once
// The fluid next to solids and obstacles, read from geometry's cut cells (CGAL-free data): the
// classification of cut cells, the rigid velocities of covered faces, the FLIP base on them and
// the cells closed to reseeding. Bodies are indexed as in the cut cells (CutCells::cutting_body).
#include <vector>

#include "picdem/core/solid_state.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/grid/field.hpp"

namespace picdem::fluid {

/// Cells from the particles: fluid = holds particles (`count`), or is a cut cell below the free
/// surface (S > 1/2: a cut cell may hold no particle in its sliver of fluid); solid = covered;
/// air otherwise. f.occupancy holds the particles' S (particles::occupancy) on entry and, with
/// `cut`, is divided by the tent's open share (open_share_correction); phi = 1/2 - S. With `cut`,
/// enclosed cut cells are wetted (wet_enclosed_cut_cells) and the cells forwarded; with
/// `ghost_fluid`, the surface fractions are computed (theta >= theta_min), with `cut` and
/// `theta_open_length` bounded on cut faces (open_length_surface_fractions).
void mark_cells(const grid::GridArray<int>& count, const geometry::CutCells* cut,
                const grid::Decomposition& d, const grid::Halo& halo, bool ghost_fluid,
                double theta_min, bool theta_open_length, FluidState& f);

/// theta = max(theta, min(1, theta_min h / E)) on every fluid-air face a body or obstacle cuts
/// (0 < E < h): the velocity the ghost-fluid gradient drives through the face is then at most
/// E / h times what it drives through a full face (free_surface/theta_open_length,
/// doc/coupling.md, "The free surface on cut faces").
void open_length_surface_fractions(const geometry::CutCells& cut, double theta_min, double h,
                                   SurfaceFractions& s);

/// Air cut cells whose groups (connected through open faces) have only fluid or solid neighbours
/// across open faces become fluid: a sliver of fluid without particles inside the water is not
/// the free surface. A group reaching the edge of the storage window is left (its owner decides).
void wet_enclosed_cut_cells(const grid::Decomposition& d, const geometry::CutCells& cut,
                            const Apertures& E, CellStates& cells);

/// The open lengths of the faces with bodies: min(the tank's apertures, the cut cells' E).
Apertures body_apertures(const geometry::CutCells& cut, const grid::Decomposition& d);

/// The cut cells of `solids` and `obstacles` over this rank's storage window (a cell whose fluid
/// fraction is below tiny_fraction is made solid: doc/geometry.md) and their body_apertures.
geometry::CutCells cut_cells(const std::vector<geometry::SolidPlacement>& solids,
                             const std::vector<geometry::Obstacle>& obstacles, double tiny_fraction,
                             const grid::Decomposition& d, Apertures& apertures);

/// Faces closed by a body (E = 0, on the grid's interior) get its rigid velocity v + omega x r,
/// bodies[b] the motion of cut body b (obstacles: 0), and are marked valid, so that
/// interpolation next to a solid sees the solid's motion.
void rigid_face_velocities(const std::vector<core::SolidState>& bodies,
                           const geometry::CutCells& cut, const Apertures& E,
                           const grid::Decomposition& d, grid::FaceField& u, grid::FaceField& w,
                           grid::GridArray<signed char>& u_valid,
                           grid::GridArray<signed char>& w_valid);

/// The velocities around the fluid: the faces carrying fluid velocity (fluid_faces; with
/// `recompute_mask`, else those of the last call are kept: cells and apertures unchanged since),
/// with `cut` the faces closed by a body at its rigid velocity (rigid_face_velocities, `motions`
/// the motion of each cut body), then extended into the rest (extend_velocity, the halo's width).
void extend_around_fluid(const std::vector<core::SolidState>& motions,
                         const geometry::CutCells* cut, const grid::Decomposition& d,
                         const grid::Halo& halo, bool recompute_mask, FluidState& f);

/// The mixture velocity on the faces a body cuts (0 < E < h): (E u + (h - E) U_n) / h in u and
/// u_old alike, U_n the normal rigid velocity of the covering body (bodies[b] the motion of cut
/// body b; obstacles: 0). It is the face's whole flux per length, fluid and solid, so it is
/// continuous with the closed faces' rigid velocity as E -> 0 and discretely divergence-free
/// over full cells; a sliver's fluid velocity (flux through a tiny E) is not handed to the
/// particles beside it (coupling/mixture_cut_faces, doc/coupling.md).
void mix_cut_faces(const std::vector<core::SolidState>& bodies, const geometry::CutCells& cut,
                   const grid::Decomposition& d, FluidState& f);

/// u_old = u on the closed interior faces: the FLIP increment u - u_old is the fluid's change
/// only, not a body sweeping over a face.
void rigid_faces_into_flip_base(const grid::GridSpec& spec, FluidState& f);

/// The cells reseeding may fill: `cells` with every cut cell (fluid fraction < 1) made solid. A
/// cut cell holds fewer particles than a full one: reseeding it would add water every step.
CellStates reseed_cells(const CellStates& cells, const geometry::CutCells& cut);

}  // namespace picdem::fluid
