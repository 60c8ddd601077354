#pragma once
// Rank-0 messages and the progress line of long runs.
#include <chrono>
#include <string>

#include "picdem/core/comm.hpp"

namespace picdem::core {

/// Prints `message` (plus newline) on rank 0 only, to standard output.
void log(const Comm& comm, const std::string& message);
/// Prints `message` on rank 0 to standard error.
void log_error(const Comm& comm, const std::string& message);

/// Wall-clock seconds since an arbitrary fixed origin.
double wall_seconds();

/// "1h02m", "3m05s", "12s".
std::string format_duration(double seconds);

/// A progress line on rank 0 with simulated time, step, dt, solver iterations and ETA, printed at
/// most every `interval` wall seconds (and always on the first and last call, the last unless it
/// repeats the line just printed). The share done is capped at 100%: the last step may end past
/// time/end (it is not shortened).
class Progress {
 public:
  Progress(Comm comm, double t_start, double t_end, double interval_seconds);
  void report(double t, long long step, double dt, int solver_iterations, bool force = false);

 private:
  Comm comm_;
  double t_start_, t_end_, interval_;
  double wall_start_, wall_last_ = -1e300;
  long long last_step_ = -1;  ///< the step of the last line printed
};

}  // namespace picdem::core
