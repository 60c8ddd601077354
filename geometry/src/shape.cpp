// Mass properties of a loop of segments and arcs: the fan of triangles over the pieces' end points
// plus one circular segment per arc, every term in closed form.
#include <cmath>

#include "picdem/geometry/shape.hpp"

namespace picdem::geometry {

namespace {

Vec2 on_circle(const Vec2& c, double r, double phi) {
  return c + r * Vec2{std::cos(phi), std::sin(phi)};
}

}  // namespace

RegionProperties loop_properties(const std::vector<BoundaryPiece>& loop) {
  RegionProperties r;
  if (loop.empty()) return r;
  // Sums about the first piece's start point o, for conditioning.
  const Vec2 o = std::holds_alternative<Segment>(loop[0])
                     ? std::get<Segment>(loop[0]).a
                     : on_circle(std::get<Arc>(loop[0]).centre, std::get<Arc>(loop[0]).radius,
                                 std::get<Arc>(loop[0]).phi0);
  double area = 0.0, j_o = 0.0;
  Vec2 first;  // integral of (x - o) dA
  for (const auto& piece : loop) {
    Vec2 p, q;
    if (const auto* s = std::get_if<Segment>(&piece)) {
      p = s->a - o;
      q = s->b - o;
    } else {
      const auto& a = std::get<Arc>(piece);
      const double span = a.phi1 - a.phi0, rr = a.radius * a.radius;
      p = on_circle(a.centre, a.radius, a.phi0) - o;
      q = on_circle(a.centre, a.radius, a.phi1) - o;
      const Vec2 c = a.centre - o;
      const Vec2 u{std::cos(0.5 * (a.phi0 + a.phi1)), std::sin(0.5 * (a.phi0 + a.phi1))};
      // circular segment: A_s = r^2 (dphi - sin dphi) / 2, its first moment about the circle's
      // centre (2/3) r^3 sin^3(dphi / 2) u, its polar moment about the centre
      // r^4 dphi / 4 - r^4 sin dphi (2 + cos dphi) / 12 (sector minus triangle)
      const double seg_area = 0.5 * rr * (span - std::sin(span));
      const double sh = std::sin(0.5 * span);
      const Vec2 m_c = (2.0 / 3.0) * rr * a.radius * sh * sh * sh * u;
      const double j_c = rr * rr * (0.25 * span - std::sin(span) * (2.0 + std::cos(span)) / 12.0);
      area += seg_area;
      first += seg_area * c + m_c;
      // parallel axis from the circle's centre to o: J_o = J_c + 2 c . m_c + A_s |c|^2
      j_o += j_c + 2.0 * core::dot(c, m_c) + seg_area * core::norm2(c);
    }
    // triangle (o, p, q): A = w / 2, first moment w (p + q) / 6, J_o = w (|p|^2 + p.q + |q|^2) / 12
    const double w = core::cross(p, q);
    area += 0.5 * w;
    first += (w / 6.0) * (p + q);
    j_o += w * (core::norm2(p) + core::dot(p, q) + core::norm2(q)) / 12.0;
  }
  r.area = area;
  const Vec2 c = first / area;
  r.centroid = o + c;
  // J about the centroid: J_o - A |c|^2
  r.polar_moment = j_o - area * core::norm2(c);
  return r;
}

}  // namespace picdem::geometry
