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

/// Optional fast paths a shape may declare. The contact code takes them instead of the general
/// piece-by-piece closest points; a shape that declares none is handled by the general code.
struct FastPaths {
  /// > 0: the shape is one full circle of this radius centred on its body origin, and contacts
  /// use eq. 19 in closed form (delta = r_i + r_j + 2 dx - d_ij). 0: no such path.
  double centred_circle_radius = 0.0;
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
  /// The fast paths this shape declares (none by default).
  virtual FastPaths fast_paths() const { return {}; }
};

using ShapePtr = std::shared_ptr<const Shape>;

/// Area, centroid and polar second moment (about the centroid) of a region.
struct RegionProperties {
  double area = 0.0;
  Vec2 centroid;
  double polar_moment = 0.0;
};

/// The region inside a closed counter-clockwise loop of segments and convex arcs (each arc's
/// solid inside its circle, span below 2 pi), exactly: the polygon of the pieces' end points plus
/// one circular segment (between chord and arc) per arc. The loop must close: each piece starts
/// where the previous one ends.
RegionProperties loop_properties(const std::vector<BoundaryPiece>& loop);

}  // namespace picdem::geometry
