#include "picdem/coupling/solids_in_fluid.hpp"

#include <algorithm>

#include "picdem/dem/gap_damping.hpp"
#include "picdem/fluid/bodies.hpp"

namespace picdem::coupling {

using core::Vec2;
using grid::CellState;
using grid::Stagger;

SolidScene scene_of(const dem::DemSolver* dem, const std::vector<geometry::Obstacle>& obstacles) {
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

geometry::CutCells cut_cells(const SolidScene& scene, const grid::Decomposition& d,
                             double tiny_fraction, fluid::Apertures& apertures) {
  const auto& spec = d.spec();
  geometry::GridWindow window{spec.origin, spec.h, d.storage(Stagger::Cell)};
  geometry::CutCellOptions options;
  options.tiny_fraction = tiny_fraction;
  auto cut = geometry::build_cut_cells(window, scene.placements, scene.obstacles, options);
  apertures = fluid::body_apertures(cut, d);
  return cut;
}

long long damp_gap_particles(particles::ParticleSet& ps, const std::vector<dem::Contact>& contacts,
                             double h, double beta) {
  if (contacts.empty() || beta >= 1.0) return 0;
  long long damped = 0;
  const dem::GapDamping gap(contacts, h, beta);
  for (std::size_t n = 0; n < ps.x.size(); ++n) {
    const double C = gap.factor({ps.x[n], ps.z[n]});  // eq. 20
    if (C < 1.0) {
      ps.u[n] *= C, ps.w[n] *= C;
      ps.cxx[n] *= C, ps.cxz[n] *= C, ps.czx[n] *= C, ps.czz[n] *= C;
      ++damped;
    }
  }
  return damped;
}

}  // namespace picdem::coupling
