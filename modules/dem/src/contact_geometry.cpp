#include "picdem/dem/contact_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace picdem::dem {

using geometry::Arc;
using geometry::Segment;

namespace {

constexpr double two_pi = 6.283185307179586;

/// |v| (sqrt of the square: hypot's overflow care is not needed at these scales and is slow)
double length(const Vec2& v) {
  return std::sqrt(core::norm2(v));
}

/// An arc's end data from its angles.
ArcEnds ends_of(const Arc& a) {
  ArcEnds e;
  e.u0 = Vec2{std::cos(a.phi0), std::sin(a.phi0)};
  e.u1 = Vec2{std::cos(a.phi1), std::sin(a.phi1)};
  e.p0 = a.centre + a.radius * e.u0;
  e.p1 = a.centre + a.radius * e.u1;
  const double span = a.phi1 - a.phi0;
  e.wide = span > 0.5 * two_pi;
  e.full = span >= two_pi - 1e-12;
  return e;
}

/// The end data of arc `w` (world frame) from its body-frame end data `b`, the rotation given by
/// its cosine and sine: the directions rotated, the points from the placed centre.
ArcEnds placed_ends(const Arc& w, const ArcEnds& b, double c, double s) {
  ArcEnds e = b;
  e.u0 = Vec2{c * b.u0.x - s * b.u0.z, s * b.u0.x + c * b.u0.z};
  e.u1 = Vec2{c * b.u1.x - s * b.u1.z, s * b.u1.x + c * b.u1.z};
  e.p0 = w.centre + w.radius * e.u0;
  e.p1 = w.centre + w.radius * e.u1;
  return e;
}

/// in_arc by the signs of two cross products instead of an angle (atan2 and fmod): d lies on the
/// span when it is counter-clockwise of the start and clockwise of the end (a span up to pi), or
/// either (a wider span, the complement of a span below pi). The ends are included, as in in_arc.
bool in_arc(const ArcEnds& e, const Vec2& d) {
  if (e.full) return true;
  const double c0 = core::cross(e.u0, d), c1 = core::cross(d, e.u1);
  return e.wide ? (c0 >= 0.0 || c1 >= 0.0) : (c0 >= 0.0 && c1 >= 0.0);
}

/// closest_on_arc with the arc's end points given.
Vec2 closest_on_arc(const Arc& a, const ArcEnds& e, const Vec2& p) {
  const Vec2 d = p - a.centre;
  const double r = length(d);
  if (r > 0.0 && in_arc(e, d)) return a.centre + (a.radius / r) * d;
  if (r == 0.0) return e.p0;
  return core::norm2(p - e.p0) <= core::norm2(p - e.p1) ? e.p0 : e.p1;
}

ClosestPoints make(const Vec2& p, const Vec2& q) {
  ClosestPoints c;
  c.on_a = p;
  c.on_b = q;
  c.distance = length(q - p);
  return c;
}

void keep_min(ClosestPoints& best, const ClosestPoints& c) {
  if (c.distance < best.distance) best = c;
}

/// Like keep_min, but a face-to-face result wins a tie (within round-off of the distances).
void keep_min_prefer_face(ClosestPoints& best, const ClosestPoints& c) {
  if (!std::isfinite(best.distance)) {
    best = c;
    return;
  }
  const double tol = 1e-9 * (1.0 + best.distance);
  if (c.distance < best.distance - tol ||
      (c.face && !best.face && c.distance <= best.distance + tol))
    best = c;
}

ClosestPoints swap_sides(const ClosestPoints& c) {
  ClosestPoints s = c;
  std::swap(s.on_a, s.on_b);
  for (int e = 0; e < 2; ++e) std::swap(s.end_a[e], s.end_b[e]);
  return s;
}

bool segments_cross(const Segment& s, const Segment& t, Vec2& where) {
  const Vec2 r = s.b - s.a, q = t.b - t.a;
  const double den = core::cross(r, q);
  if (den == 0.0) return false;
  const double u = core::cross(t.a - s.a, q) / den, v = core::cross(t.a - s.a, r) / den;
  if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) return false;
  where = s.a + u * r;
  return true;
}

ClosestPoints segment_segment(const Segment& s, const Segment& t) {
  Vec2 x;
  if (segments_cross(s, t, x)) return make(x, x);
  const Vec2 r = s.b - s.a, q = t.b - t.a;
  const double l2 = core::norm2(r);
  if (l2 > 0.0 && std::abs(core::cross(r, q)) <= 0.0998 * std::sqrt(l2 * core::norm2(q))) {
    // nearly parallel: the ends of the stretch where they face each other
    const double ua = core::dot(t.a - s.a, r) / l2, ub = core::dot(t.b - s.a, r) / l2;
    const double lo = std::max(0.0, std::min(ua, ub)), hi = std::min(1.0, std::max(ua, ub));
    if (lo <= hi) {
      ClosestPoints c;
      c.face = true;
      for (int e = 0; e < 2; ++e) {
        c.end_a[e] = s.a + (e == 0 ? lo : hi) * r;
        c.end_b[e] = closest_on_segment(t, c.end_a[e]);
      }
      const double d0 = length(c.end_b[0] - c.end_a[0]), d1 = length(c.end_b[1] - c.end_a[1]);
      const int e = d0 <= d1 ? 0 : 1;
      c.on_a = c.end_a[e];
      c.on_b = c.end_b[e];
      c.distance = std::min(d0, d1);
      // a corner of t beyond the stretch may come closer than its ends
      ClosestPoints other = make(closest_on_segment(s, t.a), t.a);
      keep_min(other, make(closest_on_segment(s, t.b), t.b));
      if (other.distance < c.distance * (1.0 - 1e-12)) return other;
      return c;
    }
  }
  ClosestPoints best = make(s.a, closest_on_segment(t, s.a));
  keep_min(best, make(s.b, closest_on_segment(t, s.b)));
  keep_min(best, make(closest_on_segment(s, t.a), t.a));
  keep_min(best, make(closest_on_segment(s, t.b), t.b));
  return best;
}

// The first point (along s) where segment s crosses arc a: |s.a + t r - c| = R for t in [0, 1],
// on the arc's span.
bool segment_crosses_arc(const Segment& s, const Arc& a, const ArcEnds& e, Vec2& where) {
  const Vec2 r = s.b - s.a, f = s.a - a.centre;
  const double A = core::norm2(r), B = core::dot(r, f), C = core::norm2(f) - a.radius * a.radius;
  const double disc = B * B - A * C;
  if (!(A > 0.0) || disc < 0.0) return false;
  const double root = std::sqrt(disc);
  for (double t : {(-B - root) / A, (-B + root) / A}) {
    if (t < 0.0 || t > 1.0) continue;
    const Vec2 x = s.a + t * r;
    if (in_arc(e, x - a.centre)) {
      where = x;
      return true;
    }
  }
  return false;
}

// A point where arcs a and b cross: the intersections of their circles, on both spans.
bool arcs_cross(const Arc& a, const ArcEnds& ea, const Arc& b, const ArcEnds& eb, Vec2& where) {
  const Vec2 c = b.centre - a.centre;
  const double d = length(c);
  if (!(d > 0.0) || d > a.radius + b.radius || d < std::abs(a.radius - b.radius)) return false;
  // along the line of centres from a's centre, then +- h across it
  const double along = (a.radius * a.radius - b.radius * b.radius + d * d) / (2.0 * d);
  const double h = std::sqrt(std::max(0.0, a.radius * a.radius - along * along));
  const Vec2 u = c / d;
  for (double side : {1.0, -1.0}) {
    const Vec2 x = a.centre + along * u + side * h * core::perp(u);
    if (in_arc(ea, x - a.centre) && in_arc(eb, x - b.centre)) {
      where = x;
      return true;
    }
  }
  return false;
}

ClosestPoints segment_arc(const Segment& s, const Arc& a, const ArcEnds& e) {
  Vec2 x;
  if (segment_crosses_arc(s, a, e, x)) return make(x, x);
  // Interior critical point: the connecting line is normal to the segment and radial to the arc,
  // so it passes through the arc centre.
  const Vec2 foot = closest_on_segment(s, a.centre);
  ClosestPoints best = make(foot, closest_on_arc(a, e, foot));
  keep_min(best, make(s.a, closest_on_arc(a, e, s.a)));
  keep_min(best, make(s.b, closest_on_arc(a, e, s.b)));
  keep_min(best, make(closest_on_segment(s, e.p0), e.p0));
  keep_min(best, make(closest_on_segment(s, e.p1), e.p1));
  return best;
}

ClosestPoints arc_arc(const Arc& a, const ArcEnds& ea, const Arc& b, const ArcEnds& eb) {
  Vec2 x;
  if (arcs_cross(a, ea, b, eb, x)) return make(x, x);
  const Vec2 c = b.centre - a.centre;
  const double d = length(c);
  ClosestPoints best;
  best.distance = std::numeric_limits<double>::infinity();
  if (d > 0.0) {
    // Interior critical points lie on the line of centres.
    const Vec2 u = c / d;
    for (double sa : {1.0, -1.0})
      for (double sb : {-1.0, 1.0}) {
        const Vec2 da = sa * u, db = sb * u;
        if (in_arc(ea, da) && in_arc(eb, db))
          keep_min(best, make(a.centre + a.radius * da, b.centre + b.radius * db));
      }
  }
  for (const Vec2& p : {ea.p0, ea.p1}) keep_min(best, make(p, closest_on_arc(b, eb, p)));
  for (const Vec2& q : {eb.p0, eb.p1}) keep_min(best, make(closest_on_arc(a, ea, q), q));
  return best;
}

}  // namespace

std::vector<BoundaryPiece> to_world(const std::vector<BoundaryPiece>& body,
                                    const geometry::Pose& pose) {
  std::vector<BoundaryPiece> world;
  world.reserve(body.size());
  for (const auto& piece : body) {
    if (const auto* s = std::get_if<Segment>(&piece)) {
      world.emplace_back(Segment{pose.to_world(s->a), pose.to_world(s->b)});
    } else {
      const auto& a = std::get<Arc>(piece);
      world.emplace_back(
          Arc{pose.to_world(a.centre), a.radius, a.phi0 + pose.theta, a.phi1 + pose.theta});
    }
  }
  return world;
}

Boundary with_ends(std::vector<BoundaryPiece> pieces) {
  Boundary b;
  b.ends.reserve(pieces.size());
  for (const auto& piece : pieces) {
    const auto* a = std::get_if<Arc>(&piece);
    b.ends.push_back(a ? ends_of(*a) : ArcEnds{});
  }
  b.pieces = std::move(pieces);
  return b;
}

namespace {
/// Places `body` by `pose` into `out`, keeping the pieces for which `keep(piece, ends)` holds
/// (one sine and cosine per call, none per piece).
template <class Keep>
void place(const Boundary& body, const geometry::Pose& pose, Boundary& out, Keep keep) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  auto at = [&](const Vec2& b) { return pose.x + Vec2{c * b.x - s * b.z, s * b.x + c * b.z}; };
  for (std::size_t k = 0; k < body.pieces.size(); ++k) {
    const auto& piece = body.pieces[k];
    if (const auto* seg = std::get_if<Segment>(&piece)) {
      const Segment w{at(seg->a), at(seg->b)};
      if (!keep(w)) continue;
      out.pieces.emplace_back(w);
      out.ends.emplace_back();
    } else {
      const auto& a = std::get<Arc>(piece);
      const Arc w{at(a.centre), a.radius, a.phi0 + pose.theta, a.phi1 + pose.theta};
      const ArcEnds e = placed_ends(w, body.ends[k], c, s);
      if (!keep(w, e)) continue;
      out.pieces.emplace_back(w);
      out.ends.push_back(e);
    }
  }
}
}  // namespace

void to_world(const Boundary& body, const geometry::Pose& pose, Boundary& out) {
  out.clear();
  place(body, pose, out, [](const auto&...) { return true; });
}

void to_world_near(const Boundary& body, const geometry::Pose& pose, const Vec2& centre,
                   double reach, Boundary& out) {
  const double reach2 = reach * reach;
  struct Near {
    const Vec2& centre;
    double reach, reach2;
    bool operator()(const Segment& w) const {
      return core::norm2(closest_on_segment(w, centre) - centre) < reach2;
    }
    bool operator()(const Arc& w, const ArcEnds& e) const {
      // the distance to the arc's whole circle is a lower bound of the distance to the arc: far
      // from the circle the arc is out of reach (with a margin for round-off, so that the exact
      // test keeps deciding every piece near the reach)
      const double off = std::abs(length(w.centre - centre) - w.radius);
      if (off > reach * (1.0 + 1e-9) + 1e-12 * w.radius) return false;
      return core::norm2(closest_on_arc(w, e, centre) - centre) < reach2;
    }
  };
  place(body, pose, out, Near{centre, reach, reach2});
}

void to_world_near(const std::vector<BoundaryPiece>& body, const geometry::Pose& pose,
                   const Vec2& centre, double reach, std::vector<BoundaryPiece>& out) {
  Boundary world;
  to_world_near(with_ends(body), pose, centre, reach, world);
  for (auto& piece : world.pieces) out.push_back(std::move(piece));
}

Vec2 closest_on_segment(const Segment& s, const Vec2& p) {
  const Vec2 r = s.b - s.a;
  const double l2 = core::norm2(r);
  if (l2 == 0.0) return s.a;
  const double t = std::clamp(core::dot(p - s.a, r) / l2, 0.0, 1.0);
  return s.a + t * r;
}

Vec2 closest_on_arc(const Arc& a, const Vec2& p) {
  return closest_on_arc(a, ends_of(a), p);
}

namespace {
/// closest_points of two pieces, an arc's end points given (unused for a segment).
ClosestPoints closest_pieces(const BoundaryPiece& a, const ArcEnds& ea, const BoundaryPiece& b,
                             const ArcEnds& eb) {
  const auto* sa = std::get_if<Segment>(&a);
  const auto* sb = std::get_if<Segment>(&b);
  if (sa && sb) return segment_segment(*sa, *sb);
  if (sa) return segment_arc(*sa, std::get<Arc>(b), eb);
  if (sb) return swap_sides(segment_arc(*sb, std::get<Arc>(a), ea));
  return arc_arc(std::get<Arc>(a), ea, std::get<Arc>(b), eb);
}

ArcEnds ends_of(const BoundaryPiece& piece) {
  const auto* a = std::get_if<Arc>(&piece);
  return a ? ends_of(*a) : ArcEnds{};
}
}  // namespace

ClosestPoints closest_points(const BoundaryPiece& a, const BoundaryPiece& b) {
  return closest_pieces(a, ends_of(a), b, ends_of(b));
}

namespace {
/// A lower bound of the distance between two pieces from an arc's whole circle (the distance of
/// any point of an arc to a set is at least that of its centre less the radius); -inf for two
/// segments, whose exact test is as cheap.
double lower_bound(const BoundaryPiece& a, const BoundaryPiece& b) {
  const auto* arc_a = std::get_if<Arc>(&a);
  const auto* arc_b = std::get_if<Arc>(&b);
  if (arc_a && arc_b) return length(arc_b->centre - arc_a->centre) - arc_a->radius - arc_b->radius;
  if (arc_a) {
    const Vec2 foot = closest_on_segment(std::get<Segment>(b), arc_a->centre);
    return length(foot - arc_a->centre) - arc_a->radius;
  }
  if (arc_b) {
    const Vec2 foot = closest_on_segment(std::get<Segment>(a), arc_b->centre);
    return length(foot - arc_b->centre) - arc_b->radius;
  }
  return -std::numeric_limits<double>::infinity();
}
}  // namespace

ClosestPoints closest_points(const Boundary& a, const Boundary& b) {
  ClosestPoints best;
  best.distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.pieces.size(); ++i)
    for (std::size_t k = 0; k < b.pieces.size(); ++k) {
      // a pair that cannot come within keep_min_prefer_face's tolerance of the best so far
      // cannot replace it (a face, which may win a tie, is two segments, never skipped): skipping
      // it leaves the result, bits included, as the full loop gives it
      if (std::isfinite(best.distance) &&
          lower_bound(a.pieces[i], b.pieces[k]) > best.distance + 1e-9 * (1.0 + best.distance))
        continue;
      keep_min_prefer_face(best, closest_pieces(a.pieces[i], a.ends[i], b.pieces[k], b.ends[k]));
    }
  return best;
}

ClosestPoints closest_points(const std::vector<BoundaryPiece>& a,
                             const std::vector<BoundaryPiece>& b) {
  return closest_points(with_ends(a), with_ends(b));
}

void face_weighted(const ClosestPoints& cp, double gap, Vec2& on_a, Vec2& on_b) {
  on_a = cp.on_a;
  on_b = cp.on_b;
  if (!cp.face) return;
  double w[2], sum = 0.0;
  for (int e = 0; e < 2; ++e) {
    w[e] = std::max(0.0, gap - length(cp.end_b[e] - cp.end_a[e]));
    sum += w[e];
  }
  if (sum <= 0.0) return;
  on_a = (w[0] / sum) * cp.end_a[0] + (w[1] / sum) * cp.end_a[1];
  on_b = (w[0] / sum) * cp.end_b[0] + (w[1] / sum) * cp.end_b[1];
}

Vec2 support_point(const Boundary& boundary, const Vec2& d) {
  Vec2 best;
  double best_h = -std::numeric_limits<double>::infinity();
  auto consider = [&](const Vec2& p) {
    const double h = core::dot(p, d);
    if (h > best_h) best_h = h, best = p;
  };
  for (std::size_t k = 0; k < boundary.pieces.size(); ++k) {
    if (const auto* s = std::get_if<Segment>(&boundary.pieces[k])) {
      consider(s->a);
      consider(s->b);
    } else {
      const auto& a = std::get<Arc>(boundary.pieces[k]);
      const ArcEnds& e = boundary.ends[k];
      if (in_arc(e, d)) consider(a.centre + a.radius * d);
      consider(e.p0);
      consider(e.p1);
    }
  }
  return best;
}

Vec2 support_point(const std::vector<BoundaryPiece>& boundary, const Vec2& d) {
  return support_point(with_ends(boundary), d);
}

}  // namespace picdem::dem
