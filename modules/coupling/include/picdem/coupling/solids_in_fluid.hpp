#pragma once
// The solids as the fluid sees them (METHOD.md sections 3 and 6): the scene of the solids at one
// instant, cut cells at their poses and damping the fluid trapped in contact gaps (eq. 20). The
// solid couplings of the pressure equation and the loads J p are the fluid's
// (fluid/body_loads.hpp, PressureSolver::solid_loads). Plain functions over plain data.
#include <cstdint>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/solid_state.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/fluid/fluid.hpp"
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

/// Collective: every solid of the run (gathered from their owners, ordered by id) and the
/// obstacles: the scene of the replicated implicit viscous solve, in which every rank solves
/// the whole grid and so must see every solid.
SolidScene scene_of_all(const dem::DemSolver* dem,
                        const std::vector<geometry::Obstacle>& obstacles);

/// The states in `after` of the solids of `before`, in before's order (the bodies of cut cells
/// built from `before`), matched by id; a solid `after` does not hold keeps its state in before.
std::vector<core::SolidState> motions_at(const SolidScene& before, const SolidScene& after);

/// Cut cells over this rank's storage window; apertures = min(tank apertures, cut-cell E).
geometry::CutCells cut_cells(const SolidScene& scene, const grid::Decomposition& d,
                             double tiny_fraction, fluid::Apertures& apertures);

/// The body holding a point and the nearest point on its boundary, over a scene's solids and
/// obstacles (geometry::BodyLocator; the scene must outlive it).
class SolidLocator : public geometry::BodyLocator {
 public:
  explicit SolidLocator(const SolidScene& scene)
      : geometry::BodyLocator(scene.placements, scene.obstacles) {}
};
using geometry::push_out;

/// Eq. 20: the particles' velocities (and APIC matrices) scaled by the gap damping factor C of
/// `contacts` (dem::GapDamping: the bands of the active contacts, gathered from all ranks by
/// dem::all_contacts). Returns the number of particles damped on this rank.
long long damp_gap_particles(particles::ParticleSet& ps, const std::vector<dem::Contact>& contacts,
                             double h, double beta);

}  // namespace picdem::coupling
