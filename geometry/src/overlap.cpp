// Exact overlap depth of outlines (overlap.hpp): support functions of convex loops, CGAL's convex
// partition for non-convex polygons.
#include "picdem/geometry/overlap.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/partition_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <list>

namespace picdem::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

double wrap(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0.0 ? a + kTwoPi : a;
}

Vec2 unit(double t) {
  return {std::cos(t), std::sin(t)};
}

/// The normal angles (shifted by `shift`) at which the loop's support changes from one vertex or
/// arc to the next: the outward normal of every segment (right-hand normal of a -> b) and the
/// end angles of every arc.
void add_breaks(const std::vector<BoundaryPiece>& loop, double shift, std::vector<double>& out) {
  for (const auto& piece : loop) {
    if (const auto* s = std::get_if<Segment>(&piece)) {
      const Vec2 d = s->b - s->a;
      if (core::norm2(d) > 0.0) out.push_back(wrap(std::atan2(-d.x, d.z) + shift));
    } else {
      const auto& a = std::get<Arc>(piece);
      out.push_back(wrap(a.phi0 + shift));
      out.push_back(wrap(a.phi1 + shift));
    }
  }
}

/// h(n) = p.n + r near the direction n: p a vertex (r = 0) or an arc's centre (r its radius).
struct Support {
  Vec2 p;
  double r = 0.0;
};

/// The vertex or arc supporting the loop in the direction of angle t (not a break angle).
Support support(const std::vector<BoundaryPiece>& loop, double t) {
  const Vec2 n = unit(t);
  Support best;
  double h = -std::numeric_limits<double>::infinity();
  auto vertex = [&](const Vec2& v) {
    if (core::dot(v, n) > h) {
      h = core::dot(v, n);
      best = {v, 0.0};
    }
  };
  for (const auto& piece : loop) {
    if (const auto* s = std::get_if<Segment>(&piece)) {
      vertex(s->a);
      vertex(s->b);
      continue;
    }
    const auto& a = std::get<Arc>(piece);
    if (a.phi1 - a.phi0 >= kTwoPi || wrap(t - a.phi0) < a.phi1 - a.phi0)
      return {a.centre, a.radius};
    vertex(a.centre + a.radius * unit(a.phi0));
    vertex(a.centre + a.radius * unit(a.phi1));
  }
  return best;
}

// The unit tangents of a piece at its start and end, in the loop's direction.
Vec2 tangent_in(const BoundaryPiece& piece) {
  if (const auto* s = std::get_if<Segment>(&piece)) return (s->b - s->a) / core::norm(s->b - s->a);
  const double phi = std::get<Arc>(piece).phi0;
  return {-std::sin(phi), std::cos(phi)};
}
Vec2 tangent_out(const BoundaryPiece& piece) {
  if (const auto* s = std::get_if<Segment>(&piece)) return (s->b - s->a) / core::norm(s->b - s->a);
  const double phi = std::get<Arc>(piece).phi1;
  return {-std::sin(phi), std::cos(phi)};
}

}  // namespace

double convex_penetration_depth(const std::vector<BoundaryPiece>& a,
                                const std::vector<BoundaryPiece>& b) {
  // b's support in -n: its break at normal angle phi is at phi + pi in terms of n.
  std::vector<double> t;
  add_breaks(a, 0.0, t);
  add_breaks(b, kPi, t);
  std::sort(t.begin(), t.end());
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double t0 = t[i], t1 = i + 1 < t.size() ? t[i + 1] : t[0] + kTwoPi;
    if (!(t1 > t0)) continue;
    const double mid = 0.5 * (t0 + t1);
    const Support sa = support(a, wrap(mid)), sb = support(b, wrap(mid + kPi));
    // h_a(n) + h_b(-n) = (p - q).n + r_a + r_b on [t0, t1]
    const Vec2 d = sa.p - sb.p;
    const double r = sa.r + sb.r;
    best = std::min({best, core::dot(d, unit(t0)) + r, core::dot(d, unit(t1)) + r});
    if (core::norm(d) > 0.0) {
      const double at = t0 + wrap(std::atan2(-d.z, -d.x) - t0);  // n = -d / |d|
      if (at < t1) best = std::min(best, r - core::norm(d));
    }
  }
  return best;
}

bool is_convex_loop(const std::vector<BoundaryPiece>& loop) {
  constexpr double tol = 1e-12;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    if (const auto* s = std::get_if<Segment>(&loop[i]); s && !(core::norm2(s->b - s->a) > 0.0))
      return false;
    const Vec2 out = tangent_out(loop[i]), in = tangent_in(loop[(i + 1) % loop.size()]);
    if (core::cross(out, in) < -tol) return false;
  }
  return !loop.empty();
}

std::vector<std::vector<Vec2>> convex_partition(const std::vector<Vec2>& vertices) {
  if (is_convex_loop(polygon_loop(vertices))) return {vertices};
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Traits = CGAL::Partition_traits_2<K>;
  std::vector<Traits::Point_2> in;
  for (const auto& v : vertices) in.emplace_back(v.x, v.z);
  std::list<Traits::Polygon_2> parts;
  CGAL::approx_convex_partition_2(in.begin(), in.end(), std::back_inserter(parts), Traits());
  std::vector<std::vector<Vec2>> out;
  for (const auto& p : parts) {
    out.emplace_back();
    for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v)
      out.back().push_back({CGAL::to_double(v->x()), CGAL::to_double(v->y())});
  }
  return out;
}

std::vector<BoundaryPiece> polygon_loop(const std::vector<Vec2>& vertices) {
  std::vector<BoundaryPiece> loop;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    loop.emplace_back(Segment{vertices[i], vertices[(i + 1) % vertices.size()]});
  return loop;
}

double overlap_depth(const std::vector<std::vector<BoundaryPiece>>& a,
                     const std::vector<std::vector<BoundaryPiece>>& b) {
  double depth = -std::numeric_limits<double>::infinity();
  for (const auto& pa : a)
    for (const auto& pb : b) depth = std::max(depth, convex_penetration_depth(pa, pb));
  return depth;
}

}  // namespace picdem::geometry
