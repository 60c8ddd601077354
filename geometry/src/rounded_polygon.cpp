// A convex polygon with every corner rounded by an arc of radius r tangent to both edges: exactly
// segments and arcs, so the cut cells, contacts and outlines take it as it is. It is the inner
// polygon of the arc centres grown by r (a Minkowski sum with a disc), which gives `contains`.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/geometry/polygon.hpp"
#include "picdem/geometry/shape_registry.hpp"

namespace picdem::geometry {

namespace {

Vec2 unit(const Vec2& v) {
  return v / core::norm(v);
}

class RoundedPolygon : public Shape {
 public:
  /// `pieces` and `centres` (of the arcs, CCW) in the body frame.
  RoundedPolygon(std::vector<BoundaryPiece> pieces, std::vector<Vec2> centres, double r,
                 MassProperties mass)
      : pieces_(std::move(pieces)), centres_(std::move(centres)), r_(r), mass_(mass) {
    for (const Vec2& c : centres_)
      bounding_radius_ = std::max(bounding_radius_, core::norm(c) + r_);
  }

  std::string kind() const override { return "rounded_polygon"; }
  std::vector<BoundaryPiece> boundary() const override { return pieces_; }
  MassProperties mass_properties() const override { return mass_; }
  double bounding_radius() const override { return bounding_radius_; }
  /// Inside the polygon of the arc centres, or within r of one of its edges.
  bool contains(const Vec2& p) const override {
    bool inside = true;
    double d2 = INFINITY;
    for (std::size_t j = 0; j < centres_.size(); ++j) {
      const Vec2 a = centres_[j], e = centres_[(j + 1) % centres_.size()] - a;
      inside = inside && core::cross(e, p - a) >= 0.0;
      const double t = std::clamp(core::dot(p - a, e) / core::norm2(e), 0.0, 1.0);
      d2 = std::min(d2, core::norm2(p - (a + t * e)));
    }
    return inside || d2 <= r_ * r_;
  }

 private:
  std::vector<BoundaryPiece> pieces_;
  std::vector<Vec2> centres_;
  double r_;
  MassProperties mass_;
  double bounding_radius_ = 0.0;
};

std::string describe(const std::vector<Vec2>& v, std::size_t j) {
  std::ostringstream s;
  s << "vertex " << j << " (" << v[j].x << ", " << v[j].z << ")";
  return s.str();
}

}  // namespace

ShapePtr make_rounded_polygon(const std::vector<Vec2>& v, double r, Vec2* centroid) {
  if (!(r > 0.0) || !std::isfinite(r)) {
    std::ostringstream m;
    m << "rounded polygon radius " << r << " is not allowed: it must be a finite number > 0";
    throw core::InputError(m.str());
  }
  validate_simple_ccw(v, "rounded polygon");
  const std::size_t n = v.size();
  // per corner j: unit edge directions in and out, and the tangent length t_j = r tan(beta_j / 2)
  // (beta_j the turning angle) from the corner to where the arc meets each edge
  std::vector<Vec2> in(n), out(n);
  std::vector<double> t(n);
  for (std::size_t j = 0; j < n; ++j) {
    in[j] = unit(v[j] - v[(j + n - 1) % n]);
    out[j] = unit(v[(j + 1) % n] - v[j]);
    const double beta = std::atan2(core::cross(in[j], out[j]), core::dot(in[j], out[j]));
    if (!(beta > 0.0)) {
      throw core::InputError("rounded polygon: " + describe(v, j) +
                             " is not a convex corner: a convex polygon is required");
    }
    t[j] = r * std::tan(0.5 * beta);
  }
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t k = (j + 1) % n;
    const double len = core::norm(v[k] - v[j]);
    if (!(t[j] + t[k] < len)) {
      std::ostringstream m;
      m << "rounded polygon radius " << r << " is not allowed: the arcs at " << describe(v, j)
        << " and " << describe(v, k) << " need " << t[j] + t[k] << " of that edge of length " << len
        << "; allowed: a radius below " << r * len / (t[j] + t[k]);
      throw core::InputError(m.str());
    }
  }
  std::vector<BoundaryPiece> pieces;
  std::vector<Vec2> centres;
  for (std::size_t j = 0; j < n; ++j) {
    // the centre lies r inside both edges; the arc runs from the incoming edge's normal
    // direction to the outgoing one's
    const Vec2 c = v[j] - t[j] * in[j] + r * Vec2{-in[j].z, in[j].x};
    const double phi0 = std::atan2(-in[j].x, in[j].z);
    double phi1 = std::atan2(-out[j].x, out[j].z);
    if (phi1 <= phi0) phi1 += 2.0 * M_PI;
    centres.push_back(c);
    pieces.emplace_back(Arc{c, r, phi0, phi1});
    pieces.emplace_back(Segment{v[j] + t[j] * out[j], v[(j + 1) % n] - t[(j + 1) % n] * out[j]});
  }
  const RegionProperties p = loop_properties(pieces);
  for (auto& piece : pieces) {
    if (auto* s = std::get_if<Segment>(&piece)) {
      s->a -= p.centroid;
      s->b -= p.centroid;
    } else {
      std::get<Arc>(piece).centre -= p.centroid;
    }
  }
  for (auto& c : centres) c -= p.centroid;
  if (centroid) *centroid = p.centroid;
  return std::make_shared<const RoundedPolygon>(std::move(pieces), std::move(centres), r,
                                                MassProperties{p.area, p.polar_moment});
}

ShapeType rounded_polygon_type() {
  ShapeType t;
  t.name = "rounded_polygon";
  t.doc =
      "a convex polygon with its corners rounded by arcs of one radius; its centroid is its "
      "centre";
  t.declare = [](core::ParamSchema& v) {
    v.reals("vertices", {},
            "x0, z0, x1, z1, ... of the sharp corners, counter-clockwise, convex, world "
            "coordinates at theta = 0 [m]")
        .size(6, 1 << 20)
        .is_required();
    v.real("radius", 0.0, "radius of the corner arcs [m]").positive().is_required();
    v.real("theta", 0.0, "initial rotation about the centroid, counter-clockwise [rad]");
  };
  t.build = [](const core::Params& s, const BuildContext&) {
    Vec2 centroid;
    try {
      auto shape = make_rounded_polygon(vertex_pairs(s, "vertices"), s.real("radius"), &centroid);
      return std::vector<PlacedShape>{{shape, {centroid, s.real("theta")}}};
    } catch (const core::InputError& e) {
      throw core::InputError("keys '" + s.full_path("vertices") + "', '" + s.full_path("radius") +
                             "': " + e.what());
    }
  };
  return t;
}

}  // namespace picdem::geometry
