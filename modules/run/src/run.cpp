#include "picdem/run/run.hpp"

#include <cstdio>

#include "checkpoint_state.hpp"

#include "picdem/core/log.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/coupling/schema.hpp"
#include "picdem/io/checkpoint_grid.hpp"
#include "picdem/run/check_step.hpp"
#include "picdem/run/output.hpp"

namespace picdem::run {

core::ParamSchema case_schema() {
  core::ParamSchema schema = coupling::case_schema();
  schema.section("run", "Checks made before the run (doc/parameters.md).");
  schema
      .real("run/memory_limit_gb", 0.0,
            "memory a rank may use [GB]; a case whose estimate exceeds it is refused "
            "(0: MemTotal of /proc/meminfo divided by the ranks on the node)")
      .non_negative();
  return schema;
}

Run::Run(coupling::Simulation& sim) : sim_(sim) {}

Run::~Run() = default;

void Run::open_output(const std::string& directory) {
  const auto m = sim_.modules();
  output_ = std::make_unique<Output>(m.comm, m.params, m.decomposition, directory);
}

void Run::restart_from(const std::string& checkpoint, const std::string& output_dir) {
  const core::Comm& comm = sim_.modules().comm;
  const bool adopted = sim_.take_cuts_of(io::checkpoint_cell_boxes(comm, checkpoint));
  const CheckpointHeader head = read_checkpoint(sim_.modules(), checkpoint);
  sim_.resume(head.t, head.step, head.last_dt, head.diag);
  if (!adopted) sim_.rebalance();
  restarted_ = true;
  output_.reset();
  const auto m = sim_.modules();
  if (!output_dir.empty())
    output_ =
        std::make_unique<Output>(m.comm, m.params, m.decomposition, output_dir, &head.mark, head.t);
  core::log(comm, "picdem: restarted from " + checkpoint + " at step " +
                      std::to_string(sim_.step_count()) + ", t = " + std::to_string(sim_.time()) +
                      " s");
}

void Run::enable_checkpoints(const std::string& directory) {
  const auto m = sim_.modules();
  checkpoint_ = io::checkpoint_config_from(m.params, "");
  checkpoint_.directory = directory;
  if (!directory.empty()) io::open_checkpoint_directory(m.comm, directory, !restarted_);
}

void Run::write_checkpoint(const std::string& path) const {
  const CheckpointHeader head{sim_.time(), sim_.step_count(), sim_.last_time_step(),
                              sim_.diagnostics(), output_ ? output_->mark() : Output::Mark{}};
  run::write_checkpoint(sim_.modules(), head, path);
}

void Run::checkpoint_now() {
  write_checkpoint(checkpoint_.directory + "/" + io::checkpoint_file_name(sim_.step_count()));
  sim_.choose_pressure_rows_again();  // a run restarted here chooses them anew too
  io::prune_checkpoints(sim_.modules().comm, checkpoint_.directory, checkpoint_.keep);
}

void Run::run(long long max_steps) {
  const auto m = sim_.modules();
  const core::Comm& comm = m.comm;
  const double t_end = m.params.real("time/end"), h = m.decomposition.spec().h;
  const bool grid_speed = m.params.string("time/cfl_speed") == "grid";  // the CFL speed's source
  // A job script that always passes --restart latest meets its own finished run: said, not run.
  if (restarted_ && sim_.time() >= t_end * (1.0 - 1e-12)) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "picdem: the checkpoint is at t = %.6g s (step %lld), at or past time/end = "
                  "%.6g s: no step to run; --set time/end=T with T > %.6g continues it",
                  sim_.time(), sim_.step_count(), t_end, sim_.time());
    core::log(comm, text);
    if (output_) output_->finish(sim_);
    return;
  }
  core::Progress progress(comm, sim_.time(), t_end, m.params.real("output/progress_seconds"));
  if (output_ && !restarted_) output_->frame(sim_, true);
  const io::CheckpointConfig& ck = checkpoint_;
  double wall_last_checkpoint = core::wall_seconds();
  long long last_checkpoint_step = restarted_ ? sim_.step_count() : -1;
  stopped_by_signal_ = false;
  while (sim_.time() < t_end * (1.0 - 1e-12) && (max_steps <= 0 || sim_.step_count() < max_steps)) {
    {
      core::ScopedTimer timer("step");  // the whole step: its phases and what lies between them
      sim_.step();
    }
    const coupling::Diagnostics& diag = sim_.diagnostics();
    try {
      check_step(diag, h, sim_.has_fluid(), grid_speed, sim_.dem(), comm);
    } catch (const core::SolverError&) {
      // Every rank throws (check_step decides on reduced figures): the blown-up step's state is
      // written as the last frame and row, so that the user sees where it went wrong.
      if (output_) {
        output_->record(diag);
        output_->frame(sim_, true);
      }
      throw;
    }
    if (output_) {
      output_->record(diag);
      if (output_->forces_due(sim_.time())) output_->forces(sim_.time(), body_forces(sim_));
      output_->frame(sim_, false);
    }
    progress.report(sim_.time(), sim_.step_count(), diag.dt, diag.ppe_iterations);
    const bool stop = comm.any(io::stop_signal_received());
    if (!ck.directory.empty()) {
      const bool by_steps = ck.every_steps > 0 && sim_.step_count() % ck.every_steps == 0;
      const bool by_time =
          ck.every_seconds > 0.0 &&
          comm.max(core::wall_seconds() - wall_last_checkpoint) >= ck.every_seconds;
      if (stop || by_steps || by_time) {
        checkpoint_now();
        wall_last_checkpoint = core::wall_seconds();
        last_checkpoint_step = sim_.step_count();
      }
    }
    if (stop) {
      core::log(comm,
                "picdem: stop signal at step " + std::to_string(sim_.step_count()) +
                    (ck.directory.empty() ? ", no checkpoint directory" : ": checkpoint written") +
                    ", stopping");
      stopped_by_signal_ = true;
      return;
    }
  }
  const coupling::Diagnostics& diag = sim_.diagnostics();
  progress.report(sim_.time(), sim_.step_count(), diag.dt, diag.ppe_iterations, true);
  if (!ck.directory.empty() && ck.at_end && last_checkpoint_step != sim_.step_count())
    checkpoint_now();
  if (output_) output_->finish(sim_);
}

}  // namespace picdem::run
