#include "picdem/io/checkpoint_grid.hpp"

#include <algorithm>
#include <cstdint>
#include <type_traits>

namespace picdem::io {

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

// Restores a grid array written on another decomposition: the global array is put together from
// every writer's owned values (halo values only where no writer owns the sample: ghosts outside
// the tank), and this rank takes its storage box from it.
template <class T>
void restore_grid(const CheckpointReader& in, const std::string& name,
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

}  // namespace

template <class T>
std::vector<T> read_range(const CheckpointReader& in, const std::string& name, long long begin,
                          long long end) {
  if constexpr (std::is_same_v<T, double>)
    return in.read_range_double(name, begin, end);
  else if constexpr (std::is_same_v<T, std::int64_t>)
    return in.read_range_int64(name, begin, end);
  else
    return in.read_range_int(name, begin, end);
}

template <class T>
std::vector<T> read_slice(const CheckpointReader& in, const std::string& name) {
  if constexpr (std::is_same_v<T, double>)
    return in.read_slice_double(name);
  else if constexpr (std::is_same_v<T, std::int64_t>)
    return in.read_slice_int64(name);
  else
    return in.read_slice_int(name);
}

template std::vector<double> read_range(const CheckpointReader&, const std::string&, long long,
                                        long long);
template std::vector<std::int64_t> read_range(const CheckpointReader&, const std::string&,
                                              long long, long long);
template std::vector<int> read_range(const CheckpointReader&, const std::string&, long long,
                                     long long);
template std::vector<double> read_slice(const CheckpointReader&, const std::string&);
template std::vector<std::int64_t> read_slice(const CheckpointReader&, const std::string&);
template std::vector<int> read_slice(const CheckpointReader&, const std::string&);

void write_grid_boxes(CheckpointWriter& out, const grid::Decomposition* d) {
  out.write("grid/boxes", d ? my_boxes(*d) : std::vector<int>{});
}

GridLayout read_grid_layout(const CheckpointReader& in, const grid::Decomposition& d,
                            bool has_grid) {
  const core::Comm& comm = d.comm();
  GridLayout layout;
  bool mine_same = in.written_ranks() == comm.size();
  on_all_ranks(comm, [&] {
    if (!has_grid) return;
    layout.boxes = in.read_range_int("grid/boxes", 0, in.length("grid/boxes"));
    if (layout.boxes.size() != 24u * static_cast<std::size_t>(in.written_ranks()))
      throw core::InputError("checkpoint file '" + in.path() + "': grid/boxes has " +
                             std::to_string(layout.boxes.size()) + " numbers for " +
                             std::to_string(in.written_ranks()) + " ranks (corrupted)");
    if (!mine_same) return;
    const auto mine = my_boxes(d);
    mine_same = std::equal(mine.begin(), mine.end(), layout.boxes.begin() + 24 * comm.rank());
  });
  layout.same = !comm.any(!mine_same);
  return layout;
}

std::vector<core::IndexBox> checkpoint_cell_boxes(const core::Comm& comm, const std::string& path) {
  std::vector<int> boxes;
  try {  // a bad file: reading the checkpoint then names what is wrong with it
    const CheckpointReader in(comm, path);
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

template <class T>
void write_grid_array(CheckpointWriter& out, const std::string& name, const grid::GridArray<T>& f) {
  const std::vector<FileType<T>> v(f.data().begin(), f.data().end());
  out.write(name, v);
}

template <class T>
void read_grid_array(const CheckpointReader& in, const std::string& name, const GridLayout& layout,
                     grid::GridArray<T>& f) {
  if (!layout.same) return restore_grid(in, name, layout.boxes, f);
  const auto v = read_slice<FileType<T>>(in, name);
  if (v.size() != f.data().size())
    throw core::InputError("checkpoint file '" + in.path() + "': " + name +
                           " does not match the grid (corrupted)");
  std::transform(v.begin(), v.end(), f.data().begin(), [](auto x) { return static_cast<T>(x); });
}

#define PICDEM_GRID_ARRAY_IO(T)                                                                 \
  template void write_grid_array(CheckpointWriter&, const std::string&,                         \
                                 const grid::GridArray<T>&);                                    \
  template void read_grid_array(const CheckpointReader&, const std::string&, const GridLayout&, \
                                grid::GridArray<T>&);
PICDEM_GRID_ARRAY_IO(double)
PICDEM_GRID_ARRAY_IO(int)
PICDEM_GRID_ARRAY_IO(signed char)
#undef PICDEM_GRID_ARRAY_IO

}  // namespace picdem::io
