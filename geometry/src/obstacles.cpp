#include "picdem/geometry/obstacles.hpp"

#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/geometry/polygon.hpp"

namespace picdem::geometry {

void declare_obstacle_parameters(core::ParamSchema& schema) {
  auto& f = schema.family("obstacles",
                          "Fixed obstacles inside the tank (their union); the tank walls are the "
                          "grid's outer faces and need no entry here.");
  auto& box = f.variant("box", "an axis-aligned rectangle");
  box.reals("lo", {0.0, 0.0}, "lower left corner (x, z) [m]").size(2, 2).is_required();
  box.reals("hi", {0.0, 0.0}, "upper right corner (x, z) [m]").size(2, 2).is_required();

  auto& poly = f.variant("polygon", "a simple polygon, vertices counter-clockwise");
  poly.reals("x", {}, "vertex x coordinates [m]").size(3, 1 << 20).is_required();
  poly.reals("z", {}, "vertex z coordinates [m], as many as x").size(3, 1 << 20).is_required();

  auto& line = f.variant("polyline", "a polyline of constant thickness (slopes, baffles)");
  line.reals("x", {}, "point x coordinates [m]").size(2, 1 << 20).is_required();
  line.reals("z", {}, "point z coordinates [m], as many as x").size(2, 1 << 20).is_required();
  line.real("thickness", 0.0, "wall thickness, centred on the polyline [m]")
      .positive()
      .is_required();

  auto& pipe = f.variant("fall_pipe",
                         "a vertical pipe of two walls with a funnel on top; with hole_size > 0 "
                         "the walls are perforated at regular heights");
  pipe.real("centre_x", 0.0, "x of the pipe axis [m]").is_required();
  pipe.real("inner_width", 0.0, "clear width between the walls [m]").positive().is_required();
  pipe.real("wall_thickness", 0.0, "thickness of each wall [m]").positive().is_required();
  pipe.real("bottom", 0.0, "z of the pipe's lower end [m]").is_required();
  pipe.real("top", 0.0, "z of the pipe's upper end, where the funnel starts [m]").is_required();
  pipe.real("funnel_top_width", 0.0, "clear width at the funnel's top [m] (0: no funnel)")
      .non_negative();
  pipe.real("funnel_height", 0.0, "height of the funnel above 'top' [m] (0: no funnel)")
      .non_negative();
  pipe.real("hole_size", 0.0, "height of each hole through the walls [m] (0: continuous walls)")
      .non_negative();
  pipe.real("hole_spacing", 0.0,
            "distance between hole centres, the first at bottom + spacing / 2 [m]")
      .non_negative();
  // Per obstacle: the viscous condition on its boundary (doc/viscous.md)
  for (auto* v : {&box, &poly, &line, &pipe})
    v->string("wall", "no_slip", {"no_slip", "free_slip"},
              "viscous condition on the boundary with fluid/viscosity_scheme: implicit: no_slip, "
              "or free_slip (the tangential legs dropped: exact on grid-aligned edges only; "
              "doc/viscous.md)");
}

namespace {

std::vector<Vec2> zip(const core::Params& p, const std::string& name) {
  const auto x = p.reals("x"), z = p.reals("z");
  if (x.size() != z.size()) {
    throw core::InputError("keys '" + p.full_path("x") + "' and '" + p.full_path("z") + "' have " +
                           std::to_string(x.size()) + " and " + std::to_string(z.size()) +
                           " values; they must have as many (" + name + ")");
  }
  std::vector<Vec2> v;
  for (std::size_t j = 0; j < x.size(); ++j) v.push_back({x[j], z[j]});
  return v;
}

}  // namespace

std::vector<Vec2> thick_polyline(const std::vector<Vec2>& pts, double t, const std::string& what) {
  if (pts.size() < 2 || !(t > 0.0)) {
    throw core::InputError(what + ": a polyline needs at least 2 points and a thickness > 0");
  }
  std::vector<Vec2> n;  // left unit normal of each segment
  for (std::size_t j = 0; j + 1 < pts.size(); ++j) {
    const Vec2 d = pts[j + 1] - pts[j];
    const double L = core::norm(d);
    if (L == 0.0) {
      throw core::InputError(what + ": points " + std::to_string(j) + " and " +
                             std::to_string(j + 1) + " coincide");
    }
    n.push_back(core::perp(d) / L);
  }
  std::vector<Vec2> offset(pts.size());  // left offset of each point
  for (std::size_t j = 0; j < pts.size(); ++j) {
    if (j == 0) {
      offset[j] = 0.5 * t * n.front();
    } else if (j + 1 == pts.size()) {
      offset[j] = 0.5 * t * n.back();
    } else {
      const double c = 1.0 + core::dot(n[j - 1], n[j]);
      if (c < 0.25) {
        std::ostringstream m;
        m << what << ": the turn at point " << j << " is sharper than allowed (more than ~140 "
          << "degrees); split the polyline there";
        throw core::InputError(m.str());
      }
      // mitre: (n1 + n2) / (1 + n1 . n2) * t / 2
      offset[j] = (0.5 * t / c) * (n[j - 1] + n[j]);
    }
  }
  std::vector<Vec2> poly;
  for (std::size_t j = 0; j < pts.size(); ++j) poly.push_back(pts[j] - offset[j]);
  for (std::size_t j = pts.size(); j-- > 0;) poly.push_back(pts[j] + offset[j]);
  validate_simple_ccw(poly, what);
  return poly;
}

std::vector<std::vector<Vec2>> fall_pipe_polygons(const FallPipe& p, const std::string& what) {
  auto fail = [&what](const std::string& m) { throw core::InputError(what + ": " + m); };
  if (!(p.top > p.bottom)) fail("'top' must be above 'bottom'");
  const bool funnel = p.funnel_height > 0.0 && p.funnel_top_width > 0.0;
  if (funnel && p.funnel_top_width < p.inner_width) {
    fail("'funnel_top_width' must be at least 'inner_width' (a funnel widens upwards)");
  }
  if (p.hole_size > 0.0 && !(p.hole_spacing > p.hole_size)) {
    fail("'hole_spacing' must exceed 'hole_size' when the walls are perforated");
  }
  // Each hole splits both walls into one more polygon: a count beyond this is a mistyped size
  // (e.g. a top of 1e30), and counting the holes one by one would not end (zc + spacing == zc).
  constexpr double max_holes = 10000.0;
  if (p.hole_size > 0.0 && (p.top - p.bottom) / p.hole_spacing > max_holes) {
    std::ostringstream m;
    m << "'top' - 'bottom' = " << p.top - p.bottom << " m with 'hole_spacing' = " << p.hole_spacing
      << " m gives " << (p.top - p.bottom) / p.hole_spacing << " holes per wall; allowed: at most "
      << max_holes << " (check the pipe's heights and the hole spacing)";
    fail(m.str());
  }
  const double a = 0.5 * p.inner_width, t = p.wall_thickness, cx = p.centre_x;
  auto rect = [](double x0, double x1, double z0, double z1) {
    return std::vector<Vec2>{{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}};
  };
  // Wall pieces between the holes, bottom to top.
  std::vector<std::pair<double, double>> spans;
  if (p.hole_size > 0.0) {
    double z = p.bottom;
    for (double zc = p.bottom + 0.5 * p.hole_spacing; zc + 0.5 * p.hole_size < p.top;
         zc += p.hole_spacing) {
      spans.push_back({z, zc - 0.5 * p.hole_size});
      z = zc + 0.5 * p.hole_size;
    }
    spans.push_back({z, p.top});
  } else {
    spans.push_back({p.bottom, p.top});
  }
  std::vector<std::vector<Vec2>> out;
  for (const auto& [z0, z1] : spans) {
    if (z1 <= z0) continue;
    out.push_back(rect(cx - a - t, cx - a, z0, z1));
    out.push_back(rect(cx + a, cx + a + t, z0, z1));
  }
  if (funnel) {
    const double A = 0.5 * p.funnel_top_width, zt = p.top + p.funnel_height;
    out.push_back({{cx - a - t, p.top}, {cx - a, p.top}, {cx - A, zt}, {cx - A - t, zt}});
    out.push_back({{cx + a, p.top}, {cx + a + t, p.top}, {cx + A + t, zt}, {cx + A, zt}});
  }
  for (const auto& poly : out) validate_simple_ccw(poly, what);
  return out;
}

std::vector<std::vector<Vec2>> outlines(const Obstacle& obstacle) {
  std::vector<std::vector<Vec2>> out;
  for (const auto& poly : obstacle.polygons) {
    out.push_back(poly);
    if (!poly.empty()) out.back().push_back(poly.front());
  }
  return out;
}

std::vector<Obstacle> obstacles_from(const core::Params& params) {
  std::vector<Obstacle> out;
  if (!params.has("obstacles")) return out;
  for (const auto& name : params.sublist_names("obstacles")) {
    const core::Params p = params.sub("obstacles/" + name);
    const std::string what = "obstacle '" + p.full_path("") + "'";
    const std::string type = p.string("type");
    Obstacle o;
    o.name = name;
    if (type == "box") {
      const auto lo = p.reals("lo"), hi = p.reals("hi");
      if (!(hi[0] > lo[0] && hi[1] > lo[1])) {
        throw core::InputError("key '" + p.full_path("hi") + "' must lie above and right of '" +
                               p.full_path("lo") + "'");
      }
      o.polygons.push_back({{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}});
    } else if (type == "polygon") {
      auto v = zip(p, what);
      validate_simple_ccw(v, what + " (keys x, z)");
      o.polygons.push_back(std::move(v));
    } else if (type == "polyline") {
      o.polygons.push_back(thick_polyline(zip(p, what), p.real("thickness"), what));
    } else if (type == "fall_pipe") {
      FallPipe f;
      f.centre_x = p.real("centre_x");
      f.inner_width = p.real("inner_width");
      f.wall_thickness = p.real("wall_thickness");
      f.bottom = p.real("bottom");
      f.top = p.real("top");
      f.funnel_top_width = p.real("funnel_top_width");
      f.funnel_height = p.real("funnel_height");
      f.hole_size = p.real("hole_size");
      f.hole_spacing = p.real("hole_spacing");
      o.polygons = fall_pipe_polygons(f, what);
    }
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace picdem::geometry
