#pragma once
// Case-file keys of the DEM (section `dem`) and of the solids (family `solids`), and the plain
// structs built from them.
#include <memory>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"
#include "picdem/core/solid_state.hpp"
#include "picdem/core/vec2.hpp"
#include "picdem/geometry/shape.hpp"

namespace picdem::geometry {
struct Obstacle;
}

namespace picdem::dem {

class DemSolver;

class ContactLaw;

/// Tangential spring: the paper's one-step displacement U_eta dt_DEM (eq. 8), or the displacement
/// accumulated over the contact (Zhang et al. 2009), which is history to checkpoint.
enum class TangentialModel { OneStep, Accumulated };

/// Velocity used in the position updates of eqs. 22 and 24: the paper's U^n + U_k (the velocity at
/// the start of the fluid step), or U_{k-1} + U_k (trapezoid within each subcycle).
enum class PositionUpdate { StepStart, SubcycleStart };

struct DemConfig {
  double alpha = 0.4;      ///< damping tuning parameter (eq. 11)
  double psi = 0.3;        ///< Poisson ratio (eqs. 12-13)
  double mu = 0.3;         ///< maximum static friction coefficient (eq. 15)
  double mu_r = 0.0;       ///< rolling resistance coefficient (doc/dem.md; 0: none, the paper)
  double theta = 0.01;     ///< penetration coefficient (eq. 10)
  double gamma = 150.0;    ///< time-step coefficient (eq. 18)
  double gap_cells = 2.0;  ///< imaginary gap in cells (eq. 19: 2 h)
  TangentialModel tangential = TangentialModel::OneStep;
  PositionUpdate position_update = PositionUpdate::StepStart;
  double h = 0.0;  ///< grid cell size [m]: gap = gap_cells h (eq. 19), k_xi from eq. 10
  core::Vec2 gravity{0.0, -9.81};  ///< body force per unit mass added in eq. 21's step (1)
  double g_stiffness = 9.81;       ///< ||g|| in eq. 10 (kept when gravity is switched off)
  double skin = 0.0;  ///< neighbour-list skin [m]; 0: a fifth of the largest bounding radius
  /// The contact law (dem/contact_law, contact_law_registry.hpp); null: the paper's linear
  /// spring-dashpot of the fields above.
  std::shared_ptr<const ContactLaw> contact_law;

  double gap() const { return gap_cells * h; }
};

/// One solid of a case: its initial state (id, pose, velocities), shape, density and friction.
/// Mass and inertia in `state` are density x the shape's area / polar moment.
struct SolidSpec {
  core::SolidState state;
  geometry::ShapePtr shape;
  double density = 0.0;
  /// Friction coefficient of this solid (eq. 15; a pair takes pair_friction() of its two);
  /// negative: the case's dem/mu.
  double friction = -1.0;
};

/// Declares dem/* and the `solids` family: one variant per registered shape type
/// (geometry::shape_types()), each with the keys of its motion (density, velocity, omega).
void declare_parameters(core::ParamSchema& schema);

/// The DEM settings of a validated case; `h` is the grid cell size.
DemConfig config_from(const core::Params& params, double h);

/// The initial solids of a validated case, ids 0, 1, 2, ... in file order (a stack numbers its
/// cylinders layer by layer from the bottom, each layer from the wall outwards).
std::vector<SolidSpec> solids_from(const core::Params& params);

/// The DEM of a validated case: its settings (config_from with the grid's cell size h), the
/// tank's sides as walls, the obstacles' polygons as fixed bodies and `solids` added;
/// regions[r]: the box of space rank r owns.
std::unique_ptr<DemSolver> solver_from(const core::Params& params, core::Comm comm, double h,
                                       const core::Box2& tank, std::vector<core::Box2> regions,
                                       const std::vector<geometry::Obstacle>& obstacles,
                                       const std::vector<SolidSpec>& solids);

}  // namespace picdem::dem
