// Cut cells by intersecting each body boundary once with every grid line it spans (not with every
// cell edge). Everything is done in grid units, xi = (x - x0) / h, zeta = (z - z0) / h, where the
// grid lines are the integers. Every intersection point is computed once and used both for the
// face lengths and for the boundary pieces, which makes the discrete divergence theorem hold to
// round-off. This file turns solids and obstacles into bodies in grid units and runs the steps of
// the other cut_cells_*.cpp files (cut_cells_internal.hpp) one body after the other.
#include "picdem/geometry/cut_cells.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cut_cells_internal.hpp"
#include "picdem/core/error.hpp"

namespace picdem::geometry {

using namespace detail;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

Item make_polygon_item(int tag, const std::vector<Vec2>& world_verts, const GridWindow& w) {
  Item it;
  it.tag = tag;
  it.lo_x = it.lo_z = INFINITY;
  it.hi_x = it.hi_z = -INFINITY;
  for (const auto& p : world_verts) {
    const Vec2 u = (p - w.origin) / w.h;
    it.verts.push_back(u);
    it.lo_x = std::min(it.lo_x, u.x);
    it.hi_x = std::max(it.hi_x, u.x);
    it.lo_z = std::min(it.lo_z, u.z);
    it.hi_z = std::max(it.hi_z, u.z);
  }
  return it;
}

/// A full circle (one arc of span 2 pi) in grid units.
Item make_circle_item(int tag, const Arc& arc, const SolidPlacement& sp, const GridWindow& window) {
  Item it;
  it.tag = tag;
  it.circle = true;
  it.c = (sp.pose.to_world(arc.centre) - window.origin) / window.h;
  it.rho = arc.radius / window.h;
  it.lo_x = it.c.x - it.rho;
  it.hi_x = it.c.x + it.rho;
  it.lo_z = it.c.z - it.rho;
  it.hi_z = it.c.z + it.rho;
  return it;
}

/// A loop of segments and arcs in grid units: joints shared bitwise between neighbouring pieces.
Item make_loop_item(int tag, const std::vector<BoundaryPiece>& boundary, const SolidPlacement& sp,
                    const GridWindow& window) {
  auto to_unit = [&](const Vec2& body) {
    return (sp.pose.to_world(body) - window.origin) / window.h;
  };
  Item it;
  it.tag = tag;
  const std::size_t n = boundary.size();
  it.loop.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    UPiece& u = it.loop[j];
    if (const auto* seg = std::get_if<Segment>(&boundary[j])) {
      u.a = to_unit(seg->a);
    } else {
      const auto& arc = std::get<Arc>(boundary[j]);
      if (!(arc.radius > 0.0) || !(arc.phi1 > arc.phi0) || arc.phi1 - arc.phi0 > kTwoPi) {
        throw core::InputError("cut cells: solid " + std::to_string(sp.id) + " of kind '" +
                               sp.shape->kind() +
                               "' has an arc with radius <= 0 or a span outside (0, 2 pi]");
      }
      u.arc = true;
      u.c = to_unit(arc.centre);
      u.rho = arc.radius / window.h;
      u.phi0 = arc.phi0 + sp.pose.theta;
      u.phi1 = arc.phi1 + sp.pose.theta;
      const auto* prev = std::get_if<Segment>(&boundary[(j + n - 1) % n]);
      u.a = prev ? to_unit(prev->b) : u.c + u.rho * Vec2{std::cos(u.phi0), std::sin(u.phi0)};
    }
  }
  it.lo_x = it.lo_z = INFINITY;
  it.hi_x = it.hi_z = -INFINITY;
  for (std::size_t j = 0; j < n; ++j) {
    UPiece& u = it.loop[j];
    u.b = it.loop[(j + 1) % n].a;
    const Vec2 lo =
        u.arc ? u.c - Vec2{u.rho, u.rho} : Vec2{std::min(u.a.x, u.b.x), std::min(u.a.z, u.b.z)};
    const Vec2 hi =
        u.arc ? u.c + Vec2{u.rho, u.rho} : Vec2{std::max(u.a.x, u.b.x), std::max(u.a.z, u.b.z)};
    it.lo_x = std::min(it.lo_x, lo.x);
    it.lo_z = std::min(it.lo_z, lo.z);
    it.hi_x = std::max(it.hi_x, hi.x);
    it.hi_z = std::max(it.hi_z, hi.z);
  }
  return it;
}

/// Solid s in grid units (a full circle, a polygon or a loop of pieces), or false when it lies
/// outside the window box `wbox` (world units).
bool add_solid_item(int s, const SolidPlacement& sp, const GridWindow& window,
                    const core::Box2& wbox, std::vector<Item>& items) {
  if (!sp.shape)
    throw core::InputError("cut cells: solid " + std::to_string(sp.id) + " has no shape");
  const double R = sp.shape->bounding_radius();
  if (sp.pose.x.x + R < wbox.lo.x || sp.pose.x.x - R > wbox.hi.x || sp.pose.x.z + R < wbox.lo.z ||
      sp.pose.x.z - R > wbox.hi.z) {
    return false;
  }
  const Vec2 com = (sp.pose.x - window.origin) / window.h;
  const std::vector<BoundaryPiece> boundary = sp.shape->boundary();
  if (boundary.empty()) {
    throw core::InputError("cut cells: solid " + std::to_string(sp.id) + " of kind '" +
                           sp.shape->kind() + "' has an empty boundary");
  }
  const auto* first_arc = std::get_if<Arc>(&boundary[0]);
  bool all_segments = true;
  for (const auto& piece : boundary)
    all_segments = all_segments && std::holds_alternative<Segment>(piece);
  if (boundary.size() == 1 && first_arc && first_arc->phi1 - first_arc->phi0 >= kTwoPi) {
    items.push_back(make_circle_item(s, *first_arc, sp, window));
  } else if (all_segments) {
    std::vector<Vec2> verts;
    for (const auto& piece : boundary)
      verts.push_back(sp.pose.to_world(std::get<Segment>(piece).a));
    items.push_back(make_polygon_item(s, verts, window));
  } else {
    items.push_back(make_loop_item(s, boundary, sp, window));
  }
  items.back().com = com;
  const ShapePtr shape = sp.shape;
  const Pose pose = sp.pose;
  items.back().contains_world = [shape, pose](const Vec2& p) {
    return shape->contains(pose.to_body(p));
  };
  return true;
}

/// The solids, then the obstacles' polygons, that reach the window grown by one cell.
std::vector<Item> make_items(const std::vector<SolidPlacement>& solids,
                             const std::vector<Obstacle>& obstacles, const Builder& bd) {
  const GridWindow& window = bd.win;
  std::vector<Item> items;
  const core::Box2 wbox{window.origin + window.h * Vec2{double(bd.W.i0), double(bd.W.k0)},
                        window.origin + window.h * Vec2{double(bd.W.i1), double(bd.W.k1)}};
  for (std::size_t s = 0; s < solids.size(); ++s)
    add_solid_item(static_cast<int>(s), solids[s], window, wbox, items);
  for (std::size_t o = 0; o < obstacles.size(); ++o) {
    for (const auto& poly : obstacles[o].polygons) {
      Item it = make_polygon_item(-1 - static_cast<int>(o), poly, window);
      if (it.hi_x < bd.W.i0 - 1 || it.lo_x > bd.W.i1 + 1 || it.hi_z < bd.W.k0 - 1 ||
          it.lo_z > bd.W.k1 + 1) {
        continue;
      }
      std::vector<K::Point_2> pts;
      for (const auto& p : poly) pts.emplace_back(p.x, p.z);
      it.contains_world = [pts](const Vec2& p) {
        return CGAL::bounded_side_2(pts.begin(), pts.end(), K::Point_2(p.x, p.z), K()) !=
               CGAL::ON_UNBOUNDED_SIDE;
      };
      items.push_back(std::move(it));
    }
  }
  return items;
}

/// Items whose boxes overlap (candidates for hiding each other's boundary), sorted per item.
std::vector<std::vector<int>> overlapping_items(const std::vector<Item>& items) {
  std::vector<std::vector<int>> neighbours(items.size());
  std::vector<int> order(items.size());
  for (std::size_t j = 0; j < items.size(); ++j) order[j] = static_cast<int>(j);
  std::sort(order.begin(), order.end(),
            [&items](int a, int b) { return items[a].lo_x < items[b].lo_x; });
  for (std::size_t a = 0; a < order.size(); ++a) {
    const Item& p = items[order[a]];
    for (std::size_t b = a + 1; b < order.size() && items[order[b]].lo_x <= p.hi_x; ++b) {
      const Item& q = items[order[b]];
      if (q.lo_z <= p.hi_z && p.lo_z <= q.hi_z) {
        neighbours[order[a]].push_back(order[b]);
        neighbours[order[b]].push_back(order[a]);
      }
    }
  }
  for (auto& nb : neighbours) std::sort(nb.begin(), nb.end());
  return neighbours;
}

/// One body: its boundary split at the grid lines, its covered faces and intervals, its visible
/// pieces, and its covered area per cell.
void add_item(const Item& it, const std::vector<Item>& items, const std::vector<int>& neighbours,
              Builder& bd) {
  // Cells that this item can touch: its bounding box plus one cell (pieces lying on a line
  // belong to the cell outside), clipped to the grown window.
  bd.B = IndexBox{floor_int(it.lo_x) - 1, floor_int(it.hi_x) + 2, floor_int(it.lo_z) - 1,
                  floor_int(it.hi_z) + 2}
             .intersect(bd.W);
  if (bd.B.empty()) return;
  const int bnx = bd.B.nx(), bnz = bd.B.nz();
  auto reset = [](auto& v, std::size_t n) {
    if (v.size() < n) v.resize(n);
    for (std::size_t j = 0; j < n; ++j) v[j].clear();
  };
  reset(bd.lx, bnx + 1);
  reset(bd.lz, bnz + 1);
  reset(bd.ex_plus, bnx + 1);
  reset(bd.ex_minus, bnx + 1);
  reset(bd.ez_plus, bnz + 1);
  reset(bd.ez_minus, bnz + 1);
  bd.subs.clear();
  split_item(it, bd);
  item_face_coverage(bd);
  // Boundary pieces: drop those inside another body (union), add area terms, chain by cell.
  item_pieces(it, items, neighbours, bd);
  item_cell_areas(it, bd);
}

}  // namespace

CutCells build_cut_cells(const GridWindow& window, const std::vector<SolidPlacement>& solids,
                         const std::vector<Obstacle>& obstacles, const CutCellOptions& options) {
  if (!(window.h > 0.0)) {
    std::ostringstream m;
    m << "cut cells: grid cell size h = " << window.h << " is not allowed: it must be > 0";
    throw core::InputError(m.str());
  }
  Builder bd;
  bd.win = window;
  const IndexBox grown = window.cells.grown(1);
  bd.W = grown;  // the items that reach the grown window
  const std::vector<Item> items = make_items(solids, obstacles, bd);
  // Then W shrinks to the cells the items can touch (add_item's boxes) and one more: every cell
  // outside is an uncut cell's, which the accessors give without storage (a window mostly of
  // water or air costs what its bodies cover).
  IndexBox reach{grown.i1, grown.i0, grown.k1, grown.k0};
  for (const Item& it : items)
    reach = {std::min(reach.i0, floor_int(it.lo_x) - 2), std::max(reach.i1, floor_int(it.hi_x) + 3),
             std::min(reach.k0, floor_int(it.lo_z) - 2),
             std::max(reach.k1, floor_int(it.hi_z) + 3)};
  bd.W = reach.intersect(grown);
  if (bd.W.empty()) bd.W = {grown.i0, grown.i0, grown.k0, grown.k0};
  bd.nwx = bd.W.nx();
  bd.nwz = bd.W.nz();
  const std::size_t ncell = static_cast<std::size_t>(bd.nwx) * bd.nwz;
  bd.gx.resize(bd.nwx + 1);
  bd.gz.resize(bd.nwz + 1);
  bd.covered.assign(ncell, 0.0);
  bd.best_solid_area.assign(ncell, -1.0);
  bd.best_obstacle_area.assign(ncell, -1.0);
  bd.best_solid.assign(ncell, -1);
  bd.best_obstacle.assign(ncell, -1);

  const std::vector<std::vector<int>> neighbours = overlapping_items(items);
  for (std::size_t j = 0; j < items.size(); ++j) add_item(items[j], items, neighbours[j], bd);
  std::vector<int> item_of_solid(solids.size(), 0);
  for (std::size_t j = 0; j < items.size(); ++j) {
    if (items[j].tag >= 0) item_of_solid[items[j].tag] = static_cast<int>(j);
  }

  CutCells cc;
  cc.window = window;
  cc.store = bd.W;
  union_apertures(bd, cc);
  cc.body = bd.best_solid;  // copied: the tiny-cell rule still reads the best areas
  cc.obstacle = std::move(bd.best_obstacle);
  drop_tiny_cells_and_collect(items, item_of_solid, options, bd, cc);
  return cc;
}

namespace {
[[noreturn]] void out_of_window(const char* what, int i, int k, const IndexBox& b) {
  std::ostringstream m;
  m << "CutCells::" << what << "(" << i << ", " << k << ") is outside the window [" << b.i0 << ", "
    << b.i1 << ") x [" << b.k0 << ", " << b.k1 << ")";
  throw std::out_of_range(m.str());
}
}  // namespace

double CutCells::E_x(int i, int k) const {
  const auto& b = window.cells;
  if (i < b.i0 || i > b.i1 || k < b.k0 || k >= b.k1) out_of_window("E_x", i, k, b);
  if (i < store.i0 || i > store.i1 || k < store.k0 || k >= store.k1) return window.h;
  return window.h * ex[(i - store.i0) + static_cast<std::size_t>(k - store.k0) * (store.nx() + 1)];
}
double CutCells::E_z(int i, int k) const {
  const auto& b = window.cells;
  if (i < b.i0 || i >= b.i1 || k < b.k0 || k > b.k1) out_of_window("E_z", i, k, b);
  if (i < store.i0 || i >= store.i1 || k < store.k0 || k > store.k1) return window.h;
  return window.h * ez[(i - store.i0) + static_cast<std::size_t>(k - store.k0) * store.nx()];
}
double CutCells::fluid_fraction(int i, int k) const {
  if (!window.cells.contains(i, k)) out_of_window("fluid_fraction", i, k, window.cells);
  if (!store.contains(i, k)) return 1.0;
  return fraction[(i - store.i0) + static_cast<std::size_t>(k - store.k0) * store.nx()];
}
int CutCells::cutting_body(int i, int k) const {
  if (!window.cells.grown(1).contains(i, k))
    out_of_window("cutting_body", i, k, window.cells.grown(1));
  if (!store.contains(i, k)) return -1;
  return body[(i - store.i0) + static_cast<std::size_t>(k - store.k0) * store.nx()];
}
int CutCells::cutting_obstacle(int i, int k) const {
  if (!window.cells.grown(1).contains(i, k))
    out_of_window("cutting_obstacle", i, k, window.cells.grown(1));
  if (!store.contains(i, k)) return -1;
  return obstacle[(i - store.i0) + static_cast<std::size_t>(k - store.k0) * store.nx()];
}
bool CutCells::dropped(int i, int k) const {
  if (!window.cells.contains(i, k)) out_of_window("dropped", i, k, window.cells);
  if (!store.contains(i, k)) return false;
  return tiny[(i - store.i0) + static_cast<std::size_t>(k - store.k0) * store.nx()] != 0;
}

}  // namespace picdem::geometry
