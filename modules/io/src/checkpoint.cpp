#include "picdem/io/checkpoint.hpp"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <type_traits>

#include "h5.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"

namespace picdem::io {
namespace {

const char* const kComplete = "picdem_checkpoint_complete";
const char* const kRanks = "picdem_checkpoint_ranks";
const char* const kSliceLengths = "slice_lengths";
const char* const kSliceChecksum = "slice_checksum";

template <class T>
hid_t native_type() {
  if constexpr (std::is_same_v<T, double>) return H5T_NATIVE_DOUBLE;
  if constexpr (std::is_same_v<T, std::int64_t>) return H5T_NATIVE_INT64;
  if constexpr (std::is_same_v<T, long long>) return H5T_NATIVE_LLONG;
  if constexpr (std::is_same_v<T, int>) return H5T_NATIVE_INT;
}

template <class T>
H5T_class_t type_class() {
  return std::is_floating_point_v<T> ? H5T_FLOAT : H5T_INTEGER;
}

// Fletcher-style checksum over 64-bit words: a = sum w_i, b = sum a_i (mod 2^64), folded with
// the byte count. One add pair per 8 bytes runs near memory speed (zlib's crc32 took a third of
// the checkpoint time); any single corrupted word changes a, swapped words change b.
std::int64_t checksum_of(const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint64_t a = 0x9e3779b97f4a7c15ull, b = bytes;
  std::size_t n = 0;
  for (; n + 8 <= bytes; n += 8) {
    std::uint64_t w;
    std::memcpy(&w, p + n, 8);
    a += w;
    b += a;
  }
  if (n < bytes) {
    std::uint64_t w = 0;
    std::memcpy(&w, p + n, bytes - n);
    a += w;
    b += a;
  }
  return static_cast<std::int64_t>(a ^ (b * 0xff51afd7ed558ccdull));
}

std::vector<std::int64_t> all_gather_int64(const core::Comm& comm, std::int64_t v) {
  std::vector<std::int64_t> all(static_cast<std::size_t>(comm.size()));
  MPI_Allgather(&v, 1, MPI_INT64_T, all.data(), 1, MPI_INT64_T, comm.raw());
  return all;
}

void write_attribute(hid_t obj, const std::string& name, hid_t type, hid_t space,
                     const void* data) {
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  h5::Handle a(h5::check(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT),
                         "H5Acreate2 " + name),
               H5Aclose);
  h5::check_status(H5Awrite(a, type, data), "H5Awrite " + name);
}

void write_attribute_array(hid_t obj, const std::string& name, hid_t type, const void* data,
                           std::size_t n) {
  const hsize_t dims[1] = {static_cast<hsize_t>(n)};
  h5::Handle space(h5::check(H5Screate_simple(1, dims, nullptr), "H5Screate_simple"), H5Sclose);
  write_attribute(obj, name, type, space, data);
}

void write_attribute_scalar(hid_t obj, const std::string& name, hid_t type, const void* data) {
  h5::Handle space(h5::check(H5Screate(H5S_SCALAR), "H5Screate"), H5Sclose);
  write_attribute(obj, name, type, space, data);
}

}  // namespace

void even_split(long long n, int rank, int size, long long& begin, long long& end) {
  const long long base = n / size, extra = n % size;
  begin = rank * base + (rank < extra ? rank : extra);
  end = begin + base + (rank < extra ? 1 : 0);
}

// ---- writer -------------------------------------------------------------------------------

struct CheckpointWriter::Impl {
  h5::Handle file;
  bool committed = false;

  template <class T>
  void write(const core::Comm& comm, const std::string& name, const std::vector<T>& local) {
    core::ScopedTimer timer("io: checkpoint write");
    const auto n = static_cast<long long>(local.size());
    // Slice offset of this rank: exclusive scan of the slice lengths.
    const long long offset = comm.exclusive_scan(n);
    const long long global = comm.sum(n);
    const std::int64_t sum = checksum_of(local.data(), local.size() * sizeof(T));
    const auto lengths = all_gather_int64(comm, n);
    const auto sums = all_gather_int64(comm, sum);
    const T dummy{};
    h5::write_rows(file, name, native_type<T>(), local.empty() ? &dummy : local.data(), n, offset,
                   global, 1);
    h5::Handle dset(h5::check(H5Dopen2(file, name.c_str(), H5P_DEFAULT), "H5Dopen2 " + name),
                    H5Dclose);
    write_attribute_array(dset, kSliceLengths, H5T_NATIVE_INT64, lengths.data(), lengths.size());
    write_attribute_array(dset, kSliceChecksum, H5T_NATIVE_INT64, sums.data(), sums.size());
  }
};

CheckpointWriter::CheckpointWriter(const core::Comm& comm, const std::string& path)
    : comm_(comm), path_(path), impl_(std::make_unique<Impl>()) {
  h5::Handle fapl = h5::mpio_access(comm_);
  h5::QuietErrors quiet;
  const hid_t f = H5Fcreate(temporary_path().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  if (comm_.any(f < 0)) {
    if (f >= 0) H5Fclose(f);
    throw core::InputError("cannot create checkpoint file '" + temporary_path() +
                           "' (is the directory there and writable?)");
  }
  impl_->file = h5::Handle(f, H5Fclose);
  const long long ranks = comm_.size();
  write_attribute_scalar(impl_->file, kRanks, H5T_NATIVE_LLONG, &ranks);
}

CheckpointWriter::~CheckpointWriter() {
  if (!impl_ || impl_->committed) return;
  // Abandoned write: the temporary file goes, the previous checkpoint stays.
  impl_->file.reset();
  // The close is collective but returns on each rank in its own time: the root removes the file
  // only once every rank has closed it, and no rank goes on before it is gone.
  MPI_Barrier(comm_.raw());
  if (comm_.is_root()) std::remove(temporary_path().c_str());
  MPI_Barrier(comm_.raw());
}

void CheckpointWriter::write(const std::string& name, const std::vector<double>& local) {
  impl_->write(comm_, name, local);
}
void CheckpointWriter::write(const std::string& name, const std::vector<std::int64_t>& local) {
  impl_->write(comm_, name, local);
}
void CheckpointWriter::write(const std::string& name, const std::vector<long long>& local) {
  impl_->write(comm_, name, local);
}
void CheckpointWriter::write(const std::string& name, const std::vector<int>& local) {
  impl_->write(comm_, name, local);
}

void CheckpointWriter::attribute(const std::string& name, const std::string& value) {
  h5::Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  H5Tset_strpad(type, H5T_STR_NULLPAD);
  const std::string v = value.empty() ? std::string(1, '\0') : value;
  write_attribute_scalar(impl_->file, name, type, v.data());
}
void CheckpointWriter::attribute(const std::string& name, long long value) {
  write_attribute_scalar(impl_->file, name, H5T_NATIVE_LLONG, &value);
}
void CheckpointWriter::attribute(const std::string& name, double value) {
  write_attribute_scalar(impl_->file, name, H5T_NATIVE_DOUBLE, &value);
}
void CheckpointWriter::attribute(const std::string& name, const std::vector<double>& value) {
  const double dummy = 0.0;
  write_attribute_array(impl_->file, name, H5T_NATIVE_DOUBLE, value.empty() ? &dummy : value.data(),
                        value.size());
}

void CheckpointWriter::commit() {
  core::ScopedTimer timer("io: checkpoint write");
  const long long complete = 1;
  write_attribute_scalar(impl_->file, kComplete, H5T_NATIVE_LLONG, &complete);
  h5::check_status(H5Fflush(impl_->file, H5F_SCOPE_GLOBAL), "H5Fflush " + temporary_path());
  impl_->file.reset();  // collective close: every rank's data is in the file after this
  impl_->committed = true;
  // rename(2) replaces the previous checkpoint atomically.
  int failed = 0;
  if (comm_.is_root()) failed = std::rename(temporary_path().c_str(), path_.c_str()) != 0;
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm_.raw());
  if (failed)
    throw core::InputError("cannot rename checkpoint '" + temporary_path() + "' to '" + path_ +
                           "'");
}

// ---- reader -------------------------------------------------------------------------------

struct CheckpointReader::Impl {
  h5::Handle file;
};

CheckpointReader::CheckpointReader(const core::Comm& comm, const std::string& path)
    : comm_(comm), path_(path), impl_(std::make_unique<Impl>()) {
  int exists = 0;
  if (comm_.is_root()) exists = std::filesystem::is_regular_file(path_) ? 1 : 0;
  MPI_Bcast(&exists, 1, MPI_INT, 0, comm_.raw());
  if (!exists) throw core::InputError("checkpoint file '" + path_ + "' does not exist");
  h5::Handle fapl = h5::mpio_access(comm_);
  h5::QuietErrors quiet;
  const hid_t f = H5Fopen(path_.c_str(), H5F_ACC_RDONLY, fapl);
  if (comm_.any(f < 0)) {
    if (f >= 0) H5Fclose(f);
    throw core::InputError("checkpoint file '" + path_ +
                           "' is not a readable HDF5 file (truncated or corrupted)");
  }
  impl_->file = h5::Handle(f, H5Fclose);
  if (!has_attribute(kComplete) || attribute_int(kComplete) != 1)
    throw core::InputError("checkpoint file '" + path_ + "' was never completed");
  written_ranks_ = static_cast<int>(attribute_int(kRanks));
}

CheckpointReader::~CheckpointReader() = default;

bool CheckpointReader::has_dataset(const std::string& name) const {
  h5::QuietErrors quiet;
  // H5Lexists needs every intermediate link to exist: check the path one component at a time.
  std::size_t pos = 0;
  while (true) {
    pos = name.find('/', pos + 1);
    const std::string prefix = name.substr(0, pos);
    if (prefix.empty() || H5Lexists(impl_->file, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    if (pos == std::string::npos) break;
  }
  H5O_info_t info;
  if (H5Oget_info_by_name(impl_->file, name.c_str(), &info, H5P_DEFAULT) < 0) return false;
  return info.type == H5O_TYPE_DATASET;
}

bool CheckpointReader::has_attribute(const std::string& name) const {
  h5::QuietErrors quiet;
  return H5Aexists(impl_->file, name.c_str()) > 0;
}

namespace {

std::string where(const std::string& path, const std::string& name) {
  return "checkpoint file '" + path + "', dataset '" + name + "'";
}

std::vector<std::int64_t> read_int64_attribute(hid_t obj, const std::string& attr,
                                               const std::string& context) {
  h5::QuietErrors quiet;
  if (H5Aexists(obj, attr.c_str()) <= 0)
    throw core::InputError(context + ": missing attribute '" + attr + "'");
  h5::Handle a(H5Aopen(obj, attr.c_str(), H5P_DEFAULT), H5Aclose);
  h5::Handle space(H5Aget_space(a), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  if (!a.valid() || !space.valid() || n < 0)
    throw core::InputError(context + ": unreadable attribute '" + attr + "'");
  std::vector<std::int64_t> v(static_cast<std::size_t>(n));
  if (H5Aread(a, H5T_NATIVE_INT64, v.data()) < 0)
    throw core::InputError(context + ": unreadable attribute '" + attr + "'");
  return v;
}

}  // namespace

long long CheckpointReader::length(const std::string& name) const {
  const auto lengths = slice_lengths(name);
  long long n = 0;
  for (auto l : lengths) n += l;
  return n;
}

std::vector<long long> CheckpointReader::slice_lengths(const std::string& name) const {
  if (!has_dataset(name)) throw core::InputError(where(path_, name) + " does not exist");
  h5::QuietErrors quiet;
  h5::Handle dset(H5Dopen2(impl_->file, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dset.valid()) throw core::InputError(where(path_, name) + " cannot be opened");
  const auto v = read_int64_attribute(dset, kSliceLengths, where(path_, name));
  return {v.begin(), v.end()};
}

namespace {

// Reads [begin, end) of a 1D dataset, verifying the checksum of every writer's slice it touches
// (the read is widened to whole slices).
template <class T>
std::vector<T> read_range_checked(hid_t file, const std::string& path, const std::string& name,
                                  long long begin, long long end) {
  const std::string ctx = where(path, name);
  h5::QuietErrors quiet;
  h5::Handle dset(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dset.valid()) throw core::InputError(ctx + " does not exist");
  h5::Handle ftype(H5Dget_type(dset), H5Tclose);
  if (H5Tget_class(ftype) != type_class<T>() || H5Tget_size(ftype) != sizeof(T))
    throw core::InputError(ctx + " holds another element type than the one asked for");
  const auto lengths = read_int64_attribute(dset, kSliceLengths, ctx);
  const auto sums = read_int64_attribute(dset, kSliceChecksum, ctx);
  if (sums.size() != lengths.size())
    throw core::InputError(ctx + ": slice attributes disagree (corrupted)");
  std::vector<long long> off(lengths.size() + 1, 0);
  for (std::size_t s = 0; s < lengths.size(); ++s) off[s + 1] = off[s] + lengths[s];
  const long long n = off.back();
  h5::Handle fspace(H5Dget_space(dset), H5Sclose);
  if (H5Sget_simple_extent_npoints(fspace) != n)
    throw core::InputError(ctx + ": length disagrees with its slice lengths (corrupted)");
  if (begin < 0 || end < begin || end > n)
    throw core::InputError(ctx + ": range [" + std::to_string(begin) + ", " + std::to_string(end) +
                           ") outside [0, " + std::to_string(n) + ")");
  if (begin == end) return {};
  // Whole slices s0..s1 covering [begin, end).
  std::size_t s0 = 0;
  while (off[s0 + 1] <= begin) ++s0;
  std::size_t s1 = s0;
  while (off[s1 + 1] < end) ++s1;
  const long long b = off[s0], e = off[s1 + 1];
  std::vector<T> buf(static_cast<std::size_t>(e - b));
  const hsize_t start[1] = {static_cast<hsize_t>(b)}, count[1] = {static_cast<hsize_t>(e - b)};
  h5::Handle mspace(H5Screate_simple(1, count, nullptr), H5Sclose);
  H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, nullptr, count, nullptr);
  if (H5Dread(dset, native_type<T>(), mspace, fspace, H5P_DEFAULT, buf.data()) < 0)
    throw core::InputError(ctx + " cannot be read (truncated or corrupted)");
  for (std::size_t s = s0; s <= s1; ++s) {
    const std::size_t first = static_cast<std::size_t>(off[s] - b);
    const auto bytes = static_cast<std::size_t>(lengths[s]) * sizeof(T);
    if (checksum_of(buf.data() + first, bytes) != sums[s])
      throw core::InputError(ctx + ": slice " + std::to_string(s) +
                             " fails its checksum (corrupted)");
  }
  if (begin == b && end == e) return buf;  // whole slices: no copy
  return {buf.begin() + (begin - b), buf.begin() + (end - b)};
}

}  // namespace

template <class T>
std::vector<T> CheckpointReader::read_range(const std::string& name, long long begin,
                                            long long end) const {
  core::ScopedTimer timer("io: checkpoint read");
  if (!has_dataset(name)) throw core::InputError(where(path_, name) + " does not exist");
  return read_range_checked<T>(impl_->file, path_, name, begin, end);
}

template <class T>
std::vector<T> CheckpointReader::read_slice(const std::string& name) const {
  if (written_ranks_ != comm_.size())
    throw core::InputError("checkpoint file '" + path_ + "' was written on " +
                           std::to_string(written_ranks_) + " ranks, read on " +
                           std::to_string(comm_.size()) + ": read ranges instead of slices");
  const auto lengths = slice_lengths(name);
  const auto r = static_cast<std::size_t>(comm_.rank());
  long long b = 0;
  for (std::size_t q = 0; q < r; ++q) b += lengths[q];
  return read_range<T>(name, b, b + lengths[r]);
}

std::vector<double> CheckpointReader::read_slice_double(const std::string& name) const {
  return read_slice<double>(name);
}
std::vector<std::int64_t> CheckpointReader::read_slice_int64(const std::string& name) const {
  return read_slice<std::int64_t>(name);
}
std::vector<int> CheckpointReader::read_slice_int(const std::string& name) const {
  return read_slice<int>(name);
}
std::vector<double> CheckpointReader::read_range_double(const std::string& name, long long begin,
                                                        long long end) const {
  return read_range<double>(name, begin, end);
}
std::vector<std::int64_t> CheckpointReader::read_range_int64(const std::string& name,
                                                             long long begin, long long end) const {
  return read_range<std::int64_t>(name, begin, end);
}
std::vector<int> CheckpointReader::read_range_int(const std::string& name, long long begin,
                                                  long long end) const {
  return read_range<int>(name, begin, end);
}

namespace {

h5::Handle open_attribute(hid_t file, const std::string& path, const std::string& name) {
  h5::QuietErrors quiet;
  if (H5Aexists(file, name.c_str()) <= 0)
    throw core::InputError("checkpoint file '" + path + "' has no attribute '" + name + "'");
  h5::Handle a(H5Aopen(file, name.c_str(), H5P_DEFAULT), H5Aclose);
  if (!a.valid())
    throw core::InputError("checkpoint file '" + path + "': attribute '" + name +
                           "' cannot be opened");
  return a;
}

void read_attribute(hid_t a, hid_t type, void* out, const std::string& path,
                    const std::string& name, H5T_class_t expected) {
  h5::Handle t(H5Aget_type(a), H5Tclose);
  if (H5Tget_class(t) != expected)
    throw core::InputError("checkpoint file '" + path + "': attribute '" + name +
                           "' has another type than the one asked for");
  if (H5Aread(a, type, out) < 0)
    throw core::InputError("checkpoint file '" + path + "': attribute '" + name +
                           "' cannot be read");
}

}  // namespace

std::string CheckpointReader::attribute_string(const std::string& name) const {
  h5::Handle a = open_attribute(impl_->file, path_, name);
  h5::Handle t(H5Aget_type(a), H5Tclose);
  if (H5Tget_class(t) != H5T_STRING)
    throw core::InputError("checkpoint file '" + path_ + "': attribute '" + name +
                           "' is not a string");
  std::string s(H5Tget_size(t), '\0');
  h5::check_status(H5Aread(a, t, s.data()), "H5Aread " + name);
  s.resize(std::strlen(s.c_str()));
  return s;
}

long long CheckpointReader::attribute_int(const std::string& name) const {
  h5::Handle a = open_attribute(impl_->file, path_, name);
  long long v = 0;
  read_attribute(a, H5T_NATIVE_LLONG, &v, path_, name, H5T_INTEGER);
  return v;
}

double CheckpointReader::attribute_double(const std::string& name) const {
  h5::Handle a = open_attribute(impl_->file, path_, name);
  double v = 0;
  read_attribute(a, H5T_NATIVE_DOUBLE, &v, path_, name, H5T_FLOAT);
  return v;
}

std::vector<double> CheckpointReader::attribute_doubles(const std::string& name) const {
  h5::Handle a = open_attribute(impl_->file, path_, name);
  h5::Handle space(H5Aget_space(a), H5Sclose);
  std::vector<double> v(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  double dummy = 0;
  read_attribute(a, H5T_NATIVE_DOUBLE, v.empty() ? &dummy : v.data(), path_, name, H5T_FLOAT);
  return v;
}

}  // namespace picdem::io
