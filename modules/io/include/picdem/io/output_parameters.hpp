#pragma once
// The output/ keys of a case: what a run writes (frames, pictures, the movie, forces.csv, the
// time series' probes) and how often. Read by the run layer (run::Output) and by the step's
// diagnostics (the level probes and the solid count box of timeseries.csv).
#include "picdem/core/params.hpp"

namespace picdem::io {

/// Declares output/* and checks output/solid_count_box.
void declare_output_parameters(core::ParamSchema& schema);

}  // namespace picdem::io
