#pragma once
// The open sides on the step's fields (open_boundary.hpp, doc/open_boundaries.md): apertures,
// boundary velocities and ghosts, the free-surface fraction of outflow faces, the boundary fluxes.
#include "picdem/core/comm.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/open_boundary.hpp"

namespace picdem::fluid {

/// E = h on the open faces of the grid's outer sides (storage faces), so that the divergence
/// (eq. 5) takes their flux.
void open_side_apertures(Apertures& E, const OpenBoundaries& o, const grid::Decomposition& d);

/// The normal velocity on the outflow faces, kept by enforce_walls across its wall rules.
struct OutflowFaces {
  std::vector<double> u_left, u_right, w_bottom, w_top;  ///< per storage row / column, NaN: none
};
OutflowFaces keep_outflow_faces(const grid::FaceField& u, const grid::FaceField& w,
                                const OpenBoundaries& o, const grid::Decomposition& d);

/// After the wall rules of enforce_walls: inflow faces get the inward face_speed (and the ghosts
/// beyond them the same), the tangential ghosts mirror with the opposite sign (tangential
/// velocity 0 on the side); outflow faces get their kept value back, the normal ghosts beyond
/// them that value (zero normal gradient) and the tangential ghosts the mirrored value (zero
/// tangential gradient).
void enforce_open_sides(grid::FaceField& u, grid::FaceField& w, const OpenBoundaries& o,
                        const grid::Decomposition& d, const OutflowFaces& kept);

/// Outflow sides with zero_gradient (open/<side>/outflow_velocity): each open face takes the
/// velocity of the interior face next to it (du_n / dn = 0), on the storage faces whose neighbour
/// is stored. Called before the projection (the step's forces phase); enforce_walls then keeps
/// it and the projection with p = 0 on the face corrects it.
void zero_gradient_outflow(grid::FaceField& u, grid::FaceField& w, const OpenBoundaries& o,
                           const grid::Decomposition& d);

/// theta = 1/2 on the outflow faces: p = 0 on the boundary face itself (ghost fluid).
void open_surface_fractions(SurfaceFractions& s, const OpenBoundaries& o,
                            const grid::Decomposition& d);

/// Volume rates through the open faces over all ranks [m^2/s per unit depth]: inflow (inward) and
/// outflow (outward), from the face velocities times the face's wet length. An inflow face counts
/// whole (its particles are injected whatever lies inside). An outflow face counts only where the
/// cell inside it is fluid (above the water an outflow face carries the extrapolated velocity of
/// the air, which moves no water), and where that cell holds the free surface (an air cell beside
/// it along the side) only up to the surface: h/2 on each side of the centre, or theta h towards
/// an air neighbour (`surface`, the ghost-fluid fractions; null: whole faces).
/// doc/open_boundaries.md, "Volume accounting".
struct OpenFluxes {
  double inflow = 0.0, outflow = 0.0;
};
OpenFluxes open_fluxes(const grid::FaceField& u, const grid::FaceField& w, const CellStates& cells,
                       const SurfaceFractions* surface, const OpenBoundaries& o,
                       const grid::Decomposition& d, const core::Comm& comm);

}  // namespace picdem::fluid
