#pragma once
// The solids and obstacles as the implicit viscous operator sees them (ViscousBody: inside test,
// rigid velocity, centre, area), and the viscous loads of a step by solid id for eq. 6
// (doc/viscous.md). Over the solids' plain states and shapes: fluid does not know the DEM.
#include <cstddef>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/solid_state.hpp"
#include "picdem/fluid/viscous.hpp"
#include "picdem/geometry/cut_cells.hpp"

namespace picdem::fluid {

/// The viscous loads of a step (fluid/viscosity_scheme: implicit; doc/viscous.md), per unit
/// depth: force [N/m], torque [N m/m]; the same on every rank. Empty with the explicit scheme,
/// which does not compute them, and with zero viscosity. (The walls': FluidState.)
struct ViscousExchange {
  std::vector<core::SolidLoads> solids;     ///< every solid, index = id; torque about its centre
  std::vector<core::SolidLoads> obstacles;  ///< id = the obstacle's index; torque about (0, 0)
};

/// The solids (placements and their states, parallel; shape contains at the pose, velocity and
/// angular velocity of the state, centre of mass, area; with `rigid_rows` their mass and inertia,
/// which makes them free bodies of the implicit step), then the obstacles (even-odd point in
/// polygon, at rest).
std::vector<ViscousBody> viscous_bodies(const std::vector<geometry::SolidPlacement>& placements,
                                        const std::vector<core::SolidState>& states,
                                        const std::vector<geometry::Obstacle>& obstacles,
                                        bool rigid_rows = false);

/// Collective: the loads `loads` of the bodies of viscous_bodies (every solid of the run,
/// `solids`, ordered by id, then `obstacles` obstacles) by solid id, each solid's taken from the
/// rank that owns it (`owned`: this rank's solids) and summed over the ranks as the pressure
/// loads are; the obstacles' as computed (the same on every rank).
ViscousExchange viscous_exchange(const std::vector<core::SolidState>& solids, std::size_t obstacles,
                                 const ViscousLoads& loads,
                                 const std::vector<core::SolidState>& owned,
                                 const core::Comm& comm);

/// `loads` (owned solids, any order) plus the viscous loads of the `owned` solids: one entry per
/// solid in `loads` or owned, ordered by id.
std::vector<core::SolidLoads> plus_viscous(const std::vector<core::SolidLoads>& loads,
                                           const ViscousExchange& viscous,
                                           const std::vector<core::SolidState>& owned);

}  // namespace picdem::fluid
