// The scene's bodies for the implicit viscous operator (viscous_bodies.hpp).
#include "viscous_bodies.hpp"

#include "picdem/geometry/locator.hpp"

namespace picdem::coupling {

using core::Vec2;

namespace {

/// Inside any of the obstacle's polygons (its union when they do not overlap).
bool inside_polygons(const std::vector<std::vector<Vec2>>& polygons, const Vec2& p) {
  for (const auto& poly : polygons)
    if (geometry::inside_polygon(p, poly)) return true;
  return false;
}

}  // namespace

std::vector<fluid::ViscousBody> viscous_bodies(const SolidScene& scene) {
  std::vector<fluid::ViscousBody> bodies;
  for (std::size_t b = 0; b < scene.placements.size(); ++b) {
    const geometry::SolidPlacement& pl = scene.placements[b];
    const core::SolidState& st = scene.states[b];
    const geometry::ShapePtr shape = pl.shape;
    const geometry::Pose pose = pl.pose;
    bodies.push_back({[shape, pose](const Vec2& x) { return shape->contains(pose.to_body(x)); },
                      st.v, st.omega, pose.x, shape->mass_properties().area});
  }
  for (const geometry::Obstacle& o : scene.obstacles) {
    const auto polygons = o.polygons;
    bodies.push_back(
        {[polygons](const Vec2& x) { return inside_polygons(polygons, x); }, {}, 0.0, {}, 0.0});
  }
  return bodies;
}

}  // namespace picdem::coupling
