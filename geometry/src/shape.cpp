// Mass properties of a loop of segments and arcs: the fan of triangles over the pieces' end points
// plus one circular segment per arc, every term in closed form. The sums run in long double: an
// arc of large radius (the flat side of an elongated ellipse) has its centre far away, and the
// parallel-axis terms from there cancel to a few digits in double.
#include <cmath>

#include "picdem/geometry/shape.hpp"

namespace picdem::geometry {

namespace {

using LD = long double;

struct P2 {
  LD x = 0, z = 0;
};
P2 operator-(const P2& p, const P2& q) {
  return {p.x - q.x, p.z - q.z};
}
LD dot(const P2& p, const P2& q) {
  return p.x * q.x + p.z * q.z;
}
LD cross(const P2& p, const P2& q) {
  return p.x * q.z - p.z * q.x;
}

P2 on_circle(const Vec2& c, double r, LD phi) {
  return {c.x + r * std::cos(phi), c.z + r * std::sin(phi)};
}

P2 start_of(const BoundaryPiece& piece) {
  if (const auto* s = std::get_if<Segment>(&piece)) return {s->a.x, s->a.z};
  const auto& a = std::get<Arc>(piece);
  return on_circle(a.centre, a.radius, a.phi0);
}

}  // namespace

RegionProperties loop_properties(const std::vector<BoundaryPiece>& loop) {
  RegionProperties r;
  if (loop.empty()) return r;
  // Sums about the first piece's start point o, for conditioning.
  const P2 o = start_of(loop[0]);
  LD area = 0, j_o = 0;
  P2 first;  // integral of (x - o) dA
  for (const auto& piece : loop) {
    P2 p, q;
    if (const auto* s = std::get_if<Segment>(&piece)) {
      p = P2{s->a.x, s->a.z} - o;
      q = P2{s->b.x, s->b.z} - o;
    } else {
      const auto& a = std::get<Arc>(piece);
      const LD span = LD(a.phi1) - a.phi0, rr = LD(a.radius) * a.radius;
      p = on_circle(a.centre, a.radius, a.phi0) - o;
      q = on_circle(a.centre, a.radius, a.phi1) - o;
      const P2 c = P2{a.centre.x, a.centre.z} - o;
      const LD mid = 0.5L * (LD(a.phi0) + a.phi1);
      const P2 u{std::cos(mid), std::sin(mid)};
      // circular segment: A_s = r^2 (dphi - sin dphi) / 2, its first moment about the circle's
      // centre (2/3) r^3 sin^3(dphi / 2) u, its polar moment about the centre
      // r^4 dphi / 4 - r^4 sin dphi (2 + cos dphi) / 12 (sector minus triangle)
      const LD seg_area = 0.5L * rr * (span - std::sin(span));
      const LD sh = std::sin(0.5L * span);
      const LD m = (2.0L / 3.0L) * rr * a.radius * sh * sh * sh;
      const P2 m_c{m * u.x, m * u.z};
      const LD j_c = rr * rr * (0.25L * span - std::sin(span) * (2.0L + std::cos(span)) / 12.0L);
      area += seg_area;
      first.x += seg_area * c.x + m_c.x;
      first.z += seg_area * c.z + m_c.z;
      // parallel axis from the circle's centre to o: J_o = J_c + 2 c . m_c + A_s |c|^2
      j_o += j_c + 2.0L * dot(c, m_c) + seg_area * dot(c, c);
    }
    // triangle (o, p, q): A = w / 2, first moment w (p + q) / 6, J_o = w (|p|^2 + p.q + |q|^2) / 12
    const LD w = cross(p, q);
    area += 0.5L * w;
    first.x += (w / 6.0L) * (p.x + q.x);
    first.z += (w / 6.0L) * (p.z + q.z);
    j_o += w * (dot(p, p) + dot(p, q) + dot(q, q)) / 12.0L;
  }
  const P2 c{first.x / area, first.z / area};
  r.area = static_cast<double>(area);
  r.centroid = {static_cast<double>(o.x + c.x), static_cast<double>(o.z + c.z)};
  // J about the centroid: J_o - A |c|^2
  r.polar_moment = static_cast<double>(j_o - area * dot(c, c));
  return r;
}

}  // namespace picdem::geometry
