// The scene's bodies for the implicit viscous operator (viscous_bodies.hpp).
#include "viscous_bodies.hpp"

namespace picdem::coupling {

using core::Vec2;

namespace {

/// Even-odd rule over all polygons of an obstacle (its union when they do not overlap).
bool inside_polygons(const std::vector<std::vector<Vec2>>& polygons, const Vec2& p) {
  for (const auto& poly : polygons) {
    bool in = false;
    for (std::size_t a = 0, b = poly.size() - 1; a < poly.size(); b = a++) {
      const Vec2 &pa = poly[a], &pb = poly[b];
      if ((pa.z > p.z) != (pb.z > p.z) && p.x < pa.x + (p.z - pa.z) * (pb.x - pa.x) / (pb.z - pa.z))
        in = !in;
    }
    if (in) return true;
  }
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
