#pragma once
// Solid shapes. Every shape is a closed, counter-clockwise curve made of straight segments and
// circular arcs, given in its body frame with the centre of mass at the origin. That one
// representation is all the cut-cell code and the contact code need, so a new shape takes part
// in both by implementing this interface once (doc/shapes.md).
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "picdem/core/vec2.hpp"

namespace picdem::geometry {

using core::Vec2;

/// Rigid placement: world = x + R(theta) body.
struct Pose {
  Vec2 x;
  double theta = 0.0;
  Vec2 to_world(const Vec2& body) const { return x + core::rotate(body, theta); }
  Vec2 to_body(const Vec2& world) const { return core::rotate(world - x, -theta); }
};

/// Straight piece from a to b. The solid lies on its left (outward normal = right-hand normal).
struct Segment {
  Vec2 a, b;
};

/// Circular piece, counter-clockwise from angle phi0 to phi1 (phi0 < phi1 <= phi0 + 2 pi), the
/// solid inside the circle (a convex arc).
struct Arc {
  Vec2 centre;
  double radius = 0.0;
  double phi0 = 0.0, phi1 = 0.0;
};

using BoundaryPiece = std::variant<Segment, Arc>;

/// Area properties of a shape per unit density and depth.
struct MassProperties {
  double area = 0.0;          ///< m^2 (mass per unit depth = density x area)
  double polar_moment = 0.0;  ///< m^4 about the centre of mass (inertia = density x this)
};

class Shape {
 public:
  virtual ~Shape() = default;
  /// "circle", "polygon", ...
  virtual std::string kind() const = 0;
  /// The closed counter-clockwise boundary in the body frame (centre of mass at the origin).
  virtual std::vector<BoundaryPiece> boundary() const = 0;
  virtual MassProperties mass_properties() const = 0;
  /// Largest distance from the body origin to the boundary.
  virtual double bounding_radius() const = 0;
  /// True when the body-frame point is inside or on the boundary.
  virtual bool contains(const Vec2& body_point) const = 0;
};

using ShapePtr = std::shared_ptr<const Shape>;

}  // namespace picdem::geometry
