#pragma once
// Scoped phase timers (Teuchos::TimeMonitor underneath), kept out of the algorithm: construct one
// at the top of a phase function.
#include <iosfwd>
#include <map>
#include <memory>
#include <string>

#include "picdem/core/comm.hpp"

namespace picdem::core {

class ScopedTimer {
 public:
  explicit ScopedTimer(const std::string& name);
  ~ScopedTimer();
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Total seconds spent so far in every timer of this rank, by name.
std::map<std::string, double> timer_totals();
/// Resets all timers to zero.
void reset_timers();
/// Writes the Teuchos timer table (min / mean / max over ranks) on rank 0.
void summarize_timers(const Comm& comm, std::ostream& out);

}  // namespace picdem::core
