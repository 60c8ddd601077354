// The rows of forces.csv (body_forces.hpp).
#include "body_forces.hpp"

#include <algorithm>

namespace picdem::coupling {

std::vector<BodyForces> body_forces(const std::vector<core::SolidState>& solids,
                                    const std::vector<core::SolidLoads>& pressure,
                                    const std::vector<core::SolidLoads>& obstacles,
                                    const ViscousExchange& viscous) {
  std::vector<BodyForces> rows;
  auto viscous_of = [](const std::vector<core::SolidLoads>& v, std::int64_t id) {
    return id >= 0 && static_cast<std::size_t>(id) < v.size() ? v[static_cast<std::size_t>(id)]
                                                              : core::SolidLoads{id, {}, 0.0};
  };
  for (const auto& st : solids) {
    const auto it =
        std::lower_bound(pressure.begin(), pressure.end(), st.id,
                         [](const core::SolidLoads& l, std::int64_t id) { return l.id < id; });
    const core::SolidLoads l =
        it != pressure.end() && it->id == st.id ? *it : core::SolidLoads{st.id, {0.0, 0.0}, 0.0};
    const auto v = viscous_of(viscous.solids, l.id);
    rows.push_back({l.id, false, l.force, v.force, l.torque, v.torque});
  }
  for (const auto& l : obstacles) {
    const auto v = viscous_of(viscous.obstacles, l.id);
    rows.push_back({l.id, true, l.force, v.force, l.torque, v.torque});
  }
  return rows;
}

}  // namespace picdem::coupling
