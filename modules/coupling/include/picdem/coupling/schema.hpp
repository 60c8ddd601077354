#pragma once
// The one parameter schema of a picdem case: every module's declarations plus the run's own
// (time, output, initial water).
#include "picdem/core/params.hpp"

namespace picdem::coupling {

/// time/*, output/*, the `water` family and the cross-checks that need several modules' keys.
void declare_parameters(core::ParamSchema& schema);

/// Everything a case file may hold.
core::ParamSchema case_schema();

}  // namespace picdem::coupling
