#include "picdem/geometry/outline.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"

namespace picdem::geometry {

std::vector<BoundaryPiece> world_boundary(const Shape& shape, const Pose& pose) {
  std::vector<BoundaryPiece> b = shape.boundary();
  // A solid turned a million radians and more (or spun up by a blown-up run) has its arcs' angles
  // reduced to one turn: beyond, phi0 + theta and phi1 + theta lose the arc's span to round-off
  // (at 1e20 a whole circle's arc had none). Below, the angles are added as they are.
  const double turn =
      std::abs(pose.theta) > 1e6 ? std::remainder(pose.theta, 2.0 * M_PI) : pose.theta;
  for (auto& piece : b) {
    if (auto* s = std::get_if<Segment>(&piece)) {
      *s = {pose.to_world(s->a), pose.to_world(s->b)};
    } else {
      auto& a = std::get<Arc>(piece);
      a.centre = pose.to_world(a.centre);
      a.phi0 += turn;
      a.phi1 += turn;
    }
  }
  return b;
}

std::vector<Vec2> outline(const Shape& shape, const Pose& pose, double max_chord) {
  if (!(max_chord > 0.0)) {
    std::ostringstream m;
    m << "outline: max_chord " << max_chord << " is not allowed: it must be > 0";
    throw core::InputError(m.str());
  }
  std::vector<Vec2> line;
  for (const auto& piece : world_boundary(shape, pose)) {
    if (const auto* s = std::get_if<Segment>(&piece)) {
      line.push_back(s->a);
    } else {
      const auto& a = std::get<Arc>(piece);
      const double span = a.phi1 - a.phi0;
      // chord = 2 r sin(dphi / 2) <= max_chord
      const double dphi_max =
          max_chord >= 2.0 * a.radius ? M_PI / 2 : 2.0 * std::asin(max_chord / (2.0 * a.radius));
      const int n = std::max(1, static_cast<int>(std::ceil(span / dphi_max)));
      for (int j = 0; j < n; ++j) {
        const double phi = a.phi0 + span * j / n;
        line.push_back(a.centre + a.radius * Vec2{std::cos(phi), std::sin(phi)});
      }
    }
  }
  if (!line.empty()) line.push_back(line.front());
  return line;
}

Box2 bounding_box(const Shape& shape, const Pose& pose) {
  Box2 b{{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
  auto add = [&b](const Vec2& p) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.z, p.z)};
  };
  for (const auto& piece : world_boundary(shape, pose)) {
    if (const auto* s = std::get_if<Segment>(&piece)) {
      add(s->a);
    } else {
      const auto& a = std::get<Arc>(piece);
      add(a.centre + a.radius * Vec2{std::cos(a.phi0), std::sin(a.phi0)});
      add(a.centre + a.radius * Vec2{std::cos(a.phi1), std::sin(a.phi1)});
      // a pose no longer finite (a blown-up run) has no place: no box, and no endless loop below
      if (!std::isfinite(a.phi0) || !std::isfinite(a.phi1)) continue;
      // Extreme points at multiples of pi/2 inside [phi0, phi1].
      for (int q = static_cast<int>(std::ceil(a.phi0 / (M_PI / 2))); q * (M_PI / 2) <= a.phi1;
           ++q) {
        const int m = ((q % 4) + 4) % 4;
        const Vec2 d = m == 0   ? Vec2{1, 0}
                       : m == 1 ? Vec2{0, 1}
                       : m == 2 ? Vec2{-1, 0}
                                : Vec2{0, -1};
        add(a.centre + a.radius * d);
      }
    }
  }
  return b;
}

}  // namespace picdem::geometry
