#pragma once
// Grid arrays in a checkpoint, and the helpers the modules' own save/restore share
// (particles/checkpoint.hpp, fluid/checkpoint.hpp, dem/checkpoint.hpp).
//
// A grid array is written as every rank's storage box (owned + halo), row-major, beside the
// dataset grid/boxes: per rank 24 numbers, for the staggerings FaceX, FaceZ, Cell in turn the
// storage box and the owned box as i0, i1, k0, k1. On the same layout each rank takes its slice
// back unchanged (bitwise); on another one the global array is put together from the writers'
// owned values and each rank takes its storage box from it.
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/error.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/grid/grid.hpp"
#include "picdem/io/checkpoint.hpp"

namespace picdem::io {

/// Collective: runs `read` on every rank; an InputError seen by some ranks only (each reads its
/// own ranges) becomes the same InputError on every rank, so a bad file never leaves ranks
/// waiting for each other.
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

/// Elements [begin, end) / this rank's slice of a dataset of element type T (double, int64, int).
template <class T>
std::vector<T> read_range(const CheckpointReader& in, const std::string& name, long long begin,
                          long long end);
template <class T>
std::vector<T> read_slice(const CheckpointReader& in, const std::string& name);

/// How the file's grid was split, against this run's.
struct GridLayout {
  bool same = false;       ///< the file was written on this rank count with this run's boxes
  std::vector<int> boxes;  ///< every writer's grid/boxes (empty without a grid)
};

/// Collective: writes grid/boxes (d: nullptr for a case without a grid: an empty dataset).
void write_grid_boxes(CheckpointWriter& out, const grid::Decomposition* d);
/// Collective: reads grid/boxes (`has_grid`) and compares them with this run's `d`. Without a
/// grid the layout is the same when the rank count is.
GridLayout read_grid_layout(const CheckpointReader& in, const grid::Decomposition& d,
                            bool has_grid);
/// Collective: the owned cell box of every rank that wrote the checkpoint `path` (rank order;
/// empty without a grid, or when the file cannot be read).
std::vector<core::IndexBox> checkpoint_cell_boxes(const core::Comm& comm, const std::string& path);

/// Collective: `f`'s storage box as `name` (floating point as double, small integers as int).
template <class T>
void write_grid_array(CheckpointWriter& out, const std::string& name, const grid::GridArray<T>& f);
/// Not collective: `f`'s storage box from `name`, written on `layout` (InputError when the file
/// does not match). T: double, int, signed char.
template <class T>
void read_grid_array(const CheckpointReader& in, const std::string& name, const GridLayout& layout,
                     grid::GridArray<T>& f);

}  // namespace picdem::io
