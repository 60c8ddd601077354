#pragma once
// Closest points between the real boundaries of two bodies, built from the segments and arcs of
// geometry::Shape::boundary(). This is all the contact law needs for any pair of shapes: the gap
// between the real boundaries, the contact point (midpoint) and the normal (along the closest
// points). Circles take an exact fast path.
#include <vector>

#include "picdem/core/vec2.hpp"
#include "picdem/geometry/shape.hpp"

namespace picdem::dem {

using core::Vec2;
using geometry::BoundaryPiece;

/// Closest points of two curves: `on_a` on the first, `on_b` on the second.
struct ClosestPoints {
  Vec2 on_a, on_b;
  double distance = 0.0;
  bool face = false;  ///< two parallel segments facing each other: the points are the middle of
                      ///< their common stretch (so a flat face carries no spurious torque)
};

/// The boundary pieces moved from the body frame to the world frame.
std::vector<BoundaryPiece> to_world(const std::vector<BoundaryPiece>& body,
                                    const geometry::Pose& pose);

/// Closest point of a segment / an arc to a point.
Vec2 closest_on_segment(const geometry::Segment& s, const Vec2& p);
Vec2 closest_on_arc(const geometry::Arc& a, const Vec2& p);

/// Closest points of two pieces (0 distance when they cross).
ClosestPoints closest_points(const BoundaryPiece& a, const BoundaryPiece& b);
/// Closest points of two boundaries: the minimum over all piece pairs (first minimum in piece
/// order, so the result is deterministic).
ClosestPoints closest_points(const std::vector<BoundaryPiece>& a,
                             const std::vector<BoundaryPiece>& b);

/// The boundary point farthest along the unit direction d (support point of the curve).
Vec2 support_point(const std::vector<BoundaryPiece>& boundary, const Vec2& d);

/// True when the boundary is one full circle centred on the body origin; `radius` gets its radius.
bool is_centred_circle(const std::vector<BoundaryPiece>& boundary, double& radius);

}  // namespace picdem::dem
