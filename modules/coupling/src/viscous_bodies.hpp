#pragma once
// The solids and obstacles of a scene as the implicit viscous operator sees them
// (fluid::ViscousBody: inside test, rigid velocity, centre, area), and the viscous loads of a
// step by solid id for eq. 6 (doc/viscous.md).
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/solid_state.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/coupling/solids_in_fluid.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/fluid/viscous.hpp"

namespace picdem::coupling {

/// The viscous loads of a step (fluid/viscosity_scheme: implicit; doc/viscous.md), per unit
/// depth: force [N/m], torque [N m/m]; the same on every rank. Empty with the explicit scheme,
/// which does not compute them, and with zero viscosity. (The walls': FluidState.)
struct ViscousExchange {
  std::vector<core::SolidLoads> solids;     ///< every solid, index = id; torque about its centre
  std::vector<core::SolidLoads> obstacles;  ///< id = the obstacle's index; torque about (0, 0)
};

/// The scene's solids (shape contains at the pose, velocity and angular velocity of their
/// state, centre of mass, area; with `rigid_rows` their mass and inertia, which makes them free
/// bodies of the implicit step), then its obstacles (even-odd point in polygon, at rest).
std::vector<fluid::ViscousBody> viscous_bodies(const SolidScene& scene, bool rigid_rows = false);

/// Collective: every solid of the run (gathered from their owners, ordered by id) and the
/// obstacles: the scene of the replicated implicit viscous solve, in which every rank solves
/// the whole grid and so must see every solid.
SolidScene scene_of_all(const dem::DemSolver* dem,
                        const std::vector<geometry::Obstacle>& obstacles);

/// Collective: the loads `loads` of the bodies of viscous_bodies(scene) (scene: scene_of_all)
/// by solid id, each solid's taken from the rank that owns it and summed over the ranks as the
/// pressure loads are; the obstacles' as computed (the same on every rank).
ViscousExchange viscous_exchange(const SolidScene& scene, const fluid::ViscousLoads& loads,
                                 const dem::DemSolver* dem, const core::Comm& comm);

/// `loads` (owned solids, any order) plus the viscous loads of the owned solids of `dem`: one
/// entry per solid in `loads` or owned, ordered by id.
std::vector<core::SolidLoads> plus_viscous(const std::vector<core::SolidLoads>& loads,
                                           const ViscousExchange& viscous,
                                           const dem::DemSolver& dem);

}  // namespace picdem::coupling
