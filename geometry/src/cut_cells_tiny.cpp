// Tiny cells (doc/geometry.md): a cell whose fluid fraction is below the threshold and that still
// has an open face is dropped; each face it had open towards a kept neighbour becomes a boundary
// piece of the body covering most of the dropped cell, attributed to that neighbour. Then the
// window's pieces outside dropped cells are stored in cell order, then body order.
#include <algorithm>

#include "cut_cells_internal.hpp"

namespace picdem::geometry::detail {

namespace {

/// The open lengths of cc (units of h) by global face index (raw pointers: the loops over the
/// window's cells write bytes, which through a vector would make every access reload it).
struct Faces {
  double* ex;
  double* ez;
  int i0, k0;
  std::size_t nwx;
  Faces(CutCells& cc, const Builder& bd)
      : ex(cc.ex.data()), ez(cc.ez.data()), i0(bd.W.i0), k0(bd.W.k0), nwx(bd.nwx) {}
  double& x(int i, int k) const {
    return ex[(i - i0) + static_cast<std::size_t>(k - k0) * (nwx + 1)];
  }
  double& z(int i, int k) const { return ez[(i - i0) + static_cast<std::size_t>(k - k0) * nwx]; }
};

/// Fraction below the threshold and still open somewhere -> marked as dropped. Returns the
/// dropped cells' indices c = (i - W.i0) + (k - W.k0) nwx in cell order (k, then i).
std::vector<long long> mark_tiny_cells(const CutCellOptions& options, const Builder& bd,
                                       const Faces& f, CutCells& cc) {
  std::vector<long long> dropped;
  const double* fraction = cc.fraction.data();
  unsigned char* tiny = cc.tiny.data();
  const double threshold = options.tiny_fraction;
  const IndexBox W = bd.W;
  for (int k = W.k0; k < W.k1; ++k) {
    for (int i = W.i0; i < W.i1; ++i) {
      const long long c = bd.cell(i, k);
      if (fraction[c] < threshold &&
          (f.x(i, k) > 0 || f.x(i + 1, k) > 0 || f.z(i, k) > 0 || f.z(i, k + 1) > 0)) {
        tiny[c] = 1;
        dropped.push_back(c);
      }
    }
  }
  return dropped;
}

/// The parts of [a, b] that the merged intervals `covered` leave open.
std::vector<Interval> open_parts(const std::vector<Interval>& covered, double a, double b) {
  std::vector<Interval> open;
  double at = a;
  for (const auto& iv : covered) {
    if (iv.hi <= at || iv.lo >= b) continue;
    if (iv.lo > at) open.push_back({at, iv.lo});
    at = std::max(at, iv.hi);
  }
  if (at < b) open.push_back({at, b});
  return open;
}

/// A face of a dropped cell: the neighbour (ni, nk) across it, the line it lies on, and whether
/// the dropped cell is on the line's low side.
struct TinyFace {
  int ni, nk;
  bool vertical;
  int line;
  bool low;
};

/// The closing piece on the open part iv of face f (grid units), owned by body `tag` (owner: its
/// item, null for obstacles). The outward normal of the enlarged body points into the neighbour.
WettedPiece closing_piece(const TinyFace& f, const Interval& iv, int tag, const Item* owner,
                          const GridWindow& window) {
  Vec2 p0, p1;
  if (f.vertical) {
    p0 = {double(f.line), f.low ? iv.lo : iv.hi};
    p1 = {double(f.line), f.low ? iv.hi : iv.lo};
  } else {
    p0 = {f.low ? iv.hi : iv.lo, double(f.line)};
    p1 = {f.low ? iv.lo : iv.hi, double(f.line)};
  }
  const Vec2 d = p1 - p0;
  WettedPiece p;
  p.body = tag;
  p.i = f.ni;
  p.k = f.nk;
  p.p0 = window.origin + window.h * p0;
  p.p1 = window.origin + window.h * p1;
  p.n_dl = window.h * Vec2{d.z, -d.x};
  if (tag >= 0 && owner) {
    p.r_cross_n_dl = -window.h * window.h * core::dot(d, 0.5 * (p0 + p1) - owner->com);
  }
  Sub segment;
  segment.p0 = p0, segment.p1 = p1;
  set_moments(p, segment, f.ni, f.nk, window.h, tag >= 0 && owner ? &owner->com : nullptr);
  p.length = window.h * core::norm(d);
  p.closes_tiny_cell = true;
  return p;
}

/// The closing pieces of the dropped cell (i, k), appended to `closing`.
void close_tiny_cell(int i, int k, const std::vector<Item>& items,
                     const std::vector<int>& item_of_solid, const Builder& bd, const Faces& fc,
                     CutCells& cc, std::vector<WettedPiece>& closing) {
  const long long c = bd.cell(i, k);
  const bool solid_owner =
      bd.best_solid_area[c] >= bd.best_obstacle_area[c] && bd.best_solid[c] >= 0;
  const int tag = solid_owner ? bd.best_solid[c] : -1 - cc.obstacle[c];
  const Item* owner = tag >= 0 ? &items[item_of_solid[tag]] : nullptr;
  const TinyFace faces[4] = {{i - 1, k, true, i, false},
                             {i + 1, k, true, i + 1, true},
                             {i, k - 1, false, k, false},
                             {i, k + 1, false, k + 1, true}};
  for (const TinyFace& f : faces) {
    const double E = f.vertical ? fc.x(f.line, k) : fc.z(i, f.line);
    if (E <= 0 || !bd.W.contains(f.ni, f.nk) || cc.tiny[bd.cell(f.ni, f.nk)]) continue;
    const auto& cov = f.vertical ? bd.gx[f.line - bd.W.i0] : bd.gz[f.line - bd.W.k0];
    const double a = f.vertical ? k : i;
    for (const auto& iv : open_parts(cov, a, a + 1.0)) {
      closing.push_back(closing_piece(f, iv, tag, owner, bd.win));
      if (tag >= 0 && cc.body[bd.cell(f.ni, f.nk)] < 0) cc.body[bd.cell(f.ni, f.nk)] = tag;
    }
  }
}

/// The window's pieces outside dropped cells, in cell order, then body order.
void collect_pieces(const Builder& bd, CutCells& cc) {
  for (const auto& p : bd.pieces) {
    if (bd.win.cells.contains(p.i, p.k) && !cc.tiny[bd.cell(p.i, p.k)]) cc.pieces.push_back(p);
  }
  std::stable_sort(cc.pieces.begin(), cc.pieces.end(),
                   [](const WettedPiece& a, const WettedPiece& b) {
                     if (a.k != b.k) return a.k < b.k;
                     if (a.i != b.i) return a.i < b.i;
                     if (a.body != b.body)
                       return (a.body >= 0 ? a.body : 1000000000 - a.body) <
                              (b.body >= 0 ? b.body : 1000000000 - b.body);
                     return a.closes_tiny_cell < b.closes_tiny_cell;
                   });
}

}  // namespace

void drop_tiny_cells_and_collect(const std::vector<Item>& items,
                                 const std::vector<int>& item_of_solid,
                                 const CutCellOptions& options, Builder& bd, CutCells& cc) {
  const Faces f(cc, bd);
  cc.tiny.assign(static_cast<std::size_t>(bd.nwx) * bd.nwz, 0);
  const std::vector<long long> dropped = mark_tiny_cells(options, bd, f, cc);
  std::vector<WettedPiece> closing;
  for (const long long c : dropped) {
    const int i = bd.W.i0 + static_cast<int>(c % bd.nwx),
              k = bd.W.k0 + static_cast<int>(c / bd.nwx);
    close_tiny_cell(i, k, items, item_of_solid, bd, f, cc, closing);
  }
  for (const long long c : dropped) {
    const int i = bd.W.i0 + static_cast<int>(c % bd.nwx),
              k = bd.W.k0 + static_cast<int>(c / bd.nwx);
    f.x(i, k) = f.x(i + 1, k) = f.z(i, k) = f.z(i, k + 1) = 0.0;
    cc.fraction[c] = 0.0;
  }
  bd.pieces.insert(bd.pieces.end(), closing.begin(), closing.end());
  collect_pieces(bd, cc);
}

}  // namespace picdem::geometry::detail
