#pragma once
// Closest points between the real boundaries of two bodies, built from the segments and arcs of
// geometry::Shape::boundary(). This is all the contact law needs for any pair of shapes: the gap
// between the real boundaries, the contact point (midpoint) and the normal (along the closest
// points). Shapes declaring the centred-circle fast path (Shape::fast_paths) skip this in the
// DEM.
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
  /// Two nearly parallel segments facing each other (within 0.1 rad): the ends of the stretch
  /// where they face each other, end_a[e] on the first and end_b[e] on the second. on_a / on_b
  /// are then the closer of the two ends.
  bool face = false;
  Vec2 end_a[2], end_b[2];
};

/// An arc's unit end directions (from its centre) and end points, with its span's kind: what the
/// tests of a pair need, so that they take neither sines nor angles. A segment's entry is unused.
struct ArcEnds {
  Vec2 u0, u1;        ///< unit directions from the centre to the start and the end
  Vec2 p0, p1;        ///< the end points
  bool wide = false;  ///< the span exceeds pi
  bool full = false;  ///< the span is the whole circle
};

/// A boundary's pieces with their arcs' end data (ends[k] belongs to pieces[k]). A body keeps its
/// body-frame boundary in this form; placing it rotates the end directions (no sines per piece).
struct Boundary {
  std::vector<BoundaryPiece> pieces;
  std::vector<ArcEnds> ends;
  void clear() {
    pieces.clear();
    ends.clear();
  }
};

/// `pieces` with their arcs' end data computed (a sine and a cosine per arc end).
Boundary with_ends(std::vector<BoundaryPiece> pieces);

/// The boundary pieces moved from the body frame to the world frame.
std::vector<BoundaryPiece> to_world(const std::vector<BoundaryPiece>& body,
                                    const geometry::Pose& pose);
/// The same with the end data: `out` is replaced.
void to_world(const Boundary& body, const geometry::Pose& pose, Boundary& out);

/// The pieces of `body` (body frame) placed by `pose` whose distance to `centre` is below `reach`,
/// appended to `out` in their boundary order (the pieces that can touch a body of bounding radius
/// reach - gap centred there).
void to_world_near(const std::vector<BoundaryPiece>& body, const geometry::Pose& pose,
                   const Vec2& centre, double reach, std::vector<BoundaryPiece>& out);
void to_world_near(const Boundary& body, const geometry::Pose& pose, const Vec2& centre,
                   double reach, Boundary& out);

/// Closest point of a segment / an arc to a point.
Vec2 closest_on_segment(const geometry::Segment& s, const Vec2& p);
Vec2 closest_on_arc(const geometry::Arc& a, const Vec2& p);

/// Closest points of two pieces (0 distance when they cross).
ClosestPoints closest_points(const BoundaryPiece& a, const BoundaryPiece& b);
/// Closest points of two boundaries: the minimum over all piece pairs (first minimum in piece
/// order, so the result is deterministic).
ClosestPoints closest_points(const std::vector<BoundaryPiece>& a,
                             const std::vector<BoundaryPiece>& b);
ClosestPoints closest_points(const Boundary& a, const Boundary& b);

/// The contact points on each body for a gap `gap` between imaginary boundaries: for a face
/// contact, the ends weighted by their overlaps gap - distance (so a face lying flat pushes at
/// its middle and a tilted one towards its deeper end, continuous with a corner contact); else
/// the closest points.
void face_weighted(const ClosestPoints& cp, double gap, Vec2& on_a, Vec2& on_b);

/// The boundary point farthest along the unit direction d (support point of the curve).
Vec2 support_point(const std::vector<BoundaryPiece>& boundary, const Vec2& d);
Vec2 support_point(const Boundary& boundary, const Vec2& d);

}  // namespace picdem::dem
