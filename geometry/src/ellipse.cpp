// The ellipse x^2 / a^2 + z^2 / b^2 <= 1 as a shape (doc/shapes.md, the worked example). Its
// boundary is a G1 (tangent-continuous) convex arc spline: biarcs between points of the ellipse
// that match the ellipse's tangents there, as many as needed for the largest distance to the true
// ellipse to stay below 1e-4 min(a, b). The cut cells and contacts then treat it exactly like any
// loop of arcs, and area and polar moment are those of the arc spline itself (loop_properties),
// so mass, buoyancy and contacts all see the same body.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/geometry/shape_registry.hpp"

namespace picdem::geometry {

namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr int kMaxDepth = 12;  // halvings of an interval of the quadrant

Vec2 left_normal(const Vec2& t) {
  return {-t.z, t.x};
}

Vec2 on_arc(const Arc& a, double phi) {
  return a.centre + a.radius * Vec2{std::cos(phi), std::sin(phi)};
}

/// The counter-clockwise arc of centre c and radius r from `from` to `to`.
Arc arc_between(const Vec2& c, double r, const Vec2& from, const Vec2& to) {
  Arc a{c, r, std::atan2(from.z - c.z, from.x - c.x), std::atan2(to.z - c.z, to.x - c.x)};
  if (a.phi1 <= a.phi0) a.phi1 += kTwoPi;
  return a;
}

/// True when the direction d (from the arc's centre) lies within the arc's span.
bool in_span(const Arc& a, const Vec2& d) {
  double phi = std::atan2(d.z, d.x) - a.phi0;
  phi -= kTwoPi * std::floor(phi / kTwoPi);
  return phi <= a.phi1 - a.phi0;
}

/// Distance from p to the arc (its circle where p faces the arc, else the nearer end).
double distance_to_arc(const Arc& a, const Vec2& p) {
  const Vec2 d = p - a.centre;
  if (in_span(a, d)) return std::fabs(core::norm(d) - a.radius);
  return std::min(core::norm(p - on_arc(a, a.phi0)), core::norm(p - on_arc(a, a.phi1)));
}

/// The biarc from p0 (unit tangent t0) to p1 (unit tangent t1), both arcs convex: the joint is
/// the incentre of the triangle p0, v, p1 (v where the two tangent lines meet), the choice that
/// makes the two arcs tangent to each other there.
void biarc(const Vec2& p0, const Vec2& t0, const Vec2& p1, const Vec2& t1, std::vector<Arc>& out) {
  // v = p0 + s t0 = p1 - u t1
  const double s = core::cross(p1 - p0, t1) / core::cross(t0, t1);
  const Vec2 v = p0 + s * t0;
  // incentre: the vertices weighted by the lengths of the opposite sides
  const double w0 = core::norm(v - p1), wv = core::norm(p1 - p0), w1 = core::norm(p0 - v);
  const Vec2 j = (w0 * p0 + wv * v + w1 * p1) / (w0 + wv + w1);
  // circle through p0 tangent to t0 there, through j: r = |j - p0|^2 / (2 n0 . (j - p0))
  const Vec2 n0 = left_normal(t0), n1 = left_normal(t1);
  const double r0 = core::norm2(j - p0) / (2.0 * core::dot(n0, j - p0));
  const double r1 = core::norm2(j - p1) / (2.0 * core::dot(n1, j - p1));
  out.push_back(arc_between(p0 + r0 * n0, r0, p0, j));
  out.push_back(arc_between(p1 + r1 * n1, r1, j, p1));
}

/// The first quadrant of the ellipse (t from 0 to pi/2, point (a cos t, b sin t)) as biarcs,
/// each interval of t halved until its biarc's largest distance to the ellipse, sampled at 64
/// points, is below tol. `error` gets the largest such distance.
class QuadrantFit {
 public:
  QuadrantFit(double a, double b, double tol) : a_(a), b_(b), tol_(tol) {}

  std::vector<Arc> fit(double& error) {
    arcs_.clear();
    error_ = 0.0;
    split(0.0, 0.5 * M_PI, 0);
    error = error_;
    return arcs_;
  }

 private:
  // the ends exactly on the axes
  Vec2 point(double t) const {
    if (t == 0.0) return {a_, 0.0};
    if (t == 0.5 * M_PI) return {0.0, b_};
    return {a_ * std::cos(t), b_ * std::sin(t)};
  }
  Vec2 tangent(double t) const {
    if (t == 0.0) return {0.0, 1.0};
    if (t == 0.5 * M_PI) return {-1.0, 0.0};
    const Vec2 d{-a_ * std::sin(t), b_ * std::cos(t)};
    return d / core::norm(d);
  }
  void split(double t0, double t1, int depth) {
    std::vector<Arc> two;
    biarc(point(t0), tangent(t0), point(t1), tangent(t1), two);
    double e = 0.0;
    for (int m = 1; m < 64; ++m) {
      const Vec2 q = point(t0 + (t1 - t0) * m / 64.0);
      e = std::max(e, std::min(distance_to_arc(two[0], q), distance_to_arc(two[1], q)));
    }
    if (e < tol_ || depth == kMaxDepth) {
      arcs_.insert(arcs_.end(), two.begin(), two.end());
      error_ = std::max(error_, e);
      return;
    }
    const double tm = 0.5 * (t0 + t1);
    split(t0, tm, depth + 1);
    split(tm, t1, depth + 1);
  }

  double a_, b_, tol_;
  std::vector<Arc> arcs_;
  double error_ = 0.0;
};

class Ellipse : public Shape {
 public:
  Ellipse(double a, double b) : a_(a), b_(b) {
    const double tol = ellipse_tolerance(a, b);
    double error = 0.0;
    quadrant_ = QuadrantFit(a, b, tol).fit(error);
    if (!(error < tol)) {
      std::ostringstream m;
      m << "ellipse a = " << a << ", b = " << b << ": no arc spline with intervals halved "
        << kMaxDepth << " times comes within " << tol << " of it";
      throw core::InputError(m.str());
    }
    // the other quadrants by symmetry: x -> -x (reversed), (x, z) -> -(x, z), z -> -z (reversed)
    const std::size_t q = quadrant_.size();
    for (const Arc& c : quadrant_) boundary_.emplace_back(c);
    for (std::size_t k = q; k-- > 0;) {
      const Arc& c = quadrant_[k];
      boundary_.emplace_back(
          Arc{{-c.centre.x, c.centre.z}, c.radius, M_PI - c.phi1, M_PI - c.phi0});
    }
    for (const Arc& c : quadrant_)
      boundary_.emplace_back(Arc{-1.0 * c.centre, c.radius, c.phi0 + M_PI, c.phi1 + M_PI});
    for (std::size_t k = q; k-- > 0;) {
      const Arc& c = quadrant_[k];
      boundary_.emplace_back(Arc{{c.centre.x, -c.centre.z}, c.radius, -c.phi1, -c.phi0});
    }
    const RegionProperties r = loop_properties(boundary_);
    mass_ = {r.area, r.polar_moment};
    for (const Arc& c : quadrant_) {
      end_angle_.push_back(std::atan2(on_arc(c, c.phi1).z, on_arc(c, c.phi1).x));
      const double d = core::norm(c.centre);
      bounding_radius_ =
          std::max({bounding_radius_, core::norm(on_arc(c, c.phi0)), core::norm(on_arc(c, c.phi1)),
                    d > 0.0 && in_span(c, c.centre) ? d + c.radius : 0.0});
    }
  }

  std::string kind() const override { return "ellipse"; }
  std::vector<BoundaryPiece> boundary() const override { return boundary_; }
  MassProperties mass_properties() const override { return mass_; }
  double bounding_radius() const override { return bounding_radius_; }

  /// Inside the arc spline: folded into the first quadrant, the ray from the centre through the
  /// point leaves the (convex, star-shaped) spline on one arc, at the far root of the ray-circle
  /// intersection t = d.c + sqrt((d.c)^2 - |c|^2 + r^2).
  bool contains(const Vec2& body_point) const override {
    const Vec2 p{std::fabs(body_point.x), std::fabs(body_point.z)};
    const double len = core::norm(p);
    if (len == 0.0) return true;
    const double angle = std::atan2(p.z, p.x);
    std::size_t k = 0;
    while (k + 1 < quadrant_.size() && angle > end_angle_[k]) ++k;
    const Arc& c = quadrant_[k];
    const Vec2 d = p / len;
    const double dc = core::dot(d, c.centre);
    const double disc = dc * dc - core::norm2(c.centre) + c.radius * c.radius;
    return disc >= 0.0 && len <= dc + std::sqrt(disc);
  }

 private:
  double a_, b_;
  std::vector<Arc> quadrant_;      // first quadrant, counter-clockwise from (a, 0) to (0, b)
  std::vector<double> end_angle_;  // polar angle of each quadrant arc's end
  std::vector<BoundaryPiece> boundary_;
  MassProperties mass_;
  double bounding_radius_ = 0.0;
};

}  // namespace

double ellipse_tolerance(double a, double b) {
  return 1e-4 * std::min(a, b);
}

ShapePtr make_ellipse(double a, double b) {
  for (const auto& [name, v] : {std::pair<const char*, double>{"a", a}, {"b", b}}) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      std::ostringstream m;
      m << "ellipse semi-axis " << name << " = " << v
        << " is not allowed: it must be a finite number > 0";
      throw core::InputError(m.str());
    }
  }
  const double aspect = std::max(a, b) / std::min(a, b);
  if (aspect > ellipse_max_aspect) {
    std::ostringstream m;
    m << "ellipse semi-axes a = " << a << ", b = " << b << " (aspect ratio " << aspect
      << ") are not allowed: max(a, b) / min(a, b) must be <= " << ellipse_max_aspect
      << " (the cut cells' moments of its flat sides' large arcs lose digits beyond, "
         "doc/shapes.md)";
    throw core::InputError(m.str());
  }
  return std::make_shared<const Ellipse>(a, b);
}

ShapeType ellipse_type() {
  ShapeType t;
  t.name = "ellipse";
  t.doc = "an ellipse of semi-axes a, b (a G1 arc spline within 1e-4 min(a, b), doc/shapes.md)";
  t.declare = [](core::ParamSchema& v) {
    v.real("a", 0.0, "semi-axis along the body x axis [m]").positive().is_required();
    v.real("b", 0.0, "semi-axis along the body z axis [m]").positive().is_required();
    v.reals("center", {0.0, 0.0}, "initial centre (x, z) [m]").size(2, 2).is_required();
    v.real("theta", 0.0, "initial rotation of the a axis from x, counter-clockwise [rad]");
  };
  t.build = [](const core::Params& s, const BuildContext&) {
    const auto c = s.reals("center");
    try {
      return std::vector<PlacedShape>{
          {make_ellipse(s.real("a"), s.real("b")), {{c[0], c[1]}, s.real("theta")}}};
    } catch (const core::InputError& e) {
      throw core::InputError("keys '" + s.full_path("a") + "', '" + s.full_path("b") +
                             "': " + e.what());
    }
  };
  return t;
}

}  // namespace picdem::geometry
