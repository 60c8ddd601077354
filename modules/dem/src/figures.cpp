#include "picdem/dem/figures.hpp"

#include <algorithm>
#include <cmath>

namespace picdem::dem {

SurfaceMotion surface_motion(const DemSolver& dem, const core::Comm& comm) {
  return surface_motion(dem, comm, [](const core::SolidState&, double, double) { return true; });
}

SurfaceMotion surface_motion(const DemSolver& dem, const core::Comm& comm,
                             const SolidFilter& counts) {
  double vmax = 0.0;
  for (const auto& s : dem.owned()) {
    const double r = dem.shape_of(s.id)->bounding_radius();
    const double speed = std::sqrt(s.v.x * s.v.x + s.v.z * s.v.z) + std::abs(s.omega) * r;
    if (counts(s, r, speed)) vmax = std::max(vmax, speed);
  }
  const core::Vec2 g = dem.config().gravity;
  return {comm.max(vmax), std::sqrt(g.x * g.x + g.z * g.z)};
}

OwnedFigures owned_figures(const DemSolver& dem, const std::vector<double>& box) {
  OwnedFigures f;
  for (const auto& st : dem.owned()) {
    f.kinetic_energy += 0.5 * st.mass * core::norm2(st.v) + 0.5 * st.inertia * st.omega * st.omega;
    f.finite = f.finite && std::isfinite(st.x.x) && std::isfinite(st.x.z) && std::isfinite(st.v.x);
  }
  if (box.size() == 4)
    for (const auto& st : dem.owned())
      f.in_box += st.x.x >= box[0] && st.x.x <= box[1] && st.x.z >= box[2] && st.x.z <= box[3];
  return f;
}

}  // namespace picdem::dem
