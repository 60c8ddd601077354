#pragma once
// Figures of the solids: the speed that bounds the coupled step (time/cfl_speed grid) and what the
// step's diagnostics record of them.
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/dem/dem_solver.hpp"

namespace picdem::dem {

/// Collective: the largest surface speed |v| + |omega| R of the solids (R the bounding radius)
/// over all ranks; 0 without solids.
double max_surface_speed(const DemSolver& dem, const core::Comm& comm);

/// This rank's owned solids (not collective).
struct OwnedFigures {
  double kinetic_energy = 0.0;  ///< sum of m |v|^2 / 2 + I omega^2 / 2 [J/m]
  bool finite = true;           ///< every position and velocity x finite
  long long in_box = 0;         ///< centres in `box` {x0, x1, z0, z1} (0 without a box)
};
OwnedFigures owned_figures(const DemSolver& dem, const std::vector<double>& box);

}  // namespace picdem::dem
