#include "picdem/coupling/checkpoint.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include "picdem/core/error.hpp"
#include "picdem/core/log.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/io/checkpoint.hpp"
#include "picdem/particles/particles.hpp"
#include "simulation_state.hpp"

#ifndef PICDEM_CODE_VERSION
#define PICDEM_CODE_VERSION "unknown"
#endif

namespace picdem::coupling {

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

}  // namespace

std::vector<std::string> case_differences(const std::string& stored_yaml,
                                          const core::Params& current) {
  const auto a = flat_case(stored_yaml, "the checkpoint's case");
  const auto b = flat_case(current.to_yaml(), "the current case");
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

// ---------------------------------------------------------------------------------------------
// The state <-> the file. Layout (doc/restart.md):
//   attributes: format_version, code_version, case_yaml, t, step, ranks, has_fluid,
//               diagnostics (the scalars of Diagnostics in declaration order),
//               diagnostics_solids_in_box, diagnostics_levels (when there are probes),
//               output_next_frame, output_frames, output_last_frame_step
//   particles/{x,z,u,w,cxx,cxz,czx,czz} (double), particles/id (int64): every rank's particles
//               in their order
//   grid/{u,w,p} (double), grid/cells (int): every rank's storage box (owned + halo), row-major
//   grid/boxes (int): per rank 24 numbers: for u, w, p in turn the storage box and the owned box
//               as i0, i1, k0, k1
//   dem/{id,x,z,theta,u,w,omega,spring_solid,spring_partner,spring}: DemSolver::Snapshot, from
//               rank 0

namespace {

Diagnostics diagnostics_from(const std::vector<double>& v, const std::string& path) {
  if (v.size() != Diagnostics::scalar_names().size())
    throw core::InputError("checkpoint file '" + path + "': attribute 'diagnostics' has " +
                           std::to_string(v.size()) + " values, expected " +
                           std::to_string(Diagnostics::scalar_names().size()));
  Diagnostics g;
  g.set_scalars(v);
  return g;
}

void push_box(std::vector<int>& out, const core::IndexBox& b) {
  out.insert(out.end(), {b.i0, b.i1, b.k0, b.k1});
}

core::IndexBox box_at(const std::vector<int>& v, std::size_t at) {
  return {v[at], v[at + 1], v[at + 2], v[at + 3]};
}

void pause_before_commit_if_asked(const core::Comm& comm, long long step, const std::string& tmp) {
  const char* at = std::getenv("PICDEM_CHECKPOINT_PAUSE_AT_STEP");
  if (!at || std::atoll(at) != step) return;
  comm.barrier();
  if (comm.is_root()) std::cerr << "checkpoint paused before commit: " << tmp << std::endl;
  std::this_thread::sleep_for(std::chrono::seconds(60));
}

}  // namespace

void write_checkpoint(const SimulationState& s, const std::string& path, const Output::Mark& mark) {
  core::ScopedTimer timer("checkpoint: write");
  io::CheckpointWriter out(s.comm, path);
  out.attribute("format_version", kCheckpointFormatVersion);
  out.attribute("code_version", code_version());
  out.attribute("case_yaml", s.params.to_yaml());
  out.attribute("t", s.t);
  out.attribute("step", s.step);
  out.attribute("ranks", static_cast<long long>(s.comm.size()));
  out.attribute("has_fluid", static_cast<long long>(s.has_fluid ? 1 : 0));
  out.attribute("diagnostics", s.diag.scalars());
  out.attribute("diagnostics_solids_in_box", s.diag.solids_in_box);
  if (!s.diag.levels.empty()) out.attribute("diagnostics_levels", s.diag.levels);
  out.attribute("output_next_frame", mark.next_frame);
  out.attribute("output_frames", mark.frames);
  out.attribute("output_last_frame_step", mark.last_frame_step);

  const auto& P = s.particles;
  out.write("particles/x", P.x);
  out.write("particles/z", P.z);
  out.write("particles/u", P.u);
  out.write("particles/w", P.w);
  out.write("particles/cxx", P.cxx);
  out.write("particles/cxz", P.cxz);
  out.write("particles/czx", P.czx);
  out.write("particles/czz", P.czz);
  out.write("particles/id", P.id);

  std::vector<int> boxes;
  if (s.has_fluid) {
    for (const auto* f : {&s.u, &s.w, &s.p})
      push_box(boxes, f->storage()), push_box(boxes, f->owned());
    std::vector<int> cells(s.cells.data().begin(), s.cells.data().end());
    out.write("grid/u", s.u.data());
    out.write("grid/w", s.w.data());
    out.write("grid/p", s.p.data());
    out.write("grid/cells", cells);
  }
  out.write("grid/boxes", boxes);

  dem::DemSolver::Snapshot snap;
  if (s.dem) snap = s.dem->snapshot();
  const bool root = s.comm.is_root();
  auto mine = [&](const auto& v) { return root ? v : std::decay_t<decltype(v)>{}; };
  out.write("dem/id", mine(snap.id));
  out.write("dem/x", mine(snap.x));
  out.write("dem/z", mine(snap.z));
  out.write("dem/theta", mine(snap.theta));
  out.write("dem/u", mine(snap.u));
  out.write("dem/w", mine(snap.w));
  out.write("dem/omega", mine(snap.omega));
  out.write("dem/spring_solid", mine(snap.spring_solid));
  out.write("dem/spring_partner", mine(snap.spring_partner));
  out.write("dem/spring", mine(snap.spring));

  pause_before_commit_if_asked(s.comm, s.step, out.temporary_path());
  out.commit();
}

namespace {

// A failure seen by some ranks only (each reads its own ranges) becomes the same InputError on
// every rank, so a bad file never leaves ranks waiting for each other.
template <class F>
void on_all_ranks(const core::Comm& comm, F&& read) {
  std::string error;
  try {
    read();
  } catch (const core::InputError& e) {
    error = e.what();
  }
  const long long bad = comm.max(error.empty() ? -1LL : static_cast<long long>(comm.rank()));
  if (bad >= 0) throw core::InputError(comm.broadcast(error, static_cast<int>(bad)));
}

// Restores a grid array written on another decomposition: the global array is put together from
// every writer's owned values (halo values only where no writer owns the sample: ghosts outside
// the tank), and this rank takes its storage box from it.
template <class T, class Read>
void restore_grid(const io::CheckpointReader& in, const std::string& name,
                  const std::vector<int>& boxes, int which, grid::GridArray<T>& f,
                  Read read_range) {
  const auto lengths = in.slice_lengths(name);
  const int writers = static_cast<int>(lengths.size());
  if (boxes.size() != static_cast<std::size_t>(24 * writers))
    throw core::InputError("checkpoint file '" + in.path() + "': grid/boxes has " +
                           std::to_string(boxes.size()) + " numbers, expected " +
                           std::to_string(24 * writers) + " (corrupted)");
  std::vector<long long> offsets(writers + 1, 0);
  for (int r = 0; r < writers; ++r) offsets[r + 1] = offsets[r] + lengths[r];
  // Union of the writers' storage boxes.
  core::IndexBox all = box_at(boxes, 24 * 0 + 8 * which);
  for (int r = 0; r < writers; ++r) {
    const auto b = box_at(boxes, 24 * r + 8 * which);
    all = {std::min(all.i0, b.i0), std::max(all.i1, b.i1), std::min(all.k0, b.k0),
           std::max(all.k1, b.k1)};
  }
  const auto nx = static_cast<std::size_t>(all.nx());
  auto at = [&](int i, int k) {
    return static_cast<std::size_t>(k - all.k0) * nx + static_cast<std::size_t>(i - all.i0);
  };
  std::vector<T> global(static_cast<std::size_t>(all.size()), T{});
  std::vector<char> level(global.size(), 0);  // 1: a ghost value, 2: the owner's value
  const core::IndexBox want = f.storage();
  for (int r = 0; r < writers; ++r) {
    const auto stor = box_at(boxes, 24 * r + 8 * which);
    const auto own = box_at(boxes, 24 * r + 8 * which + 4);
    if (stor.size() != lengths[r])
      throw core::InputError("checkpoint file '" + in.path() + "': " + name + " slice " +
                             std::to_string(r) + " does not match its box (corrupted)");
    if (want.intersect(stor).empty()) continue;
    const auto v = read_range(name, offsets[r], offsets[r + 1]);
    for (int k = stor.k0; k < stor.k1; ++k)
      for (int i = stor.i0; i < stor.i1; ++i) {
        const char lv = own.contains(i, k) ? 2 : 1;
        const std::size_t g = at(i, k);
        if (lv > level[g]) {
          global[g] = static_cast<T>(
              v[static_cast<std::size_t>(k - stor.k0) * static_cast<std::size_t>(stor.nx()) +
                static_cast<std::size_t>(i - stor.i0)]);
          level[g] = lv;
        }
      }
  }
  for (int k = want.k0; k < want.k1; ++k)
    for (int i = want.i0; i < want.i1; ++i) f(i, k) = all.contains(i, k) ? global[at(i, k)] : T{};
}

}  // namespace

Output::Mark read_checkpoint(SimulationState& s, const std::string& path) {
  core::ScopedTimer timer("checkpoint: read");
  const core::Comm& comm = s.comm;
  const io::CheckpointReader in(comm, path);
  const std::string where = "checkpoint file '" + path + "'";
  if (!in.has_attribute("format_version") || !in.has_attribute("case_yaml"))
    throw core::InputError(where + " is not a picdem checkpoint (no format_version or case_yaml)");
  const long long version = in.attribute_int("format_version");
  if (version != kCheckpointFormatVersion)
    throw core::InputError(where + " has format version " + std::to_string(version) +
                           " (written by picdem " + in.attribute_string("code_version") +
                           "); this picdem (" + code_version() + ") reads version " +
                           std::to_string(kCheckpointFormatVersion));
  const auto diff = case_differences(in.attribute_string("case_yaml"), s.params);
  if (!diff.empty()) {
    std::string m = where + " belongs to another case; these keys differ (checkpoint -> now):";
    for (const auto& d : diff) m += "\n  " + d;
    m += "\nonly time/end, grid/ranks_x, grid/ranks_z, output/*, checkpoint/* and solver/* may "
         "change on restart";
    throw core::InputError(m);
  }
  if ((in.attribute_int("has_fluid") != 0) != s.has_fluid)
    throw core::InputError(where + ": has_fluid disagrees with the case (corrupted)");

  Output::Mark mark;
  on_all_ranks(comm, [&] {
    s.t = in.attribute_double("t");
    s.step = in.attribute_int("step");
    s.diag = diagnostics_from(in.attribute_doubles("diagnostics"), path);
    if (in.has_attribute("diagnostics_solids_in_box"))
      s.diag.solids_in_box = in.attribute_int("diagnostics_solids_in_box");
    if (in.has_attribute("diagnostics_levels"))
      s.diag.levels = in.attribute_doubles("diagnostics_levels");
    mark.next_frame = in.attribute_double("output_next_frame");
    mark.frames = in.attribute_int("output_frames");
    mark.last_frame_step = in.attribute_int("output_last_frame_step");
  });

  // Same layout: the same rank count and every rank's boxes as written (the decomposition depends
  // on the rank count and grid/ranks_x, grid/ranks_z). Then each rank takes its own slices back
  // unchanged (bitwise); otherwise particles go by even shares to their owners and the grid
  // arrays are put together again.
  std::vector<int> boxes_all;
  bool mine_same = in.written_ranks() == comm.size();
  on_all_ranks(comm, [&] {
    if (!s.has_fluid) return;
    boxes_all = in.read_range_int("grid/boxes", 0, in.length("grid/boxes"));
    if (boxes_all.size() != 24u * static_cast<std::size_t>(in.written_ranks()))
      throw core::InputError(where + ": grid/boxes has " + std::to_string(boxes_all.size()) +
                             " numbers for " + std::to_string(in.written_ranks()) +
                             " ranks (corrupted)");
    if (!mine_same) return;
    std::vector<int> mine;
    for (const auto* f : {&s.u, &s.w, &s.p})
      push_box(mine, f->storage()), push_box(mine, f->owned());
    mine_same = std::equal(mine.begin(), mine.end(), boxes_all.begin() + 24 * comm.rank());
  });
  const bool same_layout = !comm.any(!mine_same);

  on_all_ranks(comm, [&] {
    long long begin = 0, end = 0;
    if (!same_layout)
      io::even_split(in.length("particles/x"), comm.rank(), comm.size(), begin, end);
    auto reals = [&](const std::string& name) {
      return same_layout ? in.read_slice_double(name) : in.read_range_double(name, begin, end);
    };
    auto& P = s.particles;
    P.x = reals("particles/x");
    P.z = reals("particles/z");
    P.u = reals("particles/u");
    P.w = reals("particles/w");
    P.cxx = reals("particles/cxx");
    P.cxz = reals("particles/cxz");
    P.czx = reals("particles/czx");
    P.czz = reals("particles/czz");
    P.id = same_layout ? in.read_slice_int64("particles/id")
                       : in.read_range_int64("particles/id", begin, end);
    const std::size_t n = P.x.size();
    for (const auto* v : {&P.z, &P.u, &P.w, &P.cxx, &P.cxz, &P.czx, &P.czz})
      if (v->size() != n)
        throw core::InputError(where + ": the particle arrays differ in length (corrupted)");
    if (P.id.size() != n)
      throw core::InputError(where + ": the particle arrays differ in length (corrupted)");
    P.spec = s.spec;
    if (!s.has_fluid) return;
    if (same_layout) {
      auto exact = [&](const std::string& name, std::vector<double>& dst) {
        auto v = in.read_slice_double(name);
        if (v.size() != dst.size())
          throw core::InputError(where + ": " + name + " does not match the grid (corrupted)");
        dst = std::move(v);
      };
      exact("grid/u", s.u.data());
      exact("grid/w", s.w.data());
      exact("grid/p", s.p.data());
      const auto cells = in.read_slice_int("grid/cells");
      if (cells.size() != s.cells.data().size())
        throw core::InputError(where + ": grid/cells does not match the grid (corrupted)");
      std::copy(cells.begin(), cells.end(), s.cells.data().begin());
    } else {
      auto real_range = [&](const std::string& name, long long b, long long e) {
        return in.read_range_double(name, b, e);
      };
      auto int_range = [&](const std::string& name, long long b, long long e) {
        return in.read_range_int(name, b, e);
      };
      restore_grid(in, "grid/u", boxes_all, 0, s.u, real_range);
      restore_grid(in, "grid/w", boxes_all, 1, s.w, real_range);
      restore_grid(in, "grid/p", boxes_all, 2, s.p, real_range);
      restore_grid(in, "grid/cells", boxes_all, 2, s.cells, int_range);
    }
  });
  if (!same_layout && s.has_fluid) particles::migrate(s.particles, *s.decomp);

  if (s.dem) {
    dem::DemSolver::Snapshot snap;
    on_all_ranks(comm, [&] {
      auto all_d = [&](const std::string& name) {
        return in.read_range_double(name, 0, in.length(name));
      };
      auto all_i = [&](const std::string& name) {
        return in.read_range_int64(name, 0, in.length(name));
      };
      snap.id = all_i("dem/id");
      snap.x = all_d("dem/x");
      snap.z = all_d("dem/z");
      snap.theta = all_d("dem/theta");
      snap.u = all_d("dem/u");
      snap.w = all_d("dem/w");
      snap.omega = all_d("dem/omega");
      snap.spring_solid = all_i("dem/spring_solid");
      snap.spring_partner = all_i("dem/spring_partner");
      snap.spring = all_d("dem/spring");
      const std::size_t n = snap.id.size();
      for (const auto* v : {&snap.x, &snap.z, &snap.theta, &snap.u, &snap.w, &snap.omega})
        if (v->size() != n)
          throw core::InputError(where + ": the solid arrays differ in length (corrupted)");
      if (snap.spring_partner.size() != snap.spring_solid.size() ||
          snap.spring.size() != snap.spring_solid.size())
        throw core::InputError(where + ": the contact spring arrays differ in length (corrupted)");
    });
    try {
      s.dem->restore(snap);
    } catch (const std::exception& e) {
      throw core::InputError(where + ": its solids do not match the case: " + e.what());
    }
  }
  return mark;
}

// ---------------------------------------------------------------------------------------------
// Blown-up steps.

void check_step(const SimulationState& s) {
  const double h = s.spec.h;
  const Diagnostics& g = s.diag;
  // CFL far exceeded: |v| dt > 2 h for the fastest particle.
  if (s.has_fluid && g.max_speed * g.dt > 2.0 * h) {
    std::ostringstream m;
    m << "step " << s.step << " at t = " << s.t << " s: a particle moved " << g.max_speed * g.dt / h
      << " cells in one step (speed " << g.max_speed << " m/s, dt " << g.dt
      << " s); more than 2 cells means the CFL condition is far exceeded: the run has "
      << "blown up";
    throw core::SolverError(m.str());
  }
  if (!s.dem) return;
  // Real boundaries overlapping: delta beyond the imaginary gap (eq. 19: delta = gap - distance).
  const double gap = s.dem->config().gap();
  std::string mine;
  for (const auto& c : s.dem->active_contacts())
    if (c.delta >= gap && mine.empty()) {
      std::ostringstream m;
      m << "step " << s.step << " at t = " << s.t << " s: solid " << c.id_i << " lies inside "
        << (c.id_j >= 0 ? "solid " + std::to_string(c.id_j) : std::string("a wall or obstacle"))
        << " (overlap of the real boundaries " << c.delta - gap << " m at (" << c.point.x << ", "
        << c.point.z << ")): the run has blown up";
      mine = m.str();
    }
  const long long bad = s.comm.max(mine.empty() ? -1LL : static_cast<long long>(s.comm.rank()));
  if (bad >= 0) throw core::SolverError(s.comm.broadcast(mine, static_cast<int>(bad)));
}

}  // namespace picdem::coupling
