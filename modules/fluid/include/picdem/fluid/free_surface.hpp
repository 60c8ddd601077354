#pragma once
// The free surface from the particles' occupancy, below cell resolution.
//
// Occupancy S at cell centres (particles::occupancy): S = 1 in the bulk and crosses 1/2 on the
// surface: across a flat surface the tent's symmetry puts S = 1/2 exactly on it. phi = 1/2 - S is
// the level set: negative in the fluid.
//
// Used for (1) the ghost-fluid Dirichlet condition p = 0 on the surface (Gibou et al. 2002): a
// face between fluid cell f and air cell a is cut at theta = phi_f / (phi_f - phi_a) of its
// length, and (2) the fluid volume: the area where the bilinear interpolant of S exceeds 1/2,
// less what solids cover of it.
//
// Next to solids a cell's tent reaches into covered cells that hold no particles: S there is
// divided by the share of the tent open to fluid (open_share_correction), so that water against a
// solid reads S = 1 and a body does not read as air.
#include "picdem/core/comm.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/grid/field.hpp"

namespace picdem::fluid {

/// S /= (tent mass on open fluid) / (tent mass) over the cell and its eight neighbours, where the
/// open share exceeds 5%; over the whole storage window (cut cells must cover it).
void open_share_correction(grid::CellField& S, const geometry::CutCells& cut,
                           const grid::Decomposition& d);

/// Area where the bilinear interpolant of S between cell centres exceeds 1/2, summed over the
/// owned cells of every rank (S needs a current halo). With cut cells, each cell's part is
/// weighted by its fluid fraction: the water's area, without the solids in it.
double occupied_area(const grid::CellField& S, const grid::Decomposition& d, const core::Comm& comm,
                     const geometry::CutCells* cut = nullptr);

/// The particles' excess area, the source of the density correction (doc/coupling.md): on every
/// owned fluid cell, relaxation (S - 1) f h^2 with f the cell's fluid fraction (1 without `cut`),
/// where S > 1, and where S < 1 only in cells whose eight neighbours hold no air (at the surface
/// S < 1 is the surface, not a deficit); |S - 1| is capped at `cap`. 0 on every other cell.
/// S and cells need a current halo. Returns whether any owned cell is nonzero.
bool excess_area(const grid::CellField& S, const CellStates& cells, const geometry::CutCells* cut,
                 double relaxation, double cap, const grid::Decomposition& d,
                 grid::CellField& source);

/// The density correction's particle displacement (dx, dz) extended beyond the fluid faces
/// (fluid_faces): closed faces (walls, bodies: E = 0) hold 0 and count as known; `unit`: the
/// correction's free-slip configuration, whose walls it enforces. Refreshes the halo.
void extend_displacement(const CellStates& cells, const Apertures& apertures,
                         const FluidConfig& unit, const grid::Decomposition& d,
                         const grid::Halo& halo, grid::FaceField& dx, grid::FaceField& dz);

}  // namespace picdem::fluid
