#pragma once
// The run of a case around the coupled step (coupling::Simulation): the time loop to time/end,
// what the run leaves for people (output.hpp: time series, frames, pictures), checkpoints (the
// schedule, restart, stop signals: doc/restart.md) and the check that stops a blown-up run.
#include <memory>
#include <string>

#include "picdem/coupling/simulation.hpp"
#include "picdem/io/checkpoint_files.hpp"

namespace picdem::run {

/// The schema of a case file as `picdem` reads it: the coupled simulation's keys
/// (coupling::case_schema) and the run section (run/memory_limit_gb, read by the checks before
/// the run). A checkpoint's case is resolved again with this same schema on restart.
core::ParamSchema case_schema();

class Output;

class Run {
 public:
  /// Drives `sim`, which must outlive the Run. No files until open_output or restart_from.
  explicit Run(coupling::Simulation& sim);
  ~Run();
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;

  /// A fresh run's output in `directory` (doc/output.md); the CSV files are started anew.
  void open_output(const std::string& directory);
  /// Collective: continues the simulation from a checkpoint file; `output_dir` non-empty: the
  /// output there is continued. Throws core::InputError for a bad or mismatched file.
  void restart_from(const std::string& checkpoint, const std::string& output_dir);
  /// run() writes checkpoints to `directory` (checkpoint/every_steps, every_seconds, at_end, and
  /// on SIGTERM / SIGUSR1, after which run() returns early); a fresh run first removes the old
  /// checkpoints there. Empty: none.
  void enable_checkpoints(const std::string& directory);
  /// Collective: writes a checkpoint of the current state as `path`.
  void write_checkpoint(const std::string& path) const;

  /// Runs to time/end (or `max_steps` steps if > 0), writing output on the way.
  void run(long long max_steps = 0);
  /// True when the last run() stopped early on a stop signal.
  bool stopped_by_signal() const { return stopped_by_signal_; }

 private:
  void checkpoint_now();

  coupling::Simulation& sim_;
  std::unique_ptr<Output> output_;
  io::CheckpointConfig checkpoint_;  // directory empty: no checkpoints
  bool restarted_ = false;           // the state came from a checkpoint (no initial frame)
  bool stopped_by_signal_ = false;
};

}  // namespace picdem::run
