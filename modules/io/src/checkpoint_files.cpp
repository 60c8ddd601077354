#include "picdem/io/checkpoint_files.hpp"

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/core/log.hpp"
#include "picdem_version.hpp"  // generated at build time (cmake/git_version.cmake)

#ifndef PICDEM_CODE_VERSION
#define PICDEM_CODE_VERSION "unknown"
#endif

namespace picdem::io {

namespace fs = std::filesystem;

void declare_checkpoint_parameters(core::ParamSchema& s) {
  s.section("checkpoint", "Checkpoints for restart (doc/restart.md).");
  s.integer("checkpoint/every_steps", 0, "steps between checkpoints; 0: not by step count")
      .non_negative();
  s.real("checkpoint/every_seconds", 0.0, "wall-clock seconds between checkpoints; 0: not by time")
      .non_negative();
  s.integer("checkpoint/keep", 2, "newest checkpoints kept; older ones are removed")
      .at_least(1)
      .at_most(1000);
  s.boolean("checkpoint/at_end", true, "write a checkpoint when the run reaches its end");
  s.string("checkpoint/directory", "", {},
           "folder of the checkpoint files; empty: OUTPUT/checkpoints");
}

CheckpointConfig checkpoint_config_from(const core::Params& p, const std::string& output_dir) {
  CheckpointConfig c;
  c.every_steps = p.integer("checkpoint/every_steps");
  c.every_seconds = p.real("checkpoint/every_seconds");
  c.keep = static_cast<int>(p.integer("checkpoint/keep"));
  c.at_end = p.boolean("checkpoint/at_end");
  c.directory = p.string("checkpoint/directory");
  if (c.directory.empty() && !output_dir.empty()) c.directory = output_dir + "/checkpoints";
  return c;
}

// ---------------------------------------------------------------------------------------------
// Files of a checkpoint directory.

std::string checkpoint_file_name(long long step) {
  char name[64];
  std::snprintf(name, sizeof name, "checkpoint_%08lld.h5", step);
  return name;
}

namespace {

// The committed checkpoints of `directory` by step (a .tmp never counts).
std::map<long long, fs::path> committed_checkpoints(const std::string& directory) {
  std::map<long long, fs::path> out;
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) return out;
  for (const auto& e : fs::directory_iterator(directory, ec)) {
    const std::string name = e.path().filename().string();
    long long step = -1;
    char tail[8] = {0};
    if (std::sscanf(name.c_str(), "checkpoint_%lld.%7s", &step, tail) == 2 &&
        std::string(tail) == "h5" && name == checkpoint_file_name(step))
      out[step] = e.path();
  }
  return out;
}

}  // namespace

std::string latest_checkpoint(const core::Comm& comm, const std::string& directory) {
  std::string found;
  if (comm.is_root()) {
    const auto all = committed_checkpoints(directory);
    if (!all.empty()) found = all.rbegin()->second.string();
  }
  found = comm.broadcast(found);
  if (found.empty())
    throw core::InputError("--restart latest: no checkpoint (checkpoint_*.h5) in '" + directory +
                           "'");
  return found;
}

void prune_checkpoints(const core::Comm& comm, const std::string& directory, int keep) {
  if (comm.is_root()) {
    const auto all = committed_checkpoints(directory);
    int n = static_cast<int>(all.size());
    for (auto it = all.begin(); it != all.end() && n > keep; ++it, --n) {
      std::error_code ec;
      fs::remove(it->second, ec);
    }
  }
  comm.barrier();
}

void open_checkpoint_directory(const core::Comm& comm, const std::string& directory, bool fresh) {
  std::string error;
  if (comm.is_root()) {
    std::error_code ec;
    fs::create_directories(directory, ec);
    if (!fs::is_directory(directory))
      error = "cannot create the checkpoint directory '" + directory + "'";
    for (const auto& e : fs::directory_iterator(directory, ec)) {
      const std::string name = e.path().filename().string();
      if (fresh && name.rfind("checkpoint_", 0) == 0 &&
          (name.size() > 3 &&
           (name.substr(name.size() - 3) == ".h5" || name.substr(name.size() - 4) == ".tmp")))
        fs::remove(e.path(), ec);
    }
  }
  error = comm.broadcast(error);
  if (!error.empty()) throw core::InputError(error);
}

std::string code_version() {
  return PICDEM_CODE_VERSION;
}

// ---------------------------------------------------------------------------------------------
// Comparing the stored case with the current one.

bool key_may_change_on_restart(const std::string& path) {
  auto under = [&](const std::string& section) { return path.rfind(section + "/", 0) == 0; };
  return path == "time/end" || path == "grid/ranks_x" || path == "grid/ranks_z" ||
         under("output") || under("checkpoint") || under("solver");
}

namespace {

// The resolved case as "section/key" -> value text, read from the YAML that Params::to_yaml()
// writes (Teuchos' writer: one key per line, two spaces per level, sublists as "name: " lines,
// arrays inline). Reading the text, not parsing it, keeps values that Teuchos' own reader refuses
// (empty arrays) comparable; both sides come from the same writer, so equal values print equally.
std::map<std::string, std::string> flat_case(const std::string& yaml, const std::string& source) {
  std::map<std::string, std::string> out;
  std::vector<std::pair<std::size_t, std::string>> open;  // indentation, sublist name
  std::istringstream in(yaml);
  std::string line;
  bool root = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::size_t indent = line.find_first_not_of(' ');
    if (indent == std::string::npos || line[indent] == '%' || line.compare(indent, 3, "---") == 0 ||
        line.compare(indent, 3, "...") == 0)
      continue;
    // the key: up to the first ':' outside quotes that ends the line or precedes a space
    std::size_t colon = std::string::npos;
    char quote = 0;
    for (std::size_t c = indent; c < line.size() && colon == std::string::npos; ++c) {
      if (quote) {
        if (line[c] == quote) quote = 0;
      } else if (line[c] == '\'' || line[c] == '"') {
        quote = line[c];
      } else if (line[c] == ':' && (c + 1 == line.size() || line[c + 1] == ' ')) {
        colon = c;
      }
    }
    if (colon == std::string::npos)
      throw core::InputError(source + " is not a resolved case (corrupted): line '" + line + "'");
    const std::string key = line.substr(indent, colon - indent);
    std::string value = line.substr(colon + 1);
    value.erase(0, std::min(value.find_first_not_of(' '), value.size()));
    while (!open.empty() && open.back().first >= indent) open.pop_back();
    if (!root) {  // the writer's top level: the list's own name
      root = true;
      open.emplace_back(indent, "");
      continue;
    }
    std::string path;
    for (std::size_t n = 1; n < open.size(); ++n) path += open[n].second + "/";
    if (value.empty())
      open.emplace_back(indent, key);
    else
      out[path + key] = value;
  }
  if (out.empty()) throw core::InputError(source + " holds no parameters (corrupted)");
  return out;
}

// A written case resolved through `schema` (defaults filled in, values in the schema's spelling),
// or as written when it no longer resolves: the differences then name the keys this picdem does
// not accept.
std::string resolved_or_as_written(const std::string& yaml, const std::string& source,
                                   const core::ParamSchema& schema) {
  try {
    return core::resolve_written_case(yaml, source, schema).to_yaml();
  } catch (const core::InputError&) {
    return yaml;
  }
}

}  // namespace

std::vector<std::string> case_differences(const std::string& stored_yaml,
                                          const core::Params& current,
                                          const core::ParamSchema& schema) {
  // The current case goes through the same schema: a section the caller's Params lack (built with
  // fewer keys than `schema`, e.g. coupling's schema without the run section) takes its defaults,
  // as the stored case's missing keys do.
  const std::string stored = resolved_or_as_written(stored_yaml, "the checkpoint's case", schema);
  const std::string now = resolved_or_as_written(current.to_yaml(), "the current case", schema);
  const auto a = flat_case(stored, "the checkpoint's case");
  const auto b = flat_case(now, "the current case");
  std::vector<std::string> diff;
  auto note = [&](const std::string& key, const std::string& x, const std::string& y) {
    if (!key_may_change_on_restart(key)) diff.push_back(key + ": " + x + " -> " + y);
  };
  for (const auto& [key, value] : a) {
    const auto it = b.find(key);
    if (it == b.end())
      note(key, value, "(absent)");
    else if (it->second != value)
      note(key, value, it->second);
  }
  for (const auto& [key, value] : b)
    if (!a.count(key)) note(key, "(absent)", value);
  return diff;
}

// ---------------------------------------------------------------------------------------------
// Stop signals.

namespace {
volatile std::sig_atomic_t stop_flag = 0;
extern "C" void on_stop_signal(int) {
  stop_flag = 1;
}
}  // namespace

void install_stop_signal_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGUSR1, &sa, nullptr);
}

bool stop_signal_received() {
  return stop_flag != 0;
}

}  // namespace picdem::io
