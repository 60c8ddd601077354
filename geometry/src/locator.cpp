#include "picdem/geometry/locator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "picdem/geometry/outline.hpp"

namespace picdem::geometry {

bool inside_polygon(Vec2 p, const std::vector<Vec2>& poly) {
  bool in = false;
  for (std::size_t a = 0, b = poly.size() - 1; a < poly.size(); b = a++) {
    const Vec2 &pa = poly[a], &pb = poly[b];
    if ((pa.z > p.z) != (pb.z > p.z) && p.x < (pb.x - pa.x) * (p.z - pa.z) / (pb.z - pa.z) + pa.x)
      in = !in;
  }
  return in;
}

namespace {

// Nearest point to p on segment ab, and the solid's outward normal there (solid on the left).
void nearest_on_segment(Vec2 p, Vec2 a, Vec2 b, Vec2& q, Vec2& n) {
  const Vec2 ab = b - a;
  const double L2 = core::norm2(ab);
  const double t = L2 > 0 ? std::clamp(core::dot(p - a, ab) / L2, 0.0, 1.0) : 0.0;
  q = a + t * ab;
  n = L2 > 0 ? Vec2{ab.z, -ab.x} / std::sqrt(L2) : Vec2{0, 1};
}

void nearest_on_arc(Vec2 p, const Arc& arc, Vec2& q, Vec2& n) {
  const Vec2 d = p - arc.centre;
  double phi = std::atan2(d.z, d.x);
  while (phi < arc.phi0) phi += 2 * M_PI;
  while (phi > arc.phi0 + 2 * M_PI) phi -= 2 * M_PI;
  if (phi > arc.phi1) {
    // outside the arc's span: the nearer end
    const Vec2 e0 = arc.centre + arc.radius * Vec2{std::cos(arc.phi0), std::sin(arc.phi0)};
    const Vec2 e1 = arc.centre + arc.radius * Vec2{std::cos(arc.phi1), std::sin(arc.phi1)};
    phi = core::norm2(p - e0) < core::norm2(p - e1) ? arc.phi0 : arc.phi1;
  }
  n = {std::cos(phi), std::sin(phi)};
  q = arc.centre + arc.radius * n;
}

void nearest_on_boundary(Vec2 p, const std::vector<BoundaryPiece>& pieces, Vec2& best_q,
                         Vec2& best_n) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& piece : pieces) {
    Vec2 q, n;
    if (const auto* s = std::get_if<Segment>(&piece))
      nearest_on_segment(p, s->a, s->b, q, n);
    else
      nearest_on_arc(p, std::get<Arc>(piece), q, n);
    const double d2 = core::norm2(p - q);
    if (d2 < best) best = d2, best_q = q, best_n = n;
  }
}

}  // namespace

BodyLocator::BodyLocator(const std::vector<SolidPlacement>& solids,
                         const std::vector<Obstacle>& obstacles)
    : solids_(solids) {
  std::vector<core::Box2> boxes;
  double rmax = 0.0;
  for (const auto& pl : solids) {
    boxes.push_back(bounding_box(*pl.shape, pl.pose));
    rmax = std::max(rmax, pl.shape->bounding_radius());
  }
  for (const auto& o : obstacles)
    for (const auto& poly : o.polygons) {
      core::Box2 b{poly.front(), poly.front()};
      for (const auto& v : poly) {
        b.lo.x = std::min(b.lo.x, v.x), b.lo.z = std::min(b.lo.z, v.z);
        b.hi.x = std::max(b.hi.x, v.x), b.hi.z = std::max(b.hi.z, v.z);
      }
      boxes.push_back(b);
      obstacle_polys_.push_back(poly);
    }
  if (boxes.empty()) return;
  // A point inside a body lies inside its box; the margin covers the rounding of the box's
  // corners against the body's own test (a quick reject only: it changes no answer).
  for (const auto& b : boxes) {
    const double m = 1e-6 * std::max({b.hi.x - b.lo.x, b.hi.z - b.lo.z, rmax});
    boxes_.push_back({{b.lo.x - m, b.lo.z - m}, {b.hi.x + m, b.hi.z + m}});
  }
  core::Box2 all = boxes.front();
  for (const auto& b : boxes) {
    all.lo.x = std::min(all.lo.x, b.lo.x), all.lo.z = std::min(all.lo.z, b.lo.z);
    all.hi.x = std::max(all.hi.x, b.hi.x), all.hi.z = std::max(all.hi.z, b.hi.z);
  }
  cell_ = std::max(2.0 * rmax, 1e-3 * std::max(all.hi.x - all.lo.x, all.hi.z - all.lo.z));
  if (!(cell_ > 0)) cell_ = 1.0;
  lo_ = all.lo;
  nx_ = static_cast<int>((all.hi.x - all.lo.x) / cell_) + 1;
  nz_ = static_cast<int>((all.hi.z - all.lo.z) / cell_) + 1;
  buckets_.assign(static_cast<std::size_t>(nx_) * nz_, {});
  for (std::size_t n = 0; n < boxes.size(); ++n) {
    const int i0 = static_cast<int>((boxes[n].lo.x - lo_.x) / cell_);
    const int i1 = std::min(nx_ - 1, static_cast<int>((boxes[n].hi.x - lo_.x) / cell_));
    const int k0 = static_cast<int>((boxes[n].lo.z - lo_.z) / cell_);
    const int k1 = std::min(nz_ - 1, static_cast<int>((boxes[n].hi.z - lo_.z) / cell_));
    for (int k = k0; k <= k1; ++k)
      for (int i = i0; i <= i1; ++i)
        buckets_[static_cast<std::size_t>(k) * nx_ + i].push_back(static_cast<int>(n));
  }
}

bool BodyLocator::inside(Vec2 p, Vec2* surface, Vec2* normal) const {
  if (buckets_.empty()) return false;
  const int i = static_cast<int>(std::floor((p.x - lo_.x) / cell_));
  const int k = static_cast<int>(std::floor((p.z - lo_.z) / cell_));
  if (i < 0 || k < 0 || i >= nx_ || k >= nz_) return false;
  const std::size_t n_solids = solids_.size();
  for (int n : buckets_[static_cast<std::size_t>(k) * nx_ + i]) {
    const auto un = static_cast<std::size_t>(n);
    const core::Box2& box = boxes_[un];
    if (p.x < box.lo.x || p.x > box.hi.x || p.z < box.lo.z || p.z > box.hi.z) continue;
    Vec2 q, nrm;
    if (un < n_solids) {
      const auto& pl = solids_[un];
      if (!pl.shape->contains(pl.pose.to_body(p))) continue;
      if (surface || normal) nearest_on_boundary(p, world_boundary(*pl.shape, pl.pose), q, nrm);
    } else {
      const auto& poly = obstacle_polys_[un - n_solids];
      if (!inside_polygon(p, poly)) continue;
      std::vector<BoundaryPiece> pieces;
      for (std::size_t a = 0; a < poly.size(); ++a)
        pieces.push_back(Segment{poly[a], poly[(a + 1) % poly.size()]});
      if (surface || normal) nearest_on_boundary(p, pieces, q, nrm);
    }
    if (surface) *surface = q;
    if (normal) *normal = nrm;
    return true;
  }
  return false;
}

void push_out(const BodyLocator& locator, double h, double& x, double& z) {
  Vec2 p{x, z}, q, nrm;
  // A few passes: the nearest surface of one polygon of an obstacle may lie in another.
  for (int pass = 0; pass < 3 && locator.inside(p, &q, &nrm); ++pass) p = q + 0.1 * h * nrm;
  x = p.x, z = p.z;
}

}  // namespace picdem::geometry
