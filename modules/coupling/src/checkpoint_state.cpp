#include "checkpoint_state.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <thread>
#include <type_traits>
#include <utility>

#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/io/checkpoint.hpp"
#include "picdem/io/checkpoint_files.hpp"
#include "picdem/particles/particles.hpp"

namespace picdem::coupling {

// Layout (doc/restart.md):
//   attributes: format_version, io::code_version, case_yaml, t, step, ranks, has_fluid,
//               diagnostics (the scalars of Diagnostics in declaration order),
//               diagnostics_solids_in_box, diagnostics_levels (when there are probes),
//               output_next_frame, output_frames, output_last_frame_step
//   particles/<name>: ParticleSet::for_each_saved, every rank's particles in their order
//   grid/<name>: FluidState::for_each_saved, every rank's storage box (owned + halo), row-major;
//               signed char fields as int
//   grid/boxes (int): per rank 24 numbers: for the staggerings FaceX, FaceZ, Cell in turn the
//               storage box and the owned box as i0, i1, k0, k1
//   dem/<name>: DemSolver::Snapshot::for_each, from rank 0

namespace {

using grid::Stagger;

constexpr Stagger kStaggers[3] = {Stagger::FaceX, Stagger::FaceZ, Stagger::Cell};

int stagger_index(Stagger s) {
  return s == Stagger::FaceX ? 0 : s == Stagger::FaceZ ? 1 : 2;
}

// The element type a grid array of T is stored as: double, or int for the small integers.
template <class T>
using FileType = std::conditional_t<std::is_floating_point_v<T>, double, int>;

void push_box(std::vector<int>& out, const core::IndexBox& b) {
  out.insert(out.end(), {b.i0, b.i1, b.k0, b.k1});
}

core::IndexBox box_at(const std::vector<int>& v, std::size_t at) {
  return {v[at], v[at + 1], v[at + 2], v[at + 3]};
}

// This rank's grid/boxes entry: storage and owned box of each staggering.
std::vector<int> my_boxes(const grid::Decomposition& d) {
  std::vector<int> out;
  for (Stagger s : kStaggers) push_box(out, d.storage(s)), push_box(out, d.owned(s));
  return out;
}

template <class T>
std::vector<T> read_range(const io::CheckpointReader& in, const std::string& name, long long b,
                          long long e) {
  if constexpr (std::is_same_v<T, double>)
    return in.read_range_double(name, b, e);
  else if constexpr (std::is_same_v<T, std::int64_t>)
    return in.read_range_int64(name, b, e);
  else
    return in.read_range_int(name, b, e);
}

template <class T>
std::vector<T> read_slice(const io::CheckpointReader& in, const std::string& name) {
  if constexpr (std::is_same_v<T, double>)
    return in.read_slice_double(name);
  else if constexpr (std::is_same_v<T, std::int64_t>)
    return in.read_slice_int64(name);
  else
    return in.read_slice_int(name);
}

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
  out.attribute("ranks", static_cast<long long>(parts.comm.size()));
  out.attribute("has_fluid", static_cast<long long>(parts.fluid ? 1 : 0));
  out.attribute("diagnostics", head.diag.scalars());
  out.attribute("diagnostics_solids_in_box", head.diag.solids_in_box);
  if (!head.diag.levels.empty()) out.attribute("diagnostics_levels", head.diag.levels);
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
  std::as_const(parts.particles).for_each_saved([&](const char* name, const auto& v) {
    out.write(std::string("particles/") + name, v);
  });
  pause_in_data_if_asked(parts.comm, head.step, out.temporary_path());
  std::vector<int> boxes;
  if (parts.fluid) {
    std::as_const(*parts.fluid).for_each_saved([&](const char* name, const auto& f) {
      using T = typename std::decay_t<decltype(f.data())>::value_type;
      const std::vector<FileType<T>> v(f.data().begin(), f.data().end());
      out.write(std::string("grid/") + name, v);
    });
    boxes = my_boxes(parts.decomposition);
  }
  out.write("grid/boxes", boxes);
  dem::DemSolver::Snapshot snap;
  if (parts.dem) snap = parts.dem->snapshot();
  const bool root = parts.comm.is_root();
  std::as_const(snap).for_each([&](const char* name, const auto& v) {
    out.write(std::string("dem/") + name, root ? v : std::decay_t<decltype(v)>{});
  });
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
template <class T>
void restore_grid(const io::CheckpointReader& in, const std::string& name,
                  const std::vector<int>& boxes, grid::GridArray<T>& f) {
  const int which = stagger_index(f.stagger());
  const auto lengths = in.slice_lengths(name);
  const int writers = static_cast<int>(lengths.size());
  if (boxes.size() != static_cast<std::size_t>(24 * writers))
    throw core::InputError("checkpoint file '" + in.path() + "': grid/boxes has " +
                           std::to_string(boxes.size()) + " numbers, expected " +
                           std::to_string(24 * writers) + " (corrupted)");
  std::vector<long long> offsets(writers + 1, 0);
  for (int r = 0; r < writers; ++r) offsets[r + 1] = offsets[r] + lengths[r];
  core::IndexBox all = box_at(boxes, 8 * which);  // the union of the writers' storage boxes
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
    const auto v = read_range<FileType<T>>(in, name, offsets[r], offsets[r + 1]);
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
  const auto diff = io::case_differences(in.attribute_string("case_yaml"), parts.params);
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
  on_all_ranks(parts.comm, [&] {
    head.t = in.attribute_double("t");
    head.step = in.attribute_int("step");
    const auto v = in.attribute_doubles("diagnostics");
    if (v.size() != Diagnostics::scalar_names().size())
      throw core::InputError(where + ": attribute 'diagnostics' has " + std::to_string(v.size()) +
                             " values, expected " +
                             std::to_string(Diagnostics::scalar_names().size()));
    head.diag.set_scalars(v);
    if (in.has_attribute("diagnostics_solids_in_box"))
      head.diag.solids_in_box = in.attribute_int("diagnostics_solids_in_box");
    if (in.has_attribute("diagnostics_levels"))
      head.diag.levels = in.attribute_doubles("diagnostics_levels");
    head.mark.next_frame = in.attribute_double("output_next_frame");
    head.mark.frames = in.attribute_int("output_frames");
    head.mark.last_frame_step = in.attribute_int("output_last_frame_step");
  });
  return head;
}

// True on every rank when the file was written on this rank count with every rank's boxes as
// this run's (the decomposition depends on the rank count and grid/ranks_x, grid/ranks_z): each
// rank then takes its own slices back unchanged (bitwise). `boxes`: every writer's grid/boxes.
bool same_layout(const io::CheckpointReader& in, const CheckpointParts& parts,
                 std::vector<int>& boxes) {
  const core::Comm& comm = parts.comm;
  bool mine_same = in.written_ranks() == comm.size();
  on_all_ranks(comm, [&] {
    if (!parts.fluid) return;
    boxes = in.read_range_int("grid/boxes", 0, in.length("grid/boxes"));
    if (boxes.size() != 24u * static_cast<std::size_t>(in.written_ranks()))
      throw core::InputError("checkpoint file '" + in.path() + "': grid/boxes has " +
                             std::to_string(boxes.size()) + " numbers for " +
                             std::to_string(in.written_ranks()) + " ranks (corrupted)");
    if (!mine_same) return;
    const auto mine = my_boxes(parts.decomposition);
    mine_same = std::equal(mine.begin(), mine.end(), boxes.begin() + 24 * comm.rank());
  });
  return !comm.any(!mine_same);
}

// Same layout: this rank's slices; otherwise an even share of the particles, which the caller
// sends to their owners.
void read_particles(const io::CheckpointReader& in, const core::Comm& comm, bool same,
                    particles::ParticleSet& P) {
  long long begin = 0, end = 0;
  if (!same) io::even_split(in.length("particles/x"), comm.rank(), comm.size(), begin, end);
  P.for_each_saved([&](const char* name, auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    const std::string key = std::string("particles/") + name;
    v = same ? read_slice<T>(in, key) : read_range<T>(in, key, begin, end);
  });
  bool equal_lengths = true;
  std::as_const(P).for_each_saved(
      [&](const char*, const auto& v) { equal_lengths = equal_lengths && v.size() == P.size(); });
  if (!equal_lengths)
    throw core::InputError("checkpoint file '" + in.path() +
                           "': the particle arrays differ in length (corrupted)");
}

void read_grid(const io::CheckpointReader& in, bool same, const std::vector<int>& boxes,
               fluid::FluidState& fluid) {
  fluid.for_each_saved([&](const char* name, auto& f) {
    using T = typename std::decay_t<decltype(f.data())>::value_type;
    const std::string key = std::string("grid/") + name;
    if (!same) return restore_grid(in, key, boxes, f);
    const auto v = read_slice<FileType<T>>(in, key);
    if (v.size() != f.data().size())
      throw core::InputError("checkpoint file '" + in.path() + "': " + key +
                             " does not match the grid (corrupted)");
    std::transform(v.begin(), v.end(), f.data().begin(), [](auto x) { return static_cast<T>(x); });
  });
}

dem::DemSolver::Snapshot read_dem(const io::CheckpointReader& in) {
  dem::DemSolver::Snapshot snap;
  snap.for_each([&](const char* name, auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    const std::string key = std::string("dem/") + name;
    v = read_range<T>(in, key, 0, in.length(key));
  });
  const std::string where = "checkpoint file '" + in.path() + "'";
  const std::size_t n = snap.id.size();
  for (const auto* v : {&snap.x, &snap.z, &snap.theta, &snap.u, &snap.w, &snap.omega})
    if (v->size() != n)
      throw core::InputError(where + ": the solid arrays differ in length (corrupted)");
  if (snap.spring_partner.size() != snap.spring_solid.size() ||
      snap.spring.size() != snap.spring_solid.size())
    throw core::InputError(where + ": the contact spring arrays differ in length (corrupted)");
  return snap;
}

}  // namespace

CheckpointHeader read_checkpoint(const CheckpointParts& parts, const std::string& path) {
  core::ScopedTimer timer("checkpoint: read");
  const core::Comm& comm = parts.comm;
  const io::CheckpointReader in(comm, path);
  const CheckpointHeader head = read_header(in, parts);
  std::vector<int> boxes;
  const bool same = same_layout(in, parts, boxes);
  on_all_ranks(comm, [&] {
    read_particles(in, comm, same, parts.particles);
    parts.particles.spec = parts.decomposition.spec();
    if (parts.fluid) read_grid(in, same, boxes, *parts.fluid);
  });
  if (!same && parts.fluid) particles::migrate(parts.particles, parts.decomposition);
  if (parts.dem) {
    dem::DemSolver::Snapshot snap;
    on_all_ranks(comm, [&] { snap = read_dem(in); });
    try {
      parts.dem->restore(snap);
    } catch (const std::exception& e) {
      throw core::InputError("checkpoint file '" + path +
                             "': its solids do not match the case: " + e.what());
    }
  }
  return head;
}

std::vector<core::IndexBox> checkpoint_cell_boxes(const core::Comm& comm, const std::string& path) {
  std::vector<int> boxes;
  try {  // a bad file: read_checkpoint then names what is wrong with it
    const io::CheckpointReader in(comm, path);
    on_all_ranks(comm,
                 [&] { boxes = in.read_range_int("grid/boxes", 0, in.length("grid/boxes")); });
  } catch (const core::InputError&) {
    return {};
  }
  std::vector<core::IndexBox> out;
  // per rank: FaceX, FaceZ, Cell, each as storage box then owned box
  for (std::size_t at = 0; at + 24 <= boxes.size(); at += 24) out.push_back(box_at(boxes, at + 20));
  return out;
}

void check_step(const Diagnostics& g, double h, bool has_fluid, const dem::DemSolver* dem,
                const core::Comm& comm) {
  // CFL far exceeded: |v| dt > 2 h for the fastest particle.
  if (has_fluid && g.max_speed * g.dt > 2.0 * h) {
    std::ostringstream m;
    m << "step " << g.step << " at t = " << g.t << " s: a particle moved " << g.max_speed * g.dt / h
      << " cells in one step (speed " << g.max_speed << " m/s, dt " << g.dt
      << " s); more than 2 cells means the CFL condition is far exceeded: the run has "
      << "blown up";
    throw core::SolverError(m.str());
  }
  if (!dem) return;
  // Real boundaries overlapping: delta beyond the imaginary gap (eq. 19: delta = gap - distance).
  const double gap = dem->config().gap();
  std::string mine;
  for (const auto& c : dem->active_contacts())
    if (c.delta >= gap && mine.empty()) {
      std::ostringstream m;
      m << "step " << g.step << " at t = " << g.t << " s: solid " << c.id_i << " lies inside "
        << (c.id_j >= 0 ? "solid " + std::to_string(c.id_j) : std::string("a wall or obstacle"))
        << " (overlap of the real boundaries " << c.delta - gap << " m at (" << c.point.x << ", "
        << c.point.z << ")): the run has blown up";
      mine = m.str();
    }
  const long long bad = comm.max(mine.empty() ? -1LL : static_cast<long long>(comm.rank()));
  if (bad >= 0) throw core::SolverError(comm.broadcast(mine, static_cast<int>(bad)));
}

}  // namespace picdem::coupling
