#pragma once
// The P2G tent integrated (not interpolated): the share of a node's transfer weight that a
// stretch or a box holds. One function for the particles' occupancy at the tank walls
// (particles/occupancy.cpp: the tent's mass inside the tank), the open-share correction of the
// free surface (fluid/free_surface.cpp: the tent's mass in a cell and its neighbours) and the
// viscous cut-node masses (fluid/viscous_operator.cpp: the tent's mass outside the bodies). The
// particles' kernel itself (interpolation) is particles' stencil.
#include <algorithm>

namespace picdem::grid {

/// Integral of the 1D tent max(0, 1 - |t|) from -1 to t (t in cell sizes from its node): 0 below
/// -1, 1/2 at 0, 1 above 1.
inline double tent_cdf(double t) {
  t = std::clamp(t, -1.0, 1.0);
  return t <= 0.0 ? 0.5 * (1.0 + t) * (1.0 + t) : 1.0 - 0.5 * (1.0 - t) * (1.0 - t);
}

/// Integral of the 1D tent over [lo, hi] (cell sizes from its node): the share of the node's
/// weight along one axis that [lo, hi] holds (1 over [-1, 1]). The bilinear tent (1 - |x|)(1 - |z|)
/// is a product, so a box [x0, x1] x [z0, z1] holds tent_share(x0, x1) * tent_share(z0, z1).
/// Exact in floating point for the bounds used here (halves and sixteenths of a cell): every
/// intermediate is a short multiple of a power of two, so the shares equal the midpoint rule's
/// (1 - |t_mid|) (hi - lo) on stretches that do not cross the node bit for bit.
inline double tent_share(double lo, double hi) {
  return tent_cdf(hi) - tent_cdf(lo);
}

}  // namespace picdem::grid
