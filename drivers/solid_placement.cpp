#include "solid_placement.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <variant>

#include "picdem/core/error.hpp"
#include "picdem/dem/contact_geometry.hpp"
#include "picdem/geometry/obstacles.hpp"
#include "picdem/geometry/overlap.hpp"
#include "picdem/geometry/shape_registry.hpp"

namespace picdem::driver {

using core::Vec2;
using geometry::Arc;
using geometry::BoundaryPiece;
using geometry::Segment;

namespace {

/// A solid or an obstacle polygon in the world frame.
struct Outline {
  std::string what;  ///< "solids/NAME[k] (id N)" or "obstacles/NAME"
  std::vector<BoundaryPiece> world;
  core::Box2 box;
  double circle_radius = 0.0;  ///< > 0: a full circle centred at `centre` (closed form)
  Vec2 centre;
  /// Convex loops whose union is the region (the outline itself when convex; a non-convex polygon
  /// partitioned); empty for a non-convex outline with arcs (no registered shape has one).
  std::vector<std::vector<BoundaryPiece>> convex_parts;
  std::function<bool(const Vec2&)> inside;  ///< closed region test in the world frame
  double density = 0.0;                     ///< a solid's density [kg/m^3]; 0 for an obstacle
  double size() const { return std::max(box.hi.x - box.lo.x, box.hi.z - box.lo.z); }
};

core::Box2 box_of(const std::vector<BoundaryPiece>& world) {
  const Vec2 hi{dem::support_point(world, {1.0, 0.0}).x, dem::support_point(world, {0.0, 1.0}).z};
  const Vec2 lo{dem::support_point(world, {-1.0, 0.0}).x, dem::support_point(world, {0.0, -1.0}).z};
  return {lo, hi};
}

/// Points along every piece (16 per piece and its end), where overlap depths are measured.
std::vector<Vec2> samples(const std::vector<BoundaryPiece>& world) {
  constexpr int per_piece = 16;
  std::vector<Vec2> out;
  for (const auto& piece : world) {
    for (int k = 0; k <= per_piece; ++k) {
      const double t = static_cast<double>(k) / per_piece;
      if (const auto* s = std::get_if<Segment>(&piece)) {
        out.push_back(s->a + t * (s->b - s->a));
      } else {
        const auto& a = std::get<Arc>(piece);
        const double phi = a.phi0 + t * (a.phi1 - a.phi0);
        out.push_back(a.centre + a.radius * Vec2{std::cos(phi), std::sin(phi)});
      }
    }
  }
  return out;
}

double distance_to(const std::vector<BoundaryPiece>& world, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& piece : world) {
    const Vec2 q = std::holds_alternative<Segment>(piece)
                       ? dem::closest_on_segment(std::get<Segment>(piece), p)
                       : dem::closest_on_arc(std::get<Arc>(piece), p);
    best = std::min(best, core::norm(q - p));
  }
  return best;
}

/// Only for an outline with no convex parts (a non-convex shape with arcs, which no registered
/// shape has): how deep the deepest of 16 points per piece of one outline (and the closest
/// points) lies inside the other [m]: a lower bound.
double sampled_depth(const Outline& a, const Outline& b) {
  const dem::ClosestPoints cp = dem::closest_points(a.world, b.world);
  double depth = 0.0;
  for (const auto& [from, into] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
    auto points = samples(from->world);
    points.push_back(from == &a ? cp.on_a : cp.on_b);
    for (const Vec2& p : points)
      if (into->inside(p)) depth = std::max(depth, distance_to(into->world, p));
  }
  return depth;
}

/// The overlap depth of two outlines [m]; <= 0 when they are apart or only touch. Circles in
/// closed form (r_a + r_b - d); otherwise exactly, the largest penetration depth over the pairs
/// of their convex parts (geometry/overlap.hpp).
double overlap_depth(const Outline& a, const Outline& b) {
  if (a.circle_radius > 0.0 && b.circle_radius > 0.0)
    return a.circle_radius + b.circle_radius - core::norm(a.centre - b.centre);
  if (a.convex_parts.empty() || b.convex_parts.empty()) return sampled_depth(a, b);
  return geometry::overlap_depth(a.convex_parts, b.convex_parts);
}

/// The convex parts of a closed loop (see Outline::convex_parts).
std::vector<std::vector<BoundaryPiece>> convex_parts(const std::vector<BoundaryPiece>& loop) {
  if (geometry::is_convex_loop(loop)) return {loop};
  std::vector<Vec2> vertices;
  for (const auto& piece : loop) {
    if (!std::holds_alternative<Segment>(piece)) return {};
    vertices.push_back(std::get<Segment>(piece).a);
  }
  std::vector<std::vector<BoundaryPiece>> parts;
  for (const auto& p : geometry::convex_partition(vertices))
    parts.push_back(geometry::polygon_loop(p));
  return parts;
}

bool in_polygon(const std::vector<Vec2>& poly, const Vec2& p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 &u = poly[i], &v = poly[j];
    if ((u.z > p.z) != (v.z > p.z) && p.x < u.x + (p.z - u.z) * (v.x - u.x) / (v.z - u.z)) in = !in;
  }
  return in;
}

std::vector<Outline> solid_outlines(const core::Params& params) {
  std::vector<Outline> out;
  if (!params.has("solids")) return out;
  geometry::BuildContext ctx;  // as dem::solids_from builds them
  ctx.gap = params.real("dem/gap_cells") * params.real("grid/cell_size");
  for (const auto& name : params.sublist_names("solids")) {
    const core::Params s = params.sub("solids/" + name);
    std::vector<geometry::PlacedShape> placed;
    try {
      placed = geometry::shape_type(s.string("type")).build(s, ctx);
    } catch (const core::InputError& e) {
      // Name the solid once: a shape's own message may already start with its path.
      const std::string what = e.what(), path = "solids/" + name;
      throw core::InputError(what.rfind(path, 0) == 0 ? what : path + ": " + what);
    }
    for (std::size_t k = 0; k < placed.size(); ++k) {
      Outline o;
      o.what = "solids/" + name + (placed.size() > 1 ? "[" + std::to_string(k) + "]" : "") +
               " (id " + std::to_string(out.size()) + ")";
      const auto shape = placed[k].shape;
      const auto pose = placed[k].pose;
      o.world = dem::to_world(shape->boundary(), pose);
      o.convex_parts = convex_parts(o.world);
      o.circle_radius = shape->fast_paths().centred_circle_radius;
      o.centre = pose.x;
      o.box = box_of(o.world);
      o.inside = [shape, pose](const Vec2& p) { return shape->contains(pose.to_body(p)); };
      o.density = placed[k].density > 0.0 ? placed[k].density : s.real("density");
      out.push_back(std::move(o));
    }
  }
  return out;
}

// The pressure system holds the fluid's terms (1 / fluid/density) beside each solid's (1 / its
// mass): a solid lighter than 1e-10 of the fluid's density makes them differ by more than the
// solve's round-off carries (floating_disk, 30 steps: a ratio of 5e-10 runs, 5e-12 stops with the
// pressure solve unconverged, 5e-28 with the flow blown up). No real solid comes near it; a
// mistyped fluid/density does.
void check_density_ratio(double fluid_density, const std::vector<Outline>& solids,
                         std::vector<std::string>& errors) {
  constexpr double lightest = 1e-10;
  for (const auto& s : solids)
    if (s.density < lightest * fluid_density) {
      std::ostringstream m;
      m << s.what << ": density " << s.density
        << " kg/m^3 against fluid/density = " << fluid_density << " kg/m^3: a solid lighter than "
        << lightest
        << " of the fluid's density is more than the pressure system's round-off can carry "
           "(doc/parameters.md); check fluid/density and the solid's density";
      errors.push_back(m.str());
    }
}

std::vector<Outline> obstacle_outlines(const core::Params& params) {
  std::vector<Outline> out;
  for (const auto& obstacle : geometry::obstacles_from(params)) {
    for (const auto& poly : obstacle.polygons) {
      Outline o;
      o.what = "obstacles/" + obstacle.name;
      for (std::size_t i = 0; i < poly.size(); ++i)
        o.world.emplace_back(Segment{poly[i], poly[(i + 1) % poly.size()]});
      o.box = box_of(o.world);
      o.convex_parts = convex_parts(o.world);
      o.inside = [poly](const Vec2& p) { return in_polygon(poly, p); };
      out.push_back(std::move(o));
    }
  }
  return out;
}

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

std::string overlap_message(const Outline& a, const Outline& b, double depth, double allowed) {
  return a.what + " and " + b.what + " overlap by " + fmt(depth) +
         " m; allowed: real boundaries at least " + fmt(allowed) +
         " m apart (the DEM's contact gap less dem/theta cells)";
}

core::Box2 grown(const core::Box2& b, double by) {
  return {{b.lo.x - by, b.lo.z - by}, {b.hi.x + by, b.hi.z + by}};
}

/// Calls f(i, j) once for every pair i < j of boxes that overlap, through a grid of buckets of
/// the median box size (at most about 4 buckets per box): a pair is visited in the bucket holding
/// the low corner of the boxes' intersection.
void box_pairs(const std::vector<core::Box2>& s,
               const std::function<void(std::size_t, std::size_t)>& f) {
  if (s.size() < 2) return;
  core::Box2 all = s[0];
  std::vector<double> sizes;
  for (const auto& b : s) {
    all.lo = {std::min(all.lo.x, b.lo.x), std::min(all.lo.z, b.lo.z)};
    all.hi = {std::max(all.hi.x, b.hi.x), std::max(all.hi.z, b.hi.z)};
    sizes.push_back(std::max(b.hi.x - b.lo.x, b.hi.z - b.lo.z));
  }
  std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
  const double w = all.hi.x - all.lo.x, hgt = all.hi.z - all.lo.z;
  double c = std::max(sizes[sizes.size() / 2], 1e-12 * std::max(w, hgt));
  const double max_buckets = 4.0 * static_cast<double>(s.size()) + 16.0;
  while ((w / c + 1.0) * (hgt / c + 1.0) > max_buckets) c *= 1.5;
  const int nx = static_cast<int>(w / c) + 1, nz = static_cast<int>(hgt / c) + 1;
  auto ix = [&](double x) { return std::clamp(static_cast<int>((x - all.lo.x) / c), 0, nx - 1); };
  auto iz = [&](double z) { return std::clamp(static_cast<int>((z - all.lo.z) / c), 0, nz - 1); };
  std::vector<std::vector<std::size_t>> buckets(static_cast<std::size_t>(nx) * nz);
  for (std::size_t n = 0; n < s.size(); ++n)
    for (int k = iz(s[n].lo.z); k <= iz(s[n].hi.z); ++k)
      for (int i = ix(s[n].lo.x); i <= ix(s[n].hi.x); ++i)
        buckets[static_cast<std::size_t>(k) * nx + i].push_back(n);
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      const auto& b = buckets[static_cast<std::size_t>(k) * nx + i];
      for (std::size_t p = 0; p < b.size(); ++p)
        for (std::size_t q = p + 1; q < b.size(); ++q) {
          const core::Box2 &u = s[b[p]], &v = s[b[q]];
          if (!u.overlaps(v)) continue;
          if (ix(std::max(u.lo.x, v.lo.x)) != i || iz(std::max(u.lo.z, v.lo.z)) != k) continue;
          f(std::min(b[p], b[q]), std::max(b[p], b[q]));
        }
    }
}

void check_in_tank(const core::Box2& tank, const std::vector<Outline>& solids,
                   std::vector<std::string>& errors) {
  for (const auto& s : solids) {
    const double out = std::max({tank.lo.x - s.box.lo.x, s.box.hi.x - tank.hi.x,
                                 tank.lo.z - s.box.lo.z, s.box.hi.z - tank.hi.z});
    if (out <= 0.0) continue;
    errors.push_back(s.what + " reaches " + fmt(out) +
                     " m outside the tank: its outline spans x in [" + fmt(s.box.lo.x) + ", " +
                     fmt(s.box.hi.x) + "], z in [" + fmt(s.box.lo.z) + ", " + fmt(s.box.hi.z) +
                     "]; allowed: inside the tank x in [" + fmt(tank.lo.x) + ", " + fmt(tank.hi.x) +
                     "], z in [" + fmt(tank.lo.z) + ", " + fmt(tank.hi.z) +
                     "] (grid/origin, grid/length, grid/height), and the DEM's contact gap "
                     "from each wall");
  }
}

// An obstacle is geometry of the tank: a vertex farther from the tank than the tank's own length
// (or height) is a mistyped size (e.g. a fall pipe's wall_thickness of 1e30), which would also
// drown the overlap depths below in round-off.
void check_obstacles_near_tank(const core::Box2& tank, const std::vector<Outline>& obstacles,
                               std::vector<std::string>& errors) {
  const double lx = tank.hi.x - tank.lo.x, lz = tank.hi.z - tank.lo.z;
  const core::Box2 near{{tank.lo.x - lx, tank.lo.z - lz}, {tank.hi.x + lx, tank.hi.z + lz}};
  std::string last;
  for (const auto& ob : obstacles) {
    if (ob.what == last) continue;  // one message per obstacle entry
    const core::Box2& b = ob.box;
    if (b.lo.x >= near.lo.x && b.hi.x <= near.hi.x && b.lo.z >= near.lo.z && b.hi.z <= near.hi.z)
      continue;
    last = ob.what;
    errors.push_back(ob.what + " reaches x in [" + fmt(b.lo.x) + ", " + fmt(b.hi.x) + "], z in [" +
                     fmt(b.lo.z) + ", " + fmt(b.hi.z) +
                     "]: check its sizes and coordinates; allowed: within one tank length and "
                     "height of the tank, x in [" +
                     fmt(near.lo.x) + ", " + fmt(near.hi.x) + "], z in [" + fmt(near.lo.z) + ", " +
                     fmt(near.hi.z) + "] (grid/origin, grid/length, grid/height)");
  }
}

// An obstacle wholly outside the tank cuts no cell and has no effect: a misplaced coordinate (a
// centre_x with the wrong sign, a tank shortened by an override). Touching a wall from outside
// counts as outside.
void check_obstacles_reach_tank(const core::Box2& tank, const std::vector<Outline>& obstacles,
                                std::vector<std::string>& errors) {
  for (std::size_t i = 0; i < obstacles.size();) {
    const std::string& what = obstacles[i].what;
    core::Box2 b = obstacles[i].box;
    std::size_t j = i + 1;
    for (; j < obstacles.size() && obstacles[j].what == what; ++j) {
      b.lo.x = std::min(b.lo.x, obstacles[j].box.lo.x);
      b.lo.z = std::min(b.lo.z, obstacles[j].box.lo.z);
      b.hi.x = std::max(b.hi.x, obstacles[j].box.hi.x);
      b.hi.z = std::max(b.hi.z, obstacles[j].box.hi.z);
    }
    i = j;
    if (b.hi.x > tank.lo.x && b.lo.x < tank.hi.x && b.hi.z > tank.lo.z && b.lo.z < tank.hi.z)
      continue;
    errors.push_back(what + " spans x in [" + fmt(b.lo.x) + ", " + fmt(b.hi.x) + "], z in [" +
                     fmt(b.lo.z) + ", " + fmt(b.hi.z) + "], wholly outside the tank x in [" +
                     fmt(tank.lo.x) + ", " + fmt(tank.hi.x) + "], z in [" + fmt(tank.lo.z) + ", " +
                     fmt(tank.hi.z) +
                     "]: it would have no effect; check its coordinates (or grid/origin, "
                     "grid/length, grid/height)");
  }
}

/// The narrowest width of an outline's convex hull over all directions: at a segment's normal
/// (where a polygon's is attained) or at one of 720 directions (the arcs'; a full circle exactly).
double narrowest_width(const Outline& o) {
  if (o.circle_radius > 0.0) return 2.0 * o.circle_radius;
  const auto width = [&](Vec2 d) {
    return core::dot(dem::support_point(o.world, d) - dem::support_point(o.world, -1.0 * d), d);
  };
  double w = std::numeric_limits<double>::infinity();
  bool arcs = false;
  for (const auto& piece : o.world) {
    if (const auto* g = std::get_if<Segment>(&piece)) {
      const Vec2 t = g->b - g->a;
      const double l = std::sqrt(core::norm2(t));
      if (l > 0.0) w = std::min(w, width(Vec2{-t.z / l, t.x / l}));
    } else {
      arcs = true;
    }
  }
  if (arcs)
    for (int k = 0; k < 720; ++k) {
      const double a = k * (3.141592653589793 / 720.0);
      w = std::min(w, width(Vec2{std::cos(a), std::sin(a)}));
    }
  return w;
}

// With water, a solid or obstacle thinner than a cell can lie between two grid lines across its
// thickness and close no cell face there: the pressure equation would let the water through it
// (a plate 0.5 mm thick in 2 mm cells sank in bursts, its speed dropping sevenfold each time it
// crossed a grid line), and one narrower than a cell both ways would not be seen at all (a radius
// typed in mm as m, or a grid far too coarse). Widths are the convex hull's: a thin arm of a
// non-convex polygon is not caught. Dry runs use the grid for nothing of the solids.
void check_resolved(double h, const std::vector<Outline>& outlines,
                    std::vector<std::string>& errors) {
  for (const auto& o : outlines) {
    const double w = narrowest_width(o);
    if (w >= h) continue;
    errors.push_back(o.what + " is " + fmt(w) +
                     " m across at its narrowest, less than one cell (grid/cell_size = " + fmt(h) +
                     " m): lying between two grid lines it closes no cell face across that width, "
                     "so the water would flow through it; allowed: at least one cell across in "
                     "every direction when the case has water (the paper resolves a cylinder with "
                     "20 cells): refine the grid or thicken the body");
  }
}

/// Solids start force-free only when their real boundaries lie at least the DEM's imaginary gap
/// apart (eq. 19: the contact spring starts at the gap). Closer, the spring starts compressed by
/// gap - distance, which eq. 10's stiffness (the heaviest solid's weight presses a contact by
/// theta cells) turns into that many weights: a disk placed on the floor with the default gap of
/// 2 cells and theta 0.01 starts under 200 weights. With water the first step blew up (a particle
/// at 19 m/s at step 1, 2 mm cells); dry, the solid is thrown up. A compression up to theta cells
/// (the heaviest weight, what a resting contact carries) is let through.
struct ContactGap {
  double gap = 0.0;    ///< dem/gap_cells x grid/cell_size [m]
  double press = 0.0;  ///< dem/theta x grid/cell_size: one heaviest weight's compression [m]
  double allowed() const { return gap - press; }
};

ContactGap contact_gap_of(const core::Params& params) {
  const double h = params.real("grid/cell_size");
  return {params.real("dem/gap_cells") * h, params.real("dem/theta") * h};
}

std::string gap_message(const std::string& a, const std::string& b, double distance,
                        const ContactGap& g) {
  return a + " and " + b + " are " + fmt(distance) + " m apart, inside the contact gap " +
         fmt(g.gap) +
         " m (dem/gap_cells x grid/cell_size, eq. 19): their contact would start compressed by " +
         fmt(g.gap - distance) + " m, " + fmt((g.gap - distance) / g.press) +
         " times what the heaviest solid's weight presses (dem/theta x grid/cell_size = " +
         fmt(g.press) + " m, eq. 10), and throw them apart at the first step; allowed: at least " +
         fmt(g.allowed()) +
         " m apart (the gap less dem/theta cells), as the cylinder stacks and packings place "
         "them";
}

/// The distance between the real boundaries of two outlines that do not overlap [m].
double distance_apart(const Outline& a, const Outline& b) {
  if (a.circle_radius > 0.0 && b.circle_radius > 0.0)
    return core::norm(a.centre - b.centre) - a.circle_radius - b.circle_radius;
  return dem::closest_points(a.world, b.world).distance;
}

void check_wall_gaps(const core::Box2& tank, const std::vector<Outline>& solids,
                     const ContactGap& g, std::vector<std::string>& errors) {
  static const char* names[4] = {"left", "right", "bottom", "top"};
  for (const auto& s : solids) {
    const double d[4] = {s.box.lo.x - tank.lo.x, tank.hi.x - s.box.hi.x, s.box.lo.z - tank.lo.z,
                         tank.hi.z - s.box.hi.z};
    for (int k = 0; k < 4; ++k)
      if (d[k] >= 0.0 && d[k] < g.allowed())
        errors.push_back(
            gap_message(s.what, std::string("the tank's ") + names[k] + " wall", d[k], g));
  }
}

core::Box2 tank_of(const core::Params& params) {
  const auto o = params.reals("grid/origin");
  return {{o[0], o[1]}, {o[0] + params.real("grid/length"), o[1] + params.real("grid/height")}};
}

}  // namespace

std::vector<std::string> check_solid_placement(const core::Params& params,
                                               std::size_t max_messages) {
  std::vector<std::string> errors;
  const core::Box2 tank = tank_of(params);
  const auto obstacles = obstacle_outlines(params);
  check_obstacles_near_tank(tank, obstacles, errors);
  if (errors.empty()) check_obstacles_reach_tank(tank, obstacles, errors);
  if (!errors.empty()) return errors;
  const auto solids = solid_outlines(params);
  check_in_tank(tank, solids, errors);
  check_density_ratio(params.real("fluid/density"), solids, errors);
  if (!params.sublist_names("water").empty()) {
    check_resolved(params.real("grid/cell_size"), solids, errors);
    check_resolved(params.real("grid/cell_size"), obstacles, errors);
  }
  const ContactGap g = contact_gap_of(params);
  // A generator told to leave a smaller gap than the contact's (cylinder_stack, graded_packing):
  // its key is the cause, named once rather than through every pair it places too close.
  const std::size_t before = errors.size();
  for (const auto& name : params.sublist_names("solids")) {
    const core::Params s = params.sub("solids/" + name);
    if (!s.has("gap")) continue;
    const double gap = s.real("gap");
    if (gap > 0.0 && gap < g.allowed())
      errors.push_back("key 'solids/" + name + "/gap' = " + fmt(gap) +
                       " m is less than the DEM's contact gap " + fmt(g.gap) +
                       " m (dem/gap_cells x grid/cell_size, eq. 19): the solids it places would "
                       "start with their contacts compressed and be thrown apart at the first "
                       "step; allowed: 0 (the contact gap, the default) or at least " +
                       fmt(g.allowed()) + " m");
  }
  if (errors.size() > before) return errors;
  check_wall_gaps(tank, solids, g, errors);
  // Overlaps first; pairs apart but inside the gap next (boxes grown by half the gap each).
  const auto check_pair = [&](const Outline& a, const Outline& b) {
    const double depth = overlap_depth(a, b);
    if (depth > 1e-9 * std::max(a.size(), b.size())) {
      errors.push_back(overlap_message(a, b, depth, g.allowed()));
      return;
    }
    const double d = std::max(0.0, distance_apart(a, b));
    if (d < g.allowed()) errors.push_back(gap_message(a.what, b.what, d, g));
  };
  std::vector<core::Box2> boxes;
  boxes.reserve(solids.size());
  for (const auto& s : solids) boxes.push_back(grown(s.box, 0.5 * g.gap));
  box_pairs(boxes, [&](std::size_t i, std::size_t j) { check_pair(solids[i], solids[j]); });
  for (std::size_t i = 0; i < solids.size(); ++i)
    for (const auto& ob : obstacles)
      if (boxes[i].overlaps(grown(ob.box, 0.5 * g.gap))) check_pair(solids[i], ob);
  if (errors.size() > max_messages) {
    const std::size_t more = errors.size() - max_messages;
    errors.resize(max_messages);
    errors.push_back("... and " + std::to_string(more) + " more misplaced solids or overlaps");
  }
  return errors;
}

}  // namespace picdem::driver
