#pragma once
// The run's state <-> a checkpoint file (layout in doc/restart.md). Each module saves and
// restores its own state (particles/checkpoint.hpp, fluid/checkpoint.hpp, dem/checkpoint.hpp,
// on the same or another rank layout); this file writes the run's header (clock, diagnostics,
// output marks, case) and calls them in order. Private to the run module.
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/run/output.hpp"

namespace picdem::run {

/// The run's clock and records, stored as attributes beside the modules' arrays.
struct CheckpointHeader {
  double t = 0.0;
  long long step = 0;
  double last_dt = 0.0;  ///< the last step's dt, state of the time-step rule (time/dt_growth)
  coupling::Diagnostics diag;
  Output::Mark mark;
};

using CheckpointParts = coupling::Simulation::Modules;

/// Collective: writes `head` and the parts to `path` (via path.tmp). Environment variable
/// PICDEM_CHECKPOINT_PAUSE_AT_STEP=N (tests): at step N the writer stops for 60 s in the middle of
/// the data (the particles written, the grid and the solids not yet), after printing "checkpoint
/// paused in the middle of the data" on stderr.
void write_checkpoint(const CheckpointParts& parts, const CheckpointHeader& head,
                      const std::string& path);
/// Collective: replaces the parts' state by the checkpoint's (same or another rank count) and
/// returns its header. Throws core::InputError for a missing, truncated, corrupted or mismatched
/// file (format version, case).
CheckpointHeader read_checkpoint(const CheckpointParts& parts, const std::string& path);

}  // namespace picdem::run
