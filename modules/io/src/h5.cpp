#include "h5.hpp"

namespace picdem::io::h5 {

hid_t check(hid_t id, const std::string& what) {
  if (id < 0) throw std::runtime_error("HDF5 failed: " + what);
  return id;
}

void check_status(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5 failed: " + what);
}

Handle mpio_access(const core::Comm& comm) {
  Handle p(check(H5Pcreate(H5P_FILE_ACCESS), "H5Pcreate(FILE_ACCESS)"), H5Pclose);
  check_status(H5Pset_fapl_mpio(p, comm.raw(), MPI_INFO_NULL), "H5Pset_fapl_mpio");
  check_status(H5Pset_coll_metadata_write(p, 1), "H5Pset_coll_metadata_write");
  // The 1.8 file format: attributes above 64 kB (a resolved case with hundreds of obstacles or
  // solids, per-rank checksum lists on thousands of ranks) go to dense storage instead of failing
  // in the object header; readable by HDF5 1.8 and later (h5py, ParaView).
  check_status(H5Pset_libver_bounds(p, H5F_LIBVER_V18, H5F_LIBVER_V18), "H5Pset_libver_bounds");
  return p;
}

Handle collective_transfer() {
  Handle p(check(H5Pcreate(H5P_DATASET_XFER), "H5Pcreate(DATASET_XFER)"), H5Pclose);
  check_status(H5Pset_dxpl_mpio(p, H5FD_MPIO_COLLECTIVE), "H5Pset_dxpl_mpio");
  return p;
}

Handle intermediate_groups() {
  Handle p(check(H5Pcreate(H5P_LINK_CREATE), "H5Pcreate(LINK_CREATE)"), H5Pclose);
  check_status(H5Pset_create_intermediate_group(p, 1), "H5Pset_create_intermediate_group");
  return p;
}

QuietErrors::QuietErrors() {
  H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietErrors::~QuietErrors() {
  H5Eset_auto2(H5E_DEFAULT, func_, data_);
}

void write_block(hid_t file, const std::string& name, hid_t mem_type, const void* data, int rank,
                 const hsize_t* dims, const hsize_t* start, const hsize_t* count) {
  Handle fspace(check(H5Screate_simple(rank, dims, nullptr), "H5Screate_simple " + name), H5Sclose);
  Handle lcpl = intermediate_groups();
  Handle dset(
      check(H5Dcreate2(file, name.c_str(), mem_type, fspace, lcpl, H5P_DEFAULT, H5P_DEFAULT),
            "H5Dcreate2 " + name),
      H5Dclose);
  Handle mspace(check(H5Screate_simple(rank, count, nullptr), "H5Screate_simple mem " + name),
                H5Sclose);
  hsize_t n = 1;
  for (int d = 0; d < rank; ++d) n *= count[d];
  if (n > 0) {
    check_status(H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, nullptr, count, nullptr),
                 "H5Sselect_hyperslab " + name);
  } else {
    H5Sselect_none(fspace);
    H5Sselect_none(mspace);
  }
  hsize_t total = 1;
  for (int d = 0; d < rank; ++d) total *= dims[d];
  if (total == 0) return;  // an empty dataset has no storage to write to (every rank agrees)
  static const double dummy = 0.0;
  Handle xfer = collective_transfer();
  check_status(H5Dwrite(dset, mem_type, mspace, fspace, xfer, data ? data : &dummy),
               "H5Dwrite " + name);
}

void write_rows(hid_t file, const std::string& name, hid_t mem_type, const void* data,
                long long local_rows, long long offset, long long global_rows, int cols) {
  const hsize_t dims[2] = {static_cast<hsize_t>(global_rows), static_cast<hsize_t>(cols)};
  const hsize_t start[2] = {static_cast<hsize_t>(offset), 0};
  const hsize_t count[2] = {static_cast<hsize_t>(local_rows), static_cast<hsize_t>(cols)};
  write_block(file, name, mem_type, data, cols > 1 ? 2 : 1, dims, start, count);
}

namespace {
void scalar_attribute(hid_t file, const std::string& path, const std::string& name, hid_t type,
                      const void* data) {
  Handle space(check(H5Screate(H5S_SCALAR), "H5Screate " + name), H5Sclose);
  Handle a(check(H5Acreate_by_name(file, path.c_str(), name.c_str(), type, space, H5P_DEFAULT,
                                   H5P_DEFAULT, H5P_DEFAULT),
                 "H5Acreate_by_name " + path + " " + name),
           H5Aclose);
  check_status(H5Awrite(a, type, data), "H5Awrite " + path + " " + name);
}
}  // namespace

void set_attribute(hid_t file, const std::string& path, const std::string& name,
                   const std::string& value) {
  Handle type(check(H5Tcopy(H5T_C_S1), "H5Tcopy"), H5Tclose);
  check_status(H5Tset_size(type, value.empty() ? 1 : value.size()), "H5Tset_size");
  check_status(H5Tset_strpad(type, H5T_STR_NULLPAD), "H5Tset_strpad");
  check_status(H5Tset_cset(type, H5T_CSET_UTF8), "H5Tset_cset");
  const std::string v = value.empty() ? std::string(1, '\0') : value;
  scalar_attribute(file, path, name, type, v.data());
}

void set_attribute(hid_t file, const std::string& path, const std::string& name, double value) {
  scalar_attribute(file, path, name, H5T_NATIVE_DOUBLE, &value);
}

void set_attribute(hid_t file, const std::string& path, const std::string& name, long long value) {
  scalar_attribute(file, path, name, H5T_NATIVE_LLONG, &value);
}

}  // namespace picdem::io::h5
