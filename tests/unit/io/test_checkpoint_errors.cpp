// Checkpoint files that must not be trusted: missing, truncated, garbage, never committed,
// corrupted data bytes, missing datasets; and an interrupted write that keeps the previous file.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/error.hpp"
#include "picdem/io/checkpoint.hpp"

namespace {

using picdem::core::Comm;
using picdem::core::InputError;
using picdem::io::CheckpointReader;
using picdem::io::CheckpointWriter;

std::string name(const std::string& base) {
  return base + "_np" + std::to_string(Comm().size()) + ".h5";
}

// This rank's slice of a global array g[n] = scale * n + 0.25, n < 1000, even split.
std::vector<double> slice(const Comm& comm, double scale) {
  long long b, e;
  picdem::io::even_split(1000, comm.rank(), comm.size(), b, e);
  std::vector<double> v;
  for (long long n = b; n < e; ++n) v.push_back(scale * n + 0.25);
  return v;
}

void write_file(const Comm& comm, const std::string& path, double scale) {
  CheckpointWriter w(comm, path);
  w.write("particles/x", slice(comm, scale));
  w.attribute("time", scale);
  w.commit();
}

// Expects an InputError whose message names the file and contains `word`.
template <class F>
void expect_input_error(F f, const std::string& path, const std::string& word) {
  try {
    f();
    ADD_FAILURE() << "no InputError for " << path;
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(path), std::string::npos) << m;
    EXPECT_NE(m.find(word), std::string::npos) << m;
  }
}

TEST(CheckpointErrors, MissingFile) {
  const Comm comm;
  expect_input_error([&] { CheckpointReader r(comm, "no_such_checkpoint.h5"); },
                     "no_such_checkpoint.h5", "does not exist");
}

TEST(CheckpointErrors, InterruptedWriteKeepsPreviousFile) {
  const Comm comm;
  const std::string path = name("ckpt_interrupted");
  write_file(comm, path, 1.0);
  {
    // A writer abandoned before commit (an exception, a stop): the previous file is untouched.
    CheckpointWriter w(comm, path);
    w.write("particles/x", slice(comm, 2.0));
    w.attribute("time", 2.0);
    EXPECT_TRUE(std::filesystem::exists(w.temporary_path()));
  }
  comm.barrier();
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  // Every rank has looked before the root writes the temporary below: leaving a barrier is not
  // simultaneous, and a rank descheduled there would see the next write's file.
  comm.barrier();
  // A crash leaves a half-written temporary behind: still the previous file is what is read.
  if (comm.is_root()) std::ofstream(path + ".tmp", std::ios::binary) << "\x89HDF half written";
  comm.barrier();
  CheckpointReader r(comm, path);
  EXPECT_EQ(r.attribute_double("time"), 1.0);
  EXPECT_EQ(r.read_range_double("particles/x", 999, 1000), std::vector<double>{999.25});
  // The next complete write replaces both the stale temporary and the previous file.
  comm.barrier();
}

TEST(CheckpointErrors, TruncatedFile) {
  const Comm comm;
  const std::string path = name("ckpt_truncated");
  write_file(comm, path, 1.0);
  if (comm.is_root()) {
    const auto size = std::filesystem::file_size(path);
    std::filesystem::resize_file(path, size / 2);
  }
  comm.barrier();
  expect_input_error([&] { CheckpointReader r(comm, path); }, path, "truncated");
}

TEST(CheckpointErrors, GarbageFile) {
  const Comm comm;
  const std::string path = name("ckpt_garbage");
  if (comm.is_root()) {
    std::ofstream out(path, std::ios::binary);
    for (int n = 0; n < 5000; ++n) out << static_cast<char>((n * 7919) % 251);
  }
  comm.barrier();
  expect_input_error([&] { CheckpointReader r(comm, path); }, path, "not a readable HDF5");
}

TEST(CheckpointErrors, CorruptedDataBytes) {
  const Comm comm;
  const std::string path = name("ckpt_corrupted");
  write_file(comm, path, 1.0);
  if (comm.is_root()) {
    // Find the raw bytes of element 500 (500.25) and flip one bit of its mantissa.
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    const double v = 500.25;
    const auto at = bytes.find(std::string(reinterpret_cast<const char*>(&v), sizeof v));
    ASSERT_NE(at, std::string::npos);
    f.seekp(static_cast<std::streamoff>(at));
    const char flipped = static_cast<char>(bytes[at] ^ 1);
    f.write(&flipped, 1);
  }
  comm.barrier();
  CheckpointReader r(comm, path);
  expect_input_error([&] { r.read_range_double("particles/x", 0, 1000); }, path, "checksum");
  // Written on 2+ ranks, element 500 sits in slice 1: slice 0 is intact and still readable.
  if (comm.size() > 1) {
    EXPECT_EQ(r.read_range_double("particles/x", 0, 1)[0], 0.25);
  }
}

TEST(CheckpointErrors, NotCommittedMissingDatasetWrongTypeAndRange) {
  const Comm comm;
  const std::string path = name("ckpt_misc");
  write_file(comm, path, 1.0);
  CheckpointReader r(comm, path);
  EXPECT_TRUE(r.has_dataset("particles/x"));
  EXPECT_FALSE(r.has_dataset("particles/y"));
  EXPECT_FALSE(r.has_dataset("solids/x"));
  expect_input_error([&] { r.read_range_double("solids/x", 0, 1); }, path, "solids/x");
  expect_input_error([&] { r.read_range_int64("particles/x", 0, 1); }, path, "element type");
  expect_input_error([&] { r.read_range_double("particles/x", 990, 1001); }, path, "1001");
  expect_input_error([&] { (void)r.attribute_int("step"); }, path, "step");
  expect_input_error([&] { (void)r.attribute_int("time"); }, path, "time");
  // The temporary file of a writer is not a checkpoint: it lacks the completion mark.
  const std::string tmp = name("ckpt_uncommitted");
  {
    CheckpointWriter w(comm, tmp);
    w.write("a", std::vector<double>{1.0});
    comm.barrier();
    if (comm.is_root())
      std::filesystem::copy_file(w.temporary_path(), tmp + ".copy",
                                 std::filesystem::copy_options::overwrite_existing);
    comm.barrier();
  }
  comm.barrier();
  expect_input_error([&] { CheckpointReader c(comm, tmp + ".copy"); }, tmp + ".copy", "");
}

}  // namespace
