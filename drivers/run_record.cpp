#include "run_record.hpp"

#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>

#include "picdem/core/error.hpp"
#include "picdem/core/log.hpp"
#include "picdem/grid/grid.hpp"
#include "picdem/io/checkpoint_files.hpp"
#include "picdem_version.hpp"  // generated at build time (cmake/git_version.cmake)

namespace picdem::driver {
namespace fs = std::filesystem;

// Writes to two buffers: the console's and the log file's.
class LogTee::Buffer : public std::streambuf {
 public:
  Buffer(std::streambuf* console, std::streambuf* file) : console_(console), file_(file) {}

 protected:
  int overflow(int c) override {
    if (c == traits_type::eof()) return traits_type::not_eof(c);
    file_->sputc(static_cast<char>(c));
    return console_->sputc(static_cast<char>(c));
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    file_->sputn(s, n);
    return console_->sputn(s, n);
  }
  int sync() override {
    file_->pubsync();
    return console_->pubsync();
  }

 private:
  std::streambuf *console_, *file_;
};

LogTee::LogTee() = default;

LogTee::~LogTee() {
  if (cout_) std::cout.rdbuf(cout_);
  if (cerr_) std::cerr.rdbuf(cerr_);
}

void LogTee::open(const core::Comm& comm, const std::string& path, bool append) {
  std::string error;
  if (comm.is_root()) {
    std::error_code ec;
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty()) fs::create_directories(parent, ec);
    file_.open(path, append ? std::ios::app : std::ios::trunc);
    if (!file_) error = "cannot open the log file '" + path + "'";
  }
  error = comm.broadcast(error);
  if (!error.empty()) throw core::InputError(error);
  if (!comm.is_root()) return;
  out_ = std::make_unique<Buffer>(std::cout.rdbuf(), file_.rdbuf());
  err_ = std::make_unique<Buffer>(std::cerr.rdbuf(), file_.rdbuf());
  cout_ = std::cout.rdbuf(out_.get());
  cerr_ = std::cerr.rdbuf(err_.get());
}

namespace {

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

// A YAML double-quoted scalar (JSON escapes are YAML escapes).
std::string yaml_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string int_list(const std::vector<int>& v) {
  std::string out;
  for (int c : v) out += (out.empty() ? "" : ", ") + std::to_string(c);
  return "[" + out + "]";
}

// {method, ranks: [px, pz], x_cuts, z_cuts}: the cut lines are null until the simulation has
// placed them (RunRecord::split); null as a whole when the grid cannot be split (the run then
// stops with its error).
std::string planned_split(const core::Comm& comm, const core::Params& params) {
  try {
    const grid::Decomposition d(grid::spec_from(params), comm, 1,
                                static_cast<int>(params.integer("grid/ranks_x")),
                                static_cast<int>(params.integer("grid/ranks_z")));
    return "{method: " + params.string("grid/decomposition") + ", ranks: [" +
           std::to_string(d.px()) + ", " + std::to_string(d.pz()) +
           "], x_cuts: null, z_cuts: null}";
  } catch (const core::InputError&) {
    return "null";
  }
}

}  // namespace

RunRecord::RunRecord(const core::Comm& comm, int argc, char** argv)
    : comm_(comm), wall_start_(core::wall_seconds()), started_(utc_now()) {
  for (int n = 0; n < argc; ++n) command_ += (n ? " " : "") + std::string(argv[n]);
}

void RunRecord::start(const std::string& output_dir, const std::string& case_file,
                      const core::Params& params, const std::string& restart) {
  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  const auto add = [&](const std::string& key, const std::string& value) {
    head_.emplace_back(key, value);
  };
  head_.clear();
  add("version", yaml_string(PICDEM_VERSION));
  add("git_hash", yaml_string(PICDEM_GIT_HASH));
  add("code_version", yaml_string(io::code_version()));
  add("command", yaml_string(command_));
  add("case_file", yaml_string(case_file));
  add("case_name", yaml_string(params.string("case/name")));
  add("output", yaml_string(fs::absolute(output_dir).string()));
  add("restarted_from", restart.empty() ? "null" : yaml_string(restart));
  add("host", yaml_string(host));
  add("ranks", std::to_string(comm_.size()));
  add("decomposition", planned_split(comm_, params));
  method_ = params.string("grid/decomposition");
  add("started", yaml_string(started_));
  path_ = output_dir + "/run.yaml";
  std::string error;
  if (comm_.is_root()) {
    try {
      write({{"status", "running"}});
    } catch (const core::InputError& e) {
      error = e.what();
    }
  }
  error = comm_.broadcast(error);
  if (!error.empty()) throw core::InputError(error);
}

void RunRecord::split(const std::vector<int>& x_cuts, const std::vector<int>& z_cuts) {
  if (path_.empty()) return;
  for (auto& [key, value] : head_)
    if (key == "decomposition")
      value = "{method: " + method_ + ", ranks: [" + std::to_string(x_cuts.size() - 1) + ", " +
              std::to_string(z_cuts.size() - 1) + "], x_cuts: " + int_list(x_cuts) +
              ", z_cuts: " + int_list(z_cuts) + "}";
  if (!comm_.is_root()) return;
  try {
    write({{"status", "running"}});
  } catch (const core::InputError& e) {
    std::cerr << "picdem: " << e.what() << std::endl;
  }
}

void RunRecord::finish(const std::string& status, int exit_code, long long steps, double t,
                       const std::string& message) {
  if (path_.empty() || !comm_.is_root()) return;
  char wall[32];
  std::snprintf(wall, sizeof wall, "%.3f", core::wall_seconds() - wall_start_);
  try {
    write({{"finished", yaml_string(utc_now())},
           {"wall_seconds", wall},
           {"first_step", std::to_string(first_step_)},
           {"steps", std::to_string(steps)},
           {"steps_this_run", std::to_string(steps - first_step_)},
           {"time", number(t)},
           {"status", status},
           {"exit_code", std::to_string(exit_code)},
           {"message", message.empty() ? "null" : yaml_string(message)}});
  } catch (const core::InputError& e) {
    std::cerr << "picdem: " << e.what() << std::endl;
  }
}

void RunRecord::write(const std::vector<std::pair<std::string, std::string>>& end) const {
  // Through a temporary and a rename: a reader never sees half a file.
  const std::string tmp = path_ + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << "# picdem run record (doc/output.md): written at the start, rewritten at the end\n";
    for (const auto& [key, value] : head_) out << key << ": " << value << "\n";
    for (const auto& [key, value] : end) out << key << ": " << value << "\n";
    if (!out) throw core::InputError("cannot write '" + tmp + "'");
  }
  if (std::rename(tmp.c_str(), path_.c_str()) != 0)
    throw core::InputError("cannot rename '" + tmp + "' to '" + path_ + "'");
}

}  // namespace picdem::driver
