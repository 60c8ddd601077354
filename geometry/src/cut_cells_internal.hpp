#pragma once
// Private to geometry/src: the working types of build_cut_cells and the functions its files share
// (doc/geometry.md maps each formula to its function and file). Everything here is in grid units,
// xi = (x - x0) / h, zeta = (z - z0) / h, where the grid lines are the integers. No CGAL here: the
// exact predicates stay inside the .cpp files that need them.
//   cut_cells.cpp            build_cut_cells: bodies in grid units, one body after the other
//   cut_cells_clip.cpp       clipping: a body's boundary split at the grid lines, crossings
//   cut_cells_apertures.cpp  covered intervals of the lines, open lengths E, fractions
//   cut_cells_pieces.cpp     wetted boundary pieces: hiding, chaining, integrals, moments
//   cut_cells_tiny.cpp       tiny cells: dropped, their open faces become boundary pieces
#include <cmath>
#include <functional>
#include <utility>
#include <vector>

#include "picdem/geometry/cut_cells.hpp"

namespace picdem::geometry::detail {

constexpr double kTwoPi = 2.0 * M_PI;

/// A boundary piece of a loop mixing segments and arcs, in grid units. a and b are the loop's
/// joints (shared bitwise with the neighbouring pieces).
struct UPiece {
  bool arc = false;
  Vec2 a, b;
  Vec2 c;
  double rho = 0.0, phi0 = 0.0, phi1 = 0.0;
};

/// A body boundary loop in grid units: a polygon (segments), a full circle, or a loop of pieces.
struct Item {
  int tag = 0;  // solid index, or -1-k for obstacle k
  bool circle = false;
  std::vector<UPiece> loop;  // a loop with partial arcs (empty for polygons and circles)
  std::vector<Vec2> verts;   // polygon loop, CCW
  Vec2 c;                    // circle centre
  double rho = 0.0;
  Vec2 com;  // centre of mass (solids), grid units
  double lo_x = 0, hi_x = 0, lo_z = 0, hi_z = 0;
  std::function<bool(const Vec2&)> contains_world;
};

/// A grid line: vertical (xi = index) or horizontal (zeta = index); kind 0 = none.
struct Line {
  int kind = 0;
  int index = 0;
  bool operator==(const Line& o) const { return kind == o.kind && index == o.index; }
};
constexpr int kVertical = 1, kHorizontal = 2;

/// A piece of boundary inside one cell (grid units).
struct Sub {
  Vec2 p0, p1;
  bool arc = false;
  Vec2 c;             // arc centre
  double rho = 0.0;   // arc radius
  double phi0 = 0.0;  // arc start angle
  double dphi = 0.0;  // arc span
  int i = 0, k = 0;
  Line line0, line1;  // the grid lines the end points lie on (none for original end points)
};

struct Event {
  double t;  // parameter along the piece (segment t, arc angle)
  Vec2 p;
  Line line;
};

struct Interval {
  double lo, hi;
};

/// Per-call working memory, reused from body to body.
struct Builder {
  GridWindow win;
  IndexBox W;  // window grown by one cell
  int nwx = 0, nwz = 0;
  std::vector<std::vector<Interval>> gx, gz;  // covered intervals on each line of W
  std::vector<double> covered;                // per cell: area terms of the visible boundary pieces
  std::vector<double> best_solid_area, best_obstacle_area;
  std::vector<int> best_solid, best_obstacle;
  std::vector<WettedPiece> pieces;

  // body scratch
  IndexBox B;
  std::vector<std::vector<Interval>> lx, lz;  // this body's intervals per line of B
  std::vector<std::vector<std::pair<double, int>>> ex_plus, ex_minus, ez_plus, ez_minus;
  std::vector<double> cx, cz, term;
  std::vector<unsigned char> touched;
  std::vector<Sub> subs;
  std::vector<Event> events;

  long long cell(int i, int k) const { return (i - W.i0) + static_cast<long long>(k - W.k0) * nwx; }
};

inline int floor_int(double v) {
  return static_cast<int>(std::floor(v));
}

// ---- cut_cells_clip.cpp ----------------------------------------------------------------------

/// Sign of |j - c| - rho, exactly (j, c, rho as given doubles).
int compare_distance(double j, double c, double rho);

/// Splits the item's boundary at the grid lines of B into bd.subs (each in one cell) and turns its
/// crossings of the lines of B into covered intervals bd.lx, bd.lz (not yet merged for circles).
void split_item(const Item& it, Builder& bd);

// ---- cut_cells_apertures.cpp -----------------------------------------------------------------

/// Sorts and merges overlapping intervals in place.
void merge(std::vector<Interval>& v);

/// Intervals where the winding number of the sorted (position, +1/-1) events is positive.
void sweep(std::vector<std::pair<double, int>>& ev, std::vector<Interval>& out);

/// Adds the covered length of merged intervals `v` on [c0, c1) faces into `c`.
void distribute(const std::vector<Interval>& v, int c0, int c1, double* c);

/// Turns the crossings of the shifted lines into covered intervals per line of B.
void finish_coverage(Builder& bd);

/// This item's covered length per face of B (bd.cx, bd.cz); adds its intervals to the union's.
void item_face_coverage(Builder& bd);

/// This item's covered area per cell of B: the cell's cutting solid or obstacle when largest.
void item_cell_areas(const Item& it, Builder& bd);

/// E_f = h - covered length of f for the union of all bodies, then the fluid fractions.
void union_apertures(Builder& bd, CutCells& cc);

// ---- cut_cells_pieces.cpp --------------------------------------------------------------------

/// The first moments of a piece s lying in cell (i, k) about the cell's centre (world units);
/// com is the body's centre of mass (grid units), null for obstacles.
void set_moments(WettedPiece& p, const Sub& s, int i, int k, double h, const Vec2* com);

/// The item's visible boundary pieces (not inside a neighbour), chained by cell into bd.pieces,
/// with their area terms in bd.term, bd.covered and bd.touched.
void item_pieces(const Item& it, const std::vector<Item>& items, const std::vector<int>& neighbours,
                 Builder& bd);

// ---- cut_cells_tiny.cpp ----------------------------------------------------------------------

/// Drops the cells below options.tiny_fraction that are still open, closes their faces with
/// boundary pieces of the owning body, and stores the window's pieces in cell order in cc.pieces.
void drop_tiny_cells_and_collect(const std::vector<Item>& items,
                                 const std::vector<int>& item_of_solid,
                                 const CutCellOptions& options, Builder& bd, CutCells& cc);

}  // namespace picdem::geometry::detail
