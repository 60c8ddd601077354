// Polygon validation uses CGAL's exact predicates (Epick): a vertex exactly on another edge or
// two collinear overlapping edges are decided without rounding.
#include "picdem/geometry/polygon.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/geometry/shape_registry.hpp"

namespace picdem::geometry {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = K::Point_2;

std::vector<P2> to_cgal(const std::vector<Vec2>& v) {
  std::vector<P2> p;
  p.reserve(v.size());
  for (const auto& q : v) p.emplace_back(q.x, q.z);
  return p;
}

std::string describe(const std::vector<Vec2>& v) {
  std::ostringstream s;
  s << v.size() << " vertices [";
  for (std::size_t j = 0; j < v.size() && j < 6; ++j)
    s << (j ? ", " : "") << "(" << v[j].x << ", " << v[j].z << ")";
  if (v.size() > 6) s << ", ...";
  s << "]";
  return s.str();
}

}  // namespace

void validate_simple_ccw(const std::vector<Vec2>& v, const std::string& what) {
  if (v.size() < 3) {
    throw core::InputError(what + ": " + describe(v) +
                           " is not a polygon: at least 3 vertices are needed");
  }
  for (const auto& q : v) {
    if (!std::isfinite(q.x) || !std::isfinite(q.z)) {
      throw core::InputError(what + ": " + describe(v) + " has a non-finite coordinate");
    }
  }
  const auto p = to_cgal(v);
  for (std::size_t j = 0; j < p.size(); ++j) {
    if (p[j] == p[(j + 1) % p.size()]) {
      throw core::InputError(what + ": " + describe(v) + " repeats vertex " + std::to_string(j) +
                             ": consecutive vertices must differ");
    }
  }
  if (!CGAL::is_simple_2(p.begin(), p.end(), K())) {
    throw core::InputError(what + ": " + describe(v) +
                           " is self-intersecting: a simple polygon (edges meet only at "
                           "consecutive vertices) is required");
  }
  if (CGAL::orientation_2(p.begin(), p.end(), K()) != CGAL::COUNTERCLOCKWISE) {
    throw core::InputError(what + ": " + describe(v) +
                           " is clockwise: vertices must be given counter-clockwise");
  }
}

PolygonProperties polygon_properties(const std::vector<Vec2>& v) {
  validate_simple_ccw(v, "polygon");
  // Shift to the first vertex to keep the sums well conditioned.
  const Vec2 o = v[0];
  double a2 = 0.0;
  Vec2 c6;
  double j12 = 0.0;
  for (std::size_t j = 0; j < v.size(); ++j) {
    const Vec2 p = v[j] - o, q = v[(j + 1) % v.size()] - o;
    const double w = core::cross(p, q);
    // 2A = sum p_j x p_{j+1}
    a2 += w;
    // 6 A c = sum (p_j + p_{j+1}) (p_j x p_{j+1})
    c6 += w * (p + q);
    // 12 J_o = sum (p_j x p_{j+1}) (|p_j|^2 + p_j . p_{j+1} + |p_{j+1}|^2)
    j12 += w * (core::norm2(p) + core::dot(p, q) + core::norm2(q));
  }
  PolygonProperties r;
  r.area = 0.5 * a2;
  const Vec2 c = c6 / (3.0 * a2);
  r.centroid = o + c;
  // J_c = J_o - A |c|^2 (parallel axis)
  r.polar_moment = j12 / 12.0 - r.area * core::norm2(c);
  return r;
}

Polygon::Polygon(std::vector<Vec2> vertices) {
  const PolygonProperties pp = polygon_properties(vertices);
  centroid_offset_ = pp.centroid;
  for (auto& q : vertices) {
    q -= centroid_offset_;
    bounding_radius_ = std::max(bounding_radius_, core::norm(q));
  }
  vertices_ = std::move(vertices);
  mass_ = {pp.area, pp.polar_moment};
}

Polygon Polygon::from_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw core::InputError("polygon vertex file '" + path + "' cannot be opened");
  std::vector<Vec2> v;
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    for (auto& ch : line) {
      if (ch == ',' || ch == ';' || ch == '\t') ch = ' ';
    }
    std::istringstream s(line);
    double x = 0.0, z = 0.0;
    std::string rest;
    if (!(s >> x)) {
      if (line.find_first_not_of(' ') == std::string::npos) continue;
      throw core::InputError("polygon vertex file '" + path + "' line " + std::to_string(n) +
                             ": expected two numbers 'x z', got '" + line + "'");
    }
    if (!(s >> z) || (s >> rest)) {
      throw core::InputError("polygon vertex file '" + path + "' line " + std::to_string(n) +
                             ": expected two numbers 'x z', got '" + line + "'");
    }
    v.push_back({x, z});
  }
  try {
    return Polygon(std::move(v));
  } catch (const core::InputError& e) {
    throw core::InputError("polygon vertex file '" + path + "': " + e.what());
  }
}

std::vector<BoundaryPiece> Polygon::boundary() const {
  std::vector<BoundaryPiece> b;
  b.reserve(vertices_.size());
  for (std::size_t j = 0; j < vertices_.size(); ++j) {
    b.emplace_back(Segment{vertices_[j], vertices_[(j + 1) % vertices_.size()]});
  }
  return b;
}

MassProperties Polygon::mass_properties() const {
  return mass_;
}

bool Polygon::contains(const Vec2& q) const {
  const auto p = to_cgal(vertices_);
  return CGAL::bounded_side_2(p.begin(), p.end(), P2(q.x, q.z), K()) != CGAL::ON_UNBOUNDED_SIDE;
}

namespace {

void declare_theta(core::ParamSchema& v) {
  v.real("theta", 0.0, "initial rotation about the centroid, counter-clockwise [rad]");
}

/// The input vertices are world coordinates at theta = 0: the centroid is the centre.
std::vector<PlacedShape> placed_polygon(const std::vector<Vec2>& vertices, double theta) {
  auto poly = std::make_shared<const Polygon>(vertices);
  return {{poly, {poly->centroid_offset(), theta}}};
}

}  // namespace

/// The pairs x0, z0, x1, z1, ... of the key `key` of `s` as points.
std::vector<Vec2> vertex_pairs(const core::Params& s, const std::string& key) {
  const auto v = s.reals(key);
  if (v.size() % 2 != 0) {
    std::ostringstream m;
    m << "key '" << s.full_path(key) << "' has " << v.size()
      << " numbers; allowed: pairs x, z (an even count >= 6)";
    throw core::InputError(m.str());
  }
  std::vector<Vec2> verts;
  for (std::size_t n = 0; n + 1 < v.size(); n += 2) verts.push_back({v[n], v[n + 1]});
  return verts;
}

ShapeType polygon_type() {
  ShapeType t;
  t.name = "polygon";
  t.doc = "a simple polygon; its centroid is its centre";
  t.declare = [](core::ParamSchema& v) {
    v.reals("vertices", {},
            "x0, z0, x1, z1, ... counter-clockwise, world coordinates at theta = 0 [m]")
        .size(6, 1 << 20)
        .is_required();
    declare_theta(v);
  };
  t.build = [](const core::Params& s, const BuildContext&) {
    return placed_polygon(vertex_pairs(s, "vertices"), s.real("theta"));
  };
  return t;
}

ShapeType polygon_file_type() {
  ShapeType t;
  t.name = "polygon_file";
  t.doc = "a polygon read from a vertex file (one 'x z' per line)";
  t.declare = [](core::ParamSchema& v) {
    v.string("file", "", {},
             "vertex file, counter-clockwise, world coordinates at theta = 0; a relative path is "
             "the case file's folder's (given with --set: the working directory's)")
        .is_required()
        .is_file_path();
    v.reals("offset", {0.0, 0.0}, "shift (x, z) added to every vertex [m]").size(2, 2);
    declare_theta(v);
  };
  t.build = [](const core::Params& s, const BuildContext&) {
    const Polygon file_poly = Polygon::from_file(s.string("file"));
    const auto o = s.reals("offset");
    std::vector<Vec2> verts;
    for (const Vec2& v : file_poly.vertices())
      verts.push_back(v + file_poly.centroid_offset() + Vec2{o[0], o[1]});
    return placed_polygon(verts, s.real("theta"));
  };
  return t;
}

}  // namespace picdem::geometry
