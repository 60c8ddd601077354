// The rows of forces.csv (forces.hpp).
#include "picdem/run/forces.hpp"

#include <algorithm>

#include "picdem/dem/dem_solver.hpp"

namespace picdem::run {

// Every solid by id once a step with water has given them pressure loads (zero for a solid
// without rows; none in a dry run), then every obstacle; viscous loads zero when the step
// computed none.
std::vector<BodyForces> body_forces(const coupling::Simulation& sim) {
  const coupling::StepLoads s = sim.last_loads();
  auto of = [](const std::vector<core::SolidLoads>& by_id, std::int64_t id) {
    const auto it =
        std::lower_bound(by_id.begin(), by_id.end(), id,
                         [](const core::SolidLoads& l, std::int64_t key) { return l.id < key; });
    return it != by_id.end() && it->id == id ? *it : core::SolidLoads{id, {0.0, 0.0}, 0.0};
  };
  std::vector<BodyForces> rows;
  if (sim.dem() && sim.has_fluid())
    for (const auto& st : sim.dem()->gather_all()) {
      const auto p = of(s.pressure, st.id), v = of(s.viscous, st.id);
      rows.push_back({st.id, false, p.force, v.force, p.torque, v.torque});
    }
  for (const auto& p : s.obstacle_pressure) {
    const auto v = of(s.obstacle_viscous, p.id);
    rows.push_back({p.id, true, p.force, v.force, p.torque, v.torque});
  }
  return rows;
}

}  // namespace picdem::run
