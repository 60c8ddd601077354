// The DEM's solids at one instant (scene.hpp).
#include "picdem/dem/scene.hpp"

#include <algorithm>

namespace picdem::dem {

const std::vector<core::SolidState>& owned_solids(const DemSolver* dem) {
  static const std::vector<core::SolidState> none;
  return dem ? dem->owned() : none;
}

SolidScene scene_of(const DemSolver* dem, const std::vector<geometry::Obstacle>& obstacles) {
  SolidScene scene;
  scene.obstacles = obstacles;
  if (!dem) return scene;
  scene.states = dem->owned();
  const auto ghosts = dem->ghosts();
  scene.states.insert(scene.states.end(), ghosts.begin(), ghosts.end());
  std::sort(scene.states.begin(), scene.states.end(),
            [](const core::SolidState& a, const core::SolidState& b) { return a.id < b.id; });
  for (const auto& st : scene.states)
    scene.placements.push_back({st.id, dem->shape_of(st.id), {st.x, st.theta}});
  return scene;
}

SolidScene scene_of_all(const DemSolver* dem, const std::vector<geometry::Obstacle>& obstacles) {
  SolidScene scene;
  scene.obstacles = obstacles;
  if (!dem) return scene;
  scene.states = dem->gather_all();
  for (const auto& st : scene.states)
    scene.placements.push_back({st.id, dem->shape_of(st.id), {st.x, st.theta}});
  return scene;
}

int SolidScene::index_of(std::int64_t id) const {
  const auto it =
      std::lower_bound(states.begin(), states.end(), id,
                       [](const core::SolidState& st, std::int64_t key) { return st.id < key; });
  return it != states.end() && it->id == id ? static_cast<int>(it - states.begin()) : -1;
}

std::vector<core::SolidState> motions_at(const SolidScene& before, const SolidScene& after) {
  std::vector<core::SolidState> out = before.states;
  for (auto& st : out)
    if (const int n = after.index_of(st.id); n >= 0) st = after.states[static_cast<std::size_t>(n)];
  return out;
}

}  // namespace picdem::dem
