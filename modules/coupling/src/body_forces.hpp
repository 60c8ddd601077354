#pragma once
// The pressure loads on the fixed obstacles (J p + F_q, as solid_couplings and the pressure
// solver's rows have them for the solids) and the rows of forces.csv (doc/output.md).
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/solid_state.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/coupling/solids_in_fluid.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/grid/field.hpp"
#include "viscous_bodies.hpp"

namespace picdem::coupling {

/// Collective: the pressure force -sum_c p_c int n dl + F_q on each of `count` obstacles, over the
/// boundary pieces in the owned Fluid cells, summed over the ranks; the torque about (0, 0) with
/// p_c on the whole piece plus the moment of F_q taken at the cell centre (id = the obstacle's
/// index).
std::vector<core::SolidLoads> obstacle_pressure_loads(const geometry::CutCells& cut,
                                                      const fluid::CellStates& cells,
                                                      const grid::Decomposition& d,
                                                      const grid::CellField& p,
                                                      const QuadratureOptions& quadrature,
                                                      std::size_t count, const core::Comm& comm);

/// The rows of forces.csv: every solid (pressure loads `pressure`, every solid by id; viscous
/// from `viscous`, zero when empty), then every obstacle (`obstacles`, by index).
std::vector<BodyForces> body_forces(const std::vector<core::SolidLoads>& pressure,
                                    const std::vector<core::SolidLoads>& obstacles,
                                    const ViscousExchange& viscous);

}  // namespace picdem::coupling
