#pragma once
// What the picdem executable leaves about a run besides its results (doc/output.md): picdem.log,
// everything rank 0 prints, and run.yaml, what ran where and how it ended.
#include <fstream>
#include <memory>
#include <streambuf>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"

namespace picdem::driver {

/// While alive after open(), everything rank 0 writes to std::cout and std::cerr also goes to a
/// log file, flushed with the stream (std::endl). Other ranks are untouched.
class LogTee {
 public:
  LogTee();
  ~LogTee();
  LogTee(const LogTee&) = delete;
  LogTee& operator=(const LogTee&) = delete;
  /// Collective. Creates the folder of `path`; append = true continues an existing log (a
  /// restart). Throws core::InputError on every rank when the file cannot be opened.
  void open(const core::Comm& comm, const std::string& path, bool append);

 private:
  class Buffer;
  std::ofstream file_;
  std::unique_ptr<Buffer> out_, err_;
  std::streambuf *cout_ = nullptr, *cerr_ = nullptr;
};

/// run.yaml in the output folder, written by rank 0 at start() (status running) and rewritten at
/// finish(); a run that dies without finish() leaves status running.
class RunRecord {
 public:
  /// Takes the wall clock, the date and the command line.
  RunRecord(const core::Comm& comm, int argc, char** argv);

  /// Collective. `restart`: the checkpoint continued from (empty: a fresh run).
  void start(const std::string& output_dir, const std::string& case_file,
             const core::Params& params, const std::string& restart);
  /// The cut lines the simulation uses now (strip starts along x and z, Simulation::grid_split);
  /// rank 0 rewrites run.yaml with them. Called once the simulation is built and again at the
  /// end (weighted cuts move as the flow does).
  void split(const std::vector<int>& x_cuts, const std::vector<int>& z_cuts);
  /// The step count the run starts from (after a restart: the checkpoint's).
  void first_step(long long step) { first_step_ = step; }
  /// Rank 0 rewrites run.yaml (no-op before start()). status: completed, stopped_by_signal,
  /// input_error, solver_error, crashed; `message`: the error, if any.
  void finish(const std::string& status, int exit_code, long long steps, double t,
              const std::string& message);

 private:
  void write(const std::vector<std::pair<std::string, std::string>>& end) const;

  core::Comm comm_;
  double wall_start_ = 0.0;
  std::string started_, command_, method_;
  std::string path_;  // empty before start()
  std::vector<std::pair<std::string, std::string>> head_;
  long long first_step_ = 0;
};

}  // namespace picdem::driver
