#pragma once
// The one parameter schema of a picdem case, assembled from the modules' declarations (each
// declares its own keys: grid, fluid with free_surface and the time step, particles with the
// water, geometry's obstacles, dem's solids, io's output and checkpoint keys) plus the step's own
// (case/name, coupling) and the checks across modules.
#include "picdem/core/params.hpp"

namespace picdem::coupling {

/// Everything a case file may hold.
core::ParamSchema case_schema();

}  // namespace picdem::coupling
