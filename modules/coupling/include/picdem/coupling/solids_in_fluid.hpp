#pragma once
// The fluid-solid part of the coupled step (METHOD.md sections 3, 4 and 6): cut cells at the
// solids' poses, the solid couplings of the augmented pressure equation (eqs. 5-6), the fluid
// loads J p and damping the fluid trapped in contact gaps (eq. 20). Plain functions over plain
// data.
#include <cstdint>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/solid_state.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/geometry/locator.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/particles/particle_set.hpp"

namespace picdem::coupling {

/// The solids a rank sees at one instant (owned + ghosts, each with its shape), ordered by id,
/// and the fixed obstacles: what the fluid reads of the solids, built from the DEM at X^n and
/// again at X^{n+1}, never changed after. Cut cells built from a scene index its solids (the
/// body b of a piece is placements[b]); another scene is matched to them by id.
struct SolidScene {
  std::vector<geometry::SolidPlacement> placements;
  std::vector<core::SolidState> states;  ///< parallel to placements
  std::vector<geometry::Obstacle> obstacles;
  /// Position of solid `id` in placements and states; -1 when this rank does not see it.
  int index_of(std::int64_t id) const;
};

SolidScene scene_of(const dem::DemSolver* dem, const std::vector<geometry::Obstacle>& obstacles);

/// The states in `after` of the solids of `before`, in before's order (the bodies of cut cells
/// built from `before`), matched by id; a solid `after` does not hold keeps its state in before.
std::vector<core::SolidState> motions_at(const SolidScene& before, const SolidScene& after);

/// Cut cells over this rank's storage window; apertures = min(tank apertures, cut-cell E).
geometry::CutCells cut_cells(const SolidScene& scene, const grid::Decomposition& d,
                             double tiny_fraction, fluid::Apertures& apertures);

/// The hydrostatic part of the boundary quadrature: J p takes p at the cell centre x_c for the
/// whole piece of boundary in the cell; with rho_g_quadrature the pressure is carried from x_c
/// to the piece's midpoint m along the hydrostatic gradient, p(m) = p_c + rho g.(m - x_c), which
/// adds the p-independent load -sum_c rho g.(m_c - x_c) a_{s,c}. It keeps the system symmetric
/// and makes the discrete Archimedes force exact to second order (doc/coupling.md).
struct QuadratureOptions {
  bool hydrostatic = true;
  double rho = 1000.0;
  core::Vec2 g{0.0, -9.81};
};

/// One SolidCoupling per solid with pieces in this rank's owned fluid cells (partial lists,
/// joined by id in the solver): a_{s,c} = (int n dl, int r x n dl), M_s,
/// V* = V^n + dt M^-1 (F_g + F_coll + F_q) with F_coll the collision loads predicted at level n
/// and F_q the hydrostatic quadrature load, and F_q of the listed pieces as the load.
std::vector<fluid::SolidCoupling> solid_couplings(
    const SolidScene& scene, const geometry::CutCells& cut, const fluid::CellStates& cells,
    const grid::Decomposition& d, const std::vector<core::SolidLoads>& collision,
    const QuadratureOptions& quadrature, double dt, const core::Comm& comm);

/// Pressure loads J p + F_q, J p = -sum_c a_{s,c} p_c, on every owned solid of `dem` (summed
/// over ranks), from the rows of the last solve of `pressure` (PressureSolver::solid_loads).
std::vector<core::SolidLoads> fluid_loads(const fluid::PressureSolver& pressure,
                                          const grid::CellField& p, const dem::DemSolver& dem);

/// The body holding a point and the nearest point on its boundary, over a scene's solids and
/// obstacles (geometry::BodyLocator; the scene must outlive it).
class SolidLocator : public geometry::BodyLocator {
 public:
  explicit SolidLocator(const SolidScene& scene)
      : geometry::BodyLocator(scene.placements, scene.obstacles) {}
};
using geometry::push_out;

/// Eq. 20: particles in the band of an active contact (4h along the tangent, centred at the
/// contact point, h either side of it along the normal) have their velocity scaled by C, linear
/// from 1 at the band's ends to beta at the contact point. Contacts are gathered from all ranks.
/// Returns the number of particles damped on this rank.
long long damp_gap_particles(particles::ParticleSet& ps, const std::vector<dem::Contact>& contacts,
                             double h, double beta);

/// Every rank's active contacts, on every rank, in a fixed order.
std::vector<dem::Contact> all_contacts(const dem::DemSolver& dem, const core::Comm& comm);

}  // namespace picdem::coupling
