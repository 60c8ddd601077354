#pragma once
// Drawing helpers: shape outlines as polylines (ParaView, PNG) and world bounding boxes.
#include <vector>

#include "picdem/core/vec2.hpp"
#include "picdem/geometry/shape.hpp"

namespace picdem::geometry {

using core::Box2;

/// The boundary of `shape` placed at `pose`, as a closed polyline in the world frame: the last
/// point repeats the first. Straight pieces keep their end points; arcs are split so that no
/// chord is longer than `max_chord` (> 0, else InputError).
std::vector<Vec2> outline(const Shape& shape, const Pose& pose, double max_chord);

/// The boundary pieces of `shape` in the world frame (arcs keep their exact form).
std::vector<BoundaryPiece> world_boundary(const Shape& shape, const Pose& pose);

/// The smallest axis-aligned box holding the placed shape (arcs' extreme points included).
Box2 bounding_box(const Shape& shape, const Pose& pose);

}  // namespace picdem::geometry
