#pragma once
// What a run leaves for people: timeseries.csv every step; at every output interval a ParaView
// frame, a PNG picture and the solids' rows of solids.csv; forces.csv every step or at its own
// interval; the resolved parameters at the start.
#include <memory>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/grid/grid.hpp"
#include "picdem/run/forces.hpp"

namespace picdem::io {
class FrameWriter;
class CsvWriter;
}  // namespace picdem::io

namespace picdem::run {

class Output {
 public:
  /// Where the frames stand, kept in checkpoints.
  struct Mark {
    double next_frame = 0.0;
    long long frames = 0;
    long long last_frame_step = -1;
  };

  /// `resume` (a restart at time `resume_t`): the CSV files and the frame index are continued
  /// (rows and frames after resume_t dropped) and the frame count goes on from the mark.
  Output(core::Comm comm, const core::Params& params, const grid::Decomposition& d,
         std::string directory, const Mark* resume = nullptr, double resume_t = 0.0);
  ~Output();

  Mark mark() const { return {next_frame_, frames_, last_frame_step_}; }

  /// One row of timeseries.csv.
  void record(const coupling::Diagnostics& diag);
  /// True when forces.csv takes the rows of time t (output/forces_interval; 0: every step).
  bool forces_due(double t) const;
  /// The rows of forces.csv at time t (rank 0 writes).
  void forces(double t, const std::vector<BodyForces>& rows);
  /// Writes a frame of `sim`'s state when an output time is reached (or `force`).
  void frame(const coupling::Simulation& sim, bool force);
  /// The last state as a frame (unless the last frame holds it), the movie when output/movie
  /// asks for it, the timer table; prints where everything is.
  void finish(const coupling::Simulation& sim);

 private:
  void write_frame(const coupling::Simulation& sim);

  core::Comm comm_;
  core::Params params_;
  const grid::Decomposition& decomp_;
  std::string dir_;
  double interval_ = 0.0, next_frame_ = 0.0;
  long long frames_ = 0;
  long long last_frame_step_ = -1;
  std::unique_ptr<io::FrameWriter> frames_writer_;
  std::unique_ptr<io::CsvWriter> timeseries_, solids_, forces_;
  double forces_interval_ = 0.0, next_forces_ = 0.0;
};

}  // namespace picdem::run
