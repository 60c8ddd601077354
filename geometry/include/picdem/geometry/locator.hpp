#pragma once
// Points inside bodies: which solid or obstacle holds a point, the nearest point of its boundary
// and the body's outward normal there (for particles that end inside a body, and for seeding).
#include <vector>

#include "picdem/core/vec2.hpp"
#include "picdem/geometry/cut_cells.hpp"

namespace picdem::geometry {

/// Even-odd rule: true when p is inside the simple polygon `poly` (either orientation).
bool inside_polygon(Vec2 p, const std::vector<Vec2>& poly);

/// Finds the body holding a point and the nearest point on its boundary; solids and obstacles are
/// bucketed by their bounding boxes. `solids` must outlive the locator.
class BodyLocator {
 public:
  BodyLocator(const std::vector<SolidPlacement>& solids, const std::vector<Obstacle>& obstacles);
  /// True when p is inside a solid or obstacle; `surface` is then the nearest boundary point
  /// and `normal` the body's outward normal there.
  bool inside(Vec2 p, Vec2* surface = nullptr, Vec2* normal = nullptr) const;

 private:
  const std::vector<SolidPlacement>& solids_;
  double cell_ = 1.0;
  Vec2 lo_;
  int nx_ = 0, nz_ = 0;
  std::vector<std::vector<int>> buckets_;  // solid indices by bucket; obstacles after solids
  std::vector<core::Box2> boxes_;          // bounding boxes, grown by a margin (a quick reject)
  std::vector<std::vector<Vec2>> obstacle_polys_;
};

/// Moves a point found inside a body to a tenth of a cell h outside the nearest point of its
/// surface; a point outside every body stays.
void push_out(const BodyLocator& locator, double h, double& x, double& z);

}  // namespace picdem::geometry
