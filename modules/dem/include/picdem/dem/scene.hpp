#pragma once
// The DEM's solids at one instant as the fluid reads them (METHOD.md section 3): a snapshot of
// the solids a rank sees, ordered by id, with their shapes, and the fixed obstacles; built at X^n
// and again at X^{n+1}, never changed after. The step builds the cut cells and the fluid's
// apertures from it (fluid::cut_cells). Plain data.
#include <cstdint>
#include <vector>

#include "picdem/core/solid_state.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/geometry/locator.hpp"

namespace picdem::dem {

/// The solids a rank sees at one instant (owned + ghosts, each with its shape), ordered by id,
/// and the fixed obstacles. Cut cells built from a scene index its solids (the body b of a piece
/// is placements[b]); another scene is matched to them by id.
struct SolidScene {
  std::vector<geometry::SolidPlacement> placements;
  std::vector<core::SolidState> states;  ///< parallel to placements
  std::vector<geometry::Obstacle> obstacles;
  /// Position of solid `id` in placements and states; -1 when this rank does not see it.
  int index_of(std::int64_t id) const;
};

/// The solids `dem` owns (none when dem is null).
const std::vector<core::SolidState>& owned_solids(const DemSolver* dem);

/// The solids `dem` holds on this rank (owned and ghosts; none when dem is null) and `obstacles`.
SolidScene scene_of(const DemSolver* dem, const std::vector<geometry::Obstacle>& obstacles);

/// Collective: every solid of the run (gathered from their owners, ordered by id) and the
/// obstacles: the scene of the replicated implicit viscous solve, in which every rank solves
/// the whole grid and so must see every solid.
SolidScene scene_of_all(const DemSolver* dem, const std::vector<geometry::Obstacle>& obstacles);

/// The states in `after` of the solids of `before`, in before's order (the bodies of cut cells
/// built from `before`), matched by id; a solid `after` does not hold keeps its state in before.
std::vector<core::SolidState> motions_at(const SolidScene& before, const SolidScene& after);

/// The body holding a point and the nearest point on its boundary, over a scene's solids and
/// obstacles (geometry::BodyLocator; the scene must outlive it).
class SolidLocator : public geometry::BodyLocator {
 public:
  explicit SolidLocator(const SolidScene& scene)
      : geometry::BodyLocator(scene.placements, scene.obstacles) {}
};

}  // namespace picdem::dem
