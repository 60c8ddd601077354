#include "checkpoint_state.hpp"

#include "diagnostic_columns.hpp"

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <thread>

#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/dem/checkpoint.hpp"
#include "picdem/fluid/checkpoint.hpp"
#include "picdem/io/checkpoint_files.hpp"
#include "picdem/io/checkpoint_grid.hpp"
#include "picdem/particles/checkpoint.hpp"
#include "picdem/run/run.hpp"

namespace picdem::run {

// Layout (doc/restart.md); each module writes and reads its own group:
//   attributes: format_version, code_version, case_yaml, t, step, last_dt, ranks, has_fluid,
//               diagnostics (the scalars of coupling::Diagnostics in declaration order),
//               diagnostics_solids_in_box, diagnostics_levels (when there are probes),
//               output_next_frame, output_frames, output_last_frame_step
//   particles/<name>: particles/checkpoint.hpp, every rank's particles in their order
//   grid/<name>, grid/boxes: fluid/checkpoint.hpp, every rank's storage box
//   (io/checkpoint_grid.hpp) dem/<name>: dem/checkpoint.hpp, from rank 0

namespace {

// The crash test's hook: the particles are written, the grid and the solids not yet.
void pause_in_data_if_asked(const core::Comm& comm, long long step, const std::string& tmp) {
  const char* at = std::getenv("PICDEM_CHECKPOINT_PAUSE_AT_STEP");
  if (!at || std::atoll(at) != step) return;
  comm.barrier();
  if (comm.is_root())
    std::cerr << "checkpoint paused in the middle of the data: " << tmp << std::endl;
  std::this_thread::sleep_for(std::chrono::seconds(60));
}

void write_header(io::CheckpointWriter& out, const CheckpointParts& parts,
                  const CheckpointHeader& head) {
  out.attribute("format_version", io::kCheckpointFormatVersion);
  out.attribute("code_version", io::code_version());
  out.attribute("case_yaml", parts.params.to_yaml());
  out.attribute("t", head.t);
  out.attribute("step", head.step);
  out.attribute("last_dt", head.last_dt);
  out.attribute("ranks", static_cast<long long>(parts.comm.size()));
  out.attribute("has_fluid", static_cast<long long>(parts.fluid ? 1 : 0));
  out.attribute("diagnostics", diagnostic_scalars(head.diag));
  out.attribute("diagnostics_solids_in_box", head.diag.solids_in_box);
  if (!head.diag.levels.empty()) out.attribute("diagnostics_levels", head.diag.levels);
  if (!head.diag.open_volumes.empty())  // open sides (doc/open_boundaries.md)
    out.attribute("diagnostics_open_volumes", head.diag.open_volumes);
  out.attribute("output_next_frame", head.mark.next_frame);
  out.attribute("output_frames", head.mark.frames);
  out.attribute("output_last_frame_step", head.mark.last_frame_step);
}

}  // namespace

void write_checkpoint(const CheckpointParts& parts, const CheckpointHeader& head,
                      const std::string& path) {
  core::ScopedTimer timer("checkpoint: write");
  io::CheckpointWriter out(parts.comm, path);
  write_header(out, parts, head);
  particles::write_checkpoint(parts.particles, out);
  pause_in_data_if_asked(parts.comm, head.step, out.temporary_path());
  if (parts.fluid)
    fluid::write_checkpoint(*parts.fluid, parts.decomposition, out);
  else
    io::write_grid_boxes(out, nullptr);
  dem::write_checkpoint(parts.dem, out, parts.comm);
  out.commit();
}

namespace {

// The format version and the case must match; returns the clock, records and output marks.
CheckpointHeader read_header(const io::CheckpointReader& in, const CheckpointParts& parts) {
  const std::string where = "checkpoint file '" + in.path() + "'";
  if (!in.has_attribute("format_version") || !in.has_attribute("case_yaml"))
    throw core::InputError(where + " is not a picdem checkpoint (no format_version or case_yaml)");
  const long long version = in.attribute_int("format_version");
  if (version != io::kCheckpointFormatVersion)
    throw core::InputError(where + " has format version " + std::to_string(version) +
                           " (written by picdem " + in.attribute_string("code_version") +
                           "); this picdem (" + io::code_version() + ") reads version " +
                           std::to_string(io::kCheckpointFormatVersion));
  const auto diff =
      io::case_differences(in.attribute_string("case_yaml"), parts.params, run::case_schema());
  if (!diff.empty()) {
    std::string m = where + " belongs to another case; these keys differ (checkpoint -> now):";
    for (const auto& d : diff) m += "\n  " + d;
    m += "\nonly time/end, grid/ranks_x, grid/ranks_z, output/*, checkpoint/* and solver/* may "
         "change on restart";
    throw core::InputError(m);
  }
  if ((in.attribute_int("has_fluid") != 0) != (parts.fluid != nullptr))
    throw core::InputError(where + ": has_fluid disagrees with the case (corrupted)");
  CheckpointHeader head;
  io::on_all_ranks(parts.comm, [&] {
    head.t = in.attribute_double("t");
    head.step = in.attribute_int("step");
    const auto v = in.attribute_doubles("diagnostics");
    if (v.size() != diagnostic_names().size())
      throw core::InputError(where + ": attribute 'diagnostics' has " + std::to_string(v.size()) +
                             " values, expected " + std::to_string(diagnostic_names().size()));
    set_diagnostic_scalars(head.diag, v);
    // files from before time/dt_growth: the recorded dt of the last step is the same number
    head.last_dt = in.has_attribute("last_dt") ? in.attribute_double("last_dt") : head.diag.dt;
    if (in.has_attribute("diagnostics_solids_in_box"))
      head.diag.solids_in_box = in.attribute_int("diagnostics_solids_in_box");
    if (in.has_attribute("diagnostics_levels"))
      head.diag.levels = in.attribute_doubles("diagnostics_levels");
    if (in.has_attribute("diagnostics_open_volumes"))
      head.diag.open_volumes = in.attribute_doubles("diagnostics_open_volumes");
    head.mark.next_frame = in.attribute_double("output_next_frame");
    head.mark.frames = in.attribute_int("output_frames");
    head.mark.last_frame_step = in.attribute_int("output_last_frame_step");
  });
  return head;
}

}  // namespace

CheckpointHeader read_checkpoint(const CheckpointParts& parts, const std::string& path) {
  core::ScopedTimer timer("checkpoint: read");
  const io::CheckpointReader in(parts.comm, path);
  const CheckpointHeader head = read_header(in, parts);
  const io::GridLayout layout =
      io::read_grid_layout(in, parts.decomposition, parts.fluid != nullptr);
  particles::read_checkpoint(parts.particles, in, parts.decomposition, layout.same);
  if (parts.fluid) fluid::read_checkpoint(*parts.fluid, in, layout, parts.comm);
  if (parts.dem) dem::read_checkpoint(*parts.dem, in, parts.comm);
  return head;
}

}  // namespace picdem::run
