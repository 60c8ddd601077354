#pragma once
// Cut cells (METHOD.md section 3): the data through which the fluid sees solids and fixed
// obstacles. For a window of cells it gives, per face, the open length E (eq. 5), per cell the
// fluid area fraction and the body that cuts it, and per (body, cell) the pieces of the body's
// boundary inside the cell with the integrals of n dl and (r x n) dl. Face lengths and pieces come
// from the same intersection points, so in every cell
//   sum_f E_f n_f  -  sum_pieces integral n dl  =  0      (n_f: the cell's outward face normal)
// holds to round-off (doc/geometry.md).
#include <cstdint>
#include <string>
#include <vector>

#include "picdem/core/vec2.hpp"
#include "picdem/geometry/shape.hpp"

namespace picdem::geometry {

using core::IndexBox;

/// The cells to compute: global cell indices (a rank's owned cells plus halo). Cell (i, k) spans
/// [origin.x + i h, origin.x + (i+1) h] x [origin.z + k h, origin.z + (k+1) h].
/// Faces: FaceX i in [i0, i1], k in [k0, k1); FaceZ i in [i0, i1), k in [k0, k1].
struct GridWindow {
  Vec2 origin;
  double h = 0.0;
  IndexBox cells;
};

struct SolidPlacement {
  std::int64_t id = 0;
  ShapePtr shape;
  Pose pose;
};

/// A fixed obstacle: the union of CCW simple polygons in the world frame.
struct Obstacle {
  std::string name;
  std::vector<std::vector<Vec2>> polygons;
};

/// One connected piece of a body's boundary inside one cell. A body may have several pieces in
/// one cell (a non-convex body entering twice); a_{s,c} is the sum over them.
struct WettedPiece {
  int body = 0;  ///< index into the solids vector, or -1-k for obstacle k
  int i = 0, k = 0;
  Vec2 p0, p1;  ///< end points in the world frame, along the CCW boundary
  Vec2 n_dl;    ///< integral of n dl, n the body's outward normal
  double r_cross_n_dl =
      0;  ///< integral of (r x n) dl, r from the body's centre of mass; 0 for obstacles
  double length = 0;
  /// First moments about the centre x_c of cell (i, k), exact on arcs and segments, for loads of
  /// a pressure varying linearly along the piece (the hydrostatic quadrature):
  /// dx_n_dl = int (x - x_c) n dl, dz_n_dl = int (z - z_c) n dl, and
  /// d_r_cross_n_dl = (int (x - x_c) (r x n) dl, int (z - z_c) (r x n) dl); 0 for obstacles.
  Vec2 dx_n_dl, dz_n_dl, d_r_cross_n_dl;
  bool closes_tiny_cell = false;  ///< a face of a dropped tiny cell (CutCellOptions)
};

struct CutCells {
  GridWindow window;

  /// Open length of FaceX (i, k), in [0, h].
  double E_x(int i, int k) const;
  /// Open length of FaceZ (i, k), in [0, h].
  double E_z(int i, int k) const;
  /// Fluid area fraction of cell (i, k), in [0, 1]; 0 for dropped tiny cells.
  double fluid_fraction(int i, int k) const;
  /// The solid covering the largest part of the cell (the lower index on ties); a solid whose
  /// boundary merely lies on the cell's edge counts with area 0. -1 when no solid touches it.
  /// Defined on the window grown by one cell as well (the ring's values are those of a window
  /// that holds it), so that a face on the window's edge sees the bodies on both sides.
  int cutting_body(int i, int k) const;
  /// The same for obstacles: obstacle index, -1 none (also on the grown ring).
  int cutting_obstacle(int i, int k) const;
  /// True when the cell was dropped as tiny (fraction below CutCellOptions::tiny_fraction).
  bool dropped(int i, int k) const;

  /// Every (body, cell) boundary piece in the window, ordered by cell (k, then i), then body.
  std::vector<WettedPiece> pieces;

  // Storage over the part of the window grown by one cell that the bodies can touch, with a
  // margin of a cell (read through the accessors above, which give an uncut cell's values
  // outside it: E = h, fraction 1, no body, not dropped). Empty when no body reaches the window.
  IndexBox store;
  std::vector<double> ex, ez, fraction;
  std::vector<int> body, obstacle;
  std::vector<unsigned char> tiny;
};

struct CutCellOptions {
  /// Cells whose fluid fraction is below this are dropped: made solid, their open faces closed
  /// and turned into boundary pieces of the body covering most of the cell, attributed to the
  /// neighbouring fluid cell (doc/geometry.md). 0 keeps every cell.
  double tiny_fraction = 1e-3;
};

/// Builds all cut-cell data of `window`. Solids and obstacles that overlap are taken as their
/// union for E; see doc/geometry.md for what overlap does to fractions and pieces.
CutCells build_cut_cells(const GridWindow& window, const std::vector<SolidPlacement>& solids,
                         const std::vector<Obstacle>& obstacles, const CutCellOptions& options);

}  // namespace picdem::geometry
