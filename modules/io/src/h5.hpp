#pragma once
// Private HDF5 helpers of the io module: an owning handle and the collective file opening.
#include <hdf5.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"

namespace picdem::io::h5 {

/// Owns one HDF5 identifier and closes it with the matching H5?close.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer close) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = o.id_;
      close_ = o.close_;
      o.id_ = -1;
    }
    return *this;
  }
  ~Handle() { reset(); }
  void reset() {
    if (id_ >= 0 && close_) close_(id_);
    id_ = -1;
  }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  operator hid_t() const { return id_; }

 private:
  hid_t id_ = -1;
  Closer close_ = nullptr;
};

/// Throws std::runtime_error with `what` if id < 0.
hid_t check(hid_t id, const std::string& what);
void check_status(herr_t status, const std::string& what);

/// File access list for MPI-IO on `comm`.
Handle mpio_access(const core::Comm& comm);
/// Transfer list for collective MPI-IO.
Handle collective_transfer();
/// Link creation list that creates missing intermediate groups.
Handle intermediate_groups();

/// Silences HDF5's automatic error printing while alive (errors are turned into exceptions).
class QuietErrors {
 public:
  QuietErrors();
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

/// Collective write of a dataset of `dims` (rank 1 to 3) from every rank's block of `count`
/// elements at `start` (row-major, contiguous in `data`); empty blocks are allowed.
void write_block(hid_t file, const std::string& name, hid_t mem_type, const void* data, int rank,
                 const hsize_t* dims, const hsize_t* start, const hsize_t* count);

/// Collective write of a (rows x cols) dataset (1D if cols == 1) from every rank's `local_rows`
/// rows starting at global row `offset`; `global_rows` is the total.
void write_rows(hid_t file, const std::string& name, hid_t mem_type, const void* data,
                long long local_rows, long long offset, long long global_rows, int cols);

/// Collective (every rank passes the same value): attribute `name` on the object at `path` of
/// `file` ("/" is the root group). Strings are fixed-length, null-padded, UTF-8.
void set_attribute(hid_t file, const std::string& path, const std::string& name,
                   const std::string& value);
void set_attribute(hid_t file, const std::string& path, const std::string& name, double value);
void set_attribute(hid_t file, const std::string& path, const std::string& name, long long value);

}  // namespace picdem::io::h5
