#pragma once
// Figures of the solids: the speed that bounds the coupled step (time/cfl_speed grid) and what the
// step's diagnostics record of them.
#include <functional>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/dem/dem_solver.hpp"

namespace picdem::dem {

/// How fast the solids' surfaces (and with them the cut cells and the rigid face velocities) may
/// move over the coming fluid step: a surface point moves at most (speed + accel dt) dt in dt.
struct SurfaceMotion {
  double speed = 0.0;  ///< the largest |v| + |omega| R over the solids (R the bounding radius)
  double accel = 0.0;  ///< |g|: the velocity change per second gravity predicts (eq. 21, step 1)
};
/// Collective: the SurfaceMotion of every rank's solids (speed 0 without solids). The fluid and
/// contact loads of the coming step are not known before it; gravity's change is.
SurfaceMotion surface_motion(const DemSolver& dem, const core::Comm& comm);
/// The same over the owned solids `counts` takes (the solid, its bounding radius R and its
/// surface speed |v| + |omega| R); collective.
using SolidFilter = std::function<bool(const core::SolidState&, double radius, double speed)>;
SurfaceMotion surface_motion(const DemSolver& dem, const core::Comm& comm,
                             const SolidFilter& counts);

/// This rank's owned solids (not collective).
struct OwnedFigures {
  double kinetic_energy = 0.0;  ///< sum of m |v|^2 / 2 + I omega^2 / 2 [J/m]
  bool finite = true;           ///< every position and velocity x finite
  long long in_box = 0;         ///< centres in `box` {x0, x1, z0, z1} (0 without a box)
};
OwnedFigures owned_figures(const DemSolver& dem, const std::vector<double>& box);

}  // namespace picdem::dem
