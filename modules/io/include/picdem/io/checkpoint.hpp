#pragma once
// Checkpoint primitives: one parallel HDF5 file written collectively by all ranks.
//
// A distributed dataset is the concatenation of every rank's local slice in rank order; rank r's
// offset is the exclusive scan of the slice lengths. Each dataset carries the slice lengths and a
// checksum per slice, so a file can be read back either slice by slice (same rank count) or by an
// arbitrary global range [begin, end) (any rank count), with the checksums of the slices touched
// verified. The file is written under `path + ".tmp"` and renamed to `path` only by commit(), after
// it is complete and closed: a crash leaves the previous checkpoint intact.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"

namespace picdem::io {

class CheckpointWriter {
 public:
  /// Collective. Creates (truncates) `path + ".tmp"`.
  CheckpointWriter(const core::Comm& comm, const std::string& path);
  /// Without commit() the temporary file is closed and removed; `path` is never touched.
  ~CheckpointWriter();
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;

  /// Collective: a dataset of global length sum(local.size()) assembled from every rank's slice.
  /// `name` may contain '/' (groups are created as needed, e.g. "particles/x").
  void write(const std::string& name, const std::vector<double>& local);
  void write(const std::string& name, const std::vector<std::int64_t>& local);
  /// Stored as 64-bit integers, read back with the *_int64 readers.
  void write(const std::string& name, const std::vector<long long>& local);
  void write(const std::string& name, const std::vector<int>& local);

  /// Collective; every rank must pass the same value. Attributes sit on the file's root group.
  void attribute(const std::string& name, const std::string& value);
  void attribute(const std::string& name, long long value);
  void attribute(const std::string& name, double value);
  void attribute(const std::string& name, const std::vector<double>& value);

  /// Collective: marks the file complete, closes it and renames it to `path`.
  void commit();

  const std::string& path() const { return path_; }
  std::string temporary_path() const { return path_ + ".tmp"; }

 private:
  struct Impl;
  core::Comm comm_;
  std::string path_;
  std::unique_ptr<Impl> impl_;
};

class CheckpointReader {
 public:
  /// Collective. Throws core::InputError naming the file when it is missing, not HDF5, truncated,
  /// or was never committed.
  CheckpointReader(const core::Comm& comm, const std::string& path);
  ~CheckpointReader();
  CheckpointReader(const CheckpointReader&) = delete;
  CheckpointReader& operator=(const CheckpointReader&) = delete;

  bool has_dataset(const std::string& name) const;
  bool has_attribute(const std::string& name) const;
  /// Number of ranks that wrote the file.
  int written_ranks() const { return written_ranks_; }
  /// Global length of a dataset.
  long long length(const std::string& name) const;
  /// The slice lengths of the writing ranks, in rank order.
  std::vector<long long> slice_lengths(const std::string& name) const;

  /// This rank's original slice; requires the same rank count as the writer (else InputError).
  std::vector<double> read_slice_double(const std::string& name) const;
  std::vector<std::int64_t> read_slice_int64(const std::string& name) const;
  std::vector<int> read_slice_int(const std::string& name) const;
  /// Elements [begin, end) of the global array (not collective: any rank, any range).
  std::vector<double> read_range_double(const std::string& name, long long begin,
                                        long long end) const;
  std::vector<std::int64_t> read_range_int64(const std::string& name, long long begin,
                                             long long end) const;
  std::vector<int> read_range_int(const std::string& name, long long begin, long long end) const;

  std::string attribute_string(const std::string& name) const;
  long long attribute_int(const std::string& name) const;
  double attribute_double(const std::string& name) const;
  std::vector<double> attribute_doubles(const std::string& name) const;

  const std::string& path() const { return path_; }

 private:
  template <class T>
  std::vector<T> read_range(const std::string& name, long long begin, long long end) const;
  template <class T>
  std::vector<T> read_slice(const std::string& name) const;

  struct Impl;
  core::Comm comm_;
  std::string path_;
  int written_ranks_ = 0;
  std::unique_ptr<Impl> impl_;
};

/// The block [begin, end) of `n` elements that rank `rank` of `size` takes in an even split
/// (the first n % size ranks get one more). A helper for reading on a different rank count.
void even_split(long long n, int rank, int size, long long& begin, long long& end);

}  // namespace picdem::io
