#pragma once
// The checkpoint files of a run: their keys in the case, names, the directory, the stored case
// compared with the current one, the code version, and the stop signals.
//
// A checkpoint is one parallel HDF5 file (io::CheckpointWriter: written collectively under
// NAME.tmp, renamed when complete) holding the complete state of METHOD.md section 7, the
// resolved case parameters, a format version and the code version. Its layout is in
// doc/restart.md. Files are <directory>/checkpoint_<step, 8 digits>.h5; the newest `keep` stay.
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"

namespace picdem::io {

/// Version of the file layout; a file of another version is refused with a message.
constexpr long long kCheckpointFormatVersion = 1;

/// Declares checkpoint/every_steps, checkpoint/every_seconds, checkpoint/keep,
/// checkpoint/directory, checkpoint/at_end.
void declare_checkpoint_parameters(core::ParamSchema& schema);

/// When and where checkpoints are written, read once from the validated case.
struct CheckpointConfig {
  long long every_steps = 0;   ///< 0: not by step count
  double every_seconds = 0.0;  ///< wall-clock seconds between checkpoints; 0: not by time
  int keep = 2;                ///< newest checkpoints kept in the directory
  bool at_end = true;          ///< a checkpoint when the run reaches its end
  std::string directory;       ///< resolved: checkpoint/directory or OUTPUT/checkpoints
};
/// `output_dir`: the run's output folder (the default directory is output_dir/checkpoints).
CheckpointConfig checkpoint_config_from(const core::Params& params, const std::string& output_dir);

/// "checkpoint_00000120.h5" for step 120.
std::string checkpoint_file_name(long long step);
/// The committed checkpoint of the highest step in `directory` (rank 0 looks, all ranks get it).
/// Throws core::InputError when there is none.
std::string latest_checkpoint(const core::Comm& comm, const std::string& directory);
/// Removes all but the newest `keep` committed checkpoints of `directory` (rank 0).
void prune_checkpoints(const core::Comm& comm, const std::string& directory, int keep);
/// Creates `directory`; `fresh` (a new run, not a restart): removes its old checkpoints and
/// left-over .tmp files, so `--restart latest` never picks a file of an earlier run.
void open_checkpoint_directory(const core::Comm& comm, const std::string& directory, bool fresh);

/// PROJECT_VERSION, plus `git describe` at configure time when it was available.
std::string code_version();

/// Keys allowed to differ between a checkpoint's case and the restarted case: time/end, the rank
/// layout (grid/ranks_x, grid/ranks_z), output/*, checkpoint/*, solver/*.
bool key_may_change_on_restart(const std::string& path);
/// The keys (outside key_may_change_on_restart) whose values differ between the two resolved
/// cases, each as "key: stored -> current" ("(absent)" where one side lacks it). The stored case
/// is first resolved again by `schema`, so a key declared after the checkpoint was written counts
/// as its default there (a new key's default keeps the behaviour of the code before it); when
/// that fails (a key since removed or restricted) the two are compared as written.
std::vector<std::string> case_differences(const std::string& stored_yaml,
                                          const core::Params& current,
                                          const core::ParamSchema& schema);

/// SIGTERM and SIGUSR1 set a flag instead of killing the process: the run finishes its step,
/// writes a checkpoint and exits 0 (how batch schedulers stop jobs).
void install_stop_signal_handlers();
/// True once SIGTERM or SIGUSR1 arrived on this process.
bool stop_signal_received();

}  // namespace picdem::io
