// The scene's bodies for the implicit viscous operator (viscous_bodies.hpp).
#include "viscous_bodies.hpp"

#include <algorithm>

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

std::vector<fluid::ViscousBody> viscous_bodies(const SolidScene& scene, bool rigid_rows) {
  std::vector<fluid::ViscousBody> bodies;
  for (std::size_t b = 0; b < scene.placements.size(); ++b) {
    const geometry::SolidPlacement& pl = scene.placements[b];
    const core::SolidState& st = scene.states[b];
    const geometry::ShapePtr shape = pl.shape;
    const geometry::Pose pose = pl.pose;
    bodies.push_back({[shape, pose](const Vec2& x) { return shape->contains(pose.to_body(x)); },
                      st.v, st.omega, pose.x, shape->mass_properties().area,
                      rigid_rows ? st.mass : 0.0, rigid_rows ? st.inertia : 0.0});
  }
  for (const geometry::Obstacle& o : scene.obstacles) {
    const auto polygons = o.polygons;
    bodies.push_back(
        {[polygons](const Vec2& x) { return inside_polygons(polygons, x); }, {}, 0.0, {}, 0.0});
  }
  return bodies;
}

}  // namespace picdem::coupling

namespace picdem::coupling {

SolidScene scene_of_all(const dem::DemSolver* dem,
                        const std::vector<geometry::Obstacle>& obstacles) {
  SolidScene scene;
  scene.obstacles = obstacles;
  if (!dem) return scene;
  scene.states = dem->gather_all();
  for (const auto& st : scene.states)
    scene.placements.push_back({st.id, dem->shape_of(st.id), {st.x, st.theta}});
  return scene;
}

ViscousExchange viscous_exchange(const SolidScene& scene, const fluid::ViscousLoads& loads,
                                 const dem::DemSolver* dem, const core::Comm& comm) {
  ViscousExchange out;
  const std::size_t solids = scene.states.size();
  if (loads.force.size() != solids + scene.obstacles.size()) return out;  // nu = 0: none
  std::int64_t n = 0;
  for (const auto& st : scene.states) n = std::max(n, st.id + 1);
  n = static_cast<std::int64_t>(comm.max(static_cast<long long>(n)));
  // id -> (F_x, F_z, T), written by the owner only, then summed over the ranks
  std::vector<double> table(static_cast<std::size_t>(3 * n), 0.0);
  if (dem)
    for (const auto& st : dem->owned()) {
      const int b = scene.index_of(st.id);
      if (b < 0) continue;
      double* r = &table[static_cast<std::size_t>(3 * st.id)];
      r[0] = loads.force[static_cast<std::size_t>(b)].x;
      r[1] = loads.force[static_cast<std::size_t>(b)].z;
      r[2] = loads.torque[static_cast<std::size_t>(b)];
    }
  comm.sum_in_place(table);
  for (std::int64_t id = 0; id < n; ++id) {
    const double* r = &table[static_cast<std::size_t>(3 * id)];
    out.solids.push_back({id, {r[0], r[1]}, r[2]});
  }
  for (std::size_t o = 0; o < scene.obstacles.size(); ++o)
    out.obstacles.push_back(
        {static_cast<std::int64_t>(o), loads.force[solids + o], loads.torque[solids + o]});
  return out;
}

std::vector<core::SolidLoads> plus_viscous(const std::vector<core::SolidLoads>& loads,
                                           const ViscousExchange& viscous,
                                           const dem::DemSolver& dem) {
  std::vector<core::SolidLoads> out = loads;
  for (const auto& st : dem.owned()) {
    if (st.id < 0 || static_cast<std::size_t>(st.id) >= viscous.solids.size()) continue;
    const core::SolidLoads& v = viscous.solids[static_cast<std::size_t>(st.id)];
    auto it = std::find_if(out.begin(), out.end(),
                           [&](const core::SolidLoads& l) { return l.id == st.id; });
    if (it == out.end()) it = out.insert(out.end(), {st.id, {0.0, 0.0}, 0.0});
    it->force += v.force;
    it->torque += v.torque;
  }
  std::sort(out.begin(), out.end(),
            [](const core::SolidLoads& a, const core::SolidLoads& b) { return a.id < b.id; });
  return out;
}

}  // namespace picdem::coupling
