#pragma once
// The bodies in the pressure equation, read from geometry's cut cells (CGAL-free data): the solid
// couplings of the augmented pressure equation (eqs. 5-6, METHOD.md section 4), whose rows
// a_{s,c} give the solids' loads J_s p + F_s (PressureSolver::solid_loads), and the pressure
// loads on the fixed obstacles, which are not unknowns of the system. Bodies are indexed as in
// the cut cells (WettedPiece::body: solid b, or obstacle -1 - o).
#include <cstddef>
#include <vector>

#include "picdem/core/solid_state.hpp"
#include "picdem/core/vec2.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/grid/field.hpp"

namespace picdem::fluid {

/// The hydrostatic part of the boundary quadrature: J p takes p at the cell centre x_c for the
/// whole piece of boundary in the cell; with `hydrostatic` the pressure is carried from x_c to
/// the piece's points along the hydrostatic gradient, p(x) = p_c + rho g.(x - x_c), which adds
/// the p-independent load F_q = -sum_c int rho g.(x - x_c) (n, r x n) dl. It keeps the system
/// symmetric and makes the discrete Archimedes force exact to second order (doc/coupling.md).
struct QuadratureOptions {
  bool hydrostatic = true;
  double rho = 1000.0;
  core::Vec2 g{0.0, -9.81};
};

/// Collective over d.comm(): one SolidCoupling per solid with pieces in this rank's owned fluid
/// cells (partial lists, joined by id in the solver): a_{s,c} = (int n dl, int r x n dl),
/// M_s, V* = V^n + dt M^-1 (F_g + F_coll + F_q) with F_coll the collision loads predicted at
/// level n (`collision`, owned solids, from their owners) and F_q the hydrostatic quadrature
/// load, and F_q of the listed pieces as the load. bodies[b]: the state of cut body b (ids
/// 0 .. n-1 over the ranks).
std::vector<SolidCoupling> solid_couplings(const std::vector<core::SolidState>& bodies,
                                           const geometry::CutCells& cut, const CellStates& cells,
                                           const grid::Decomposition& d,
                                           const std::vector<core::SolidLoads>& collision,
                                           const QuadratureOptions& quadrature, double dt);

/// Collective: the pressure force -sum_c p_c int n dl + F_q on each of `count` obstacles, over
/// the boundary pieces in the owned Fluid cells, summed over the ranks; the torque about (0, 0)
/// with p_c on the whole piece plus the moment of F_q taken at the cell centre (id = the
/// obstacle's index). Obstacles have no rows in the pressure matrix (they do not move), so their
/// loads are read from the pieces directly.
std::vector<core::SolidLoads> obstacle_pressure_loads(
    const geometry::CutCells& cut, const CellStates& cells, const grid::Decomposition& d,
    const grid::CellField& p, const QuadratureOptions& quadrature, std::size_t count);

}  // namespace picdem::fluid
