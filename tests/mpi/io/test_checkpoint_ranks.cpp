// Checkpoint round trips of distributed arrays, and files written on N ranks read on M ranks
// (N, M = 1 .. size of the run, with sub-communicators).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/error.hpp"
#include "picdem/io/checkpoint.hpp"

namespace {

using picdem::core::Comm;
using picdem::io::CheckpointReader;
using picdem::io::CheckpointWriter;

// Uneven slices on purpose: rank r of n holds 37 r + 5 values (rank 0 of 3 also one empty array).
long long slice_length(int rank) {
  return 37LL * rank + 5;
}

double value_x(long long g) {
  return 0.1 * static_cast<double>(g) - 3.0 / (g + 1.0);
}
std::int64_t value_id(long long g) {
  return 1000000007LL * g + (1LL << 40);
}

void fill(const Comm& comm, std::vector<double>& x, std::vector<std::int64_t>& id,
          std::vector<int>& c) {
  long long b = 0;
  for (int r = 0; r < comm.rank(); ++r) b += slice_length(r);
  for (long long g = b; g < b + slice_length(comm.rank()); ++g) {
    x.push_back(value_x(g));
    id.push_back(value_id(g));
    c.push_back(static_cast<int>(g % 7) - 3);
  }
}

long long global_length(int ranks) {
  long long n = 0;
  for (int r = 0; r < ranks; ++r) n += slice_length(r);
  return n;
}

// One file per writer count and per run (the np1, np2, np3 runs may share the directory).
std::string file_for(int writers) {
  return "ckpt_ranks_np" + std::to_string(Comm().size()) + "_w" + std::to_string(writers) + ".h5";
}

void write_on(const Comm& comm) {
  std::vector<double> x;
  std::vector<std::int64_t> id;
  std::vector<int> c;
  fill(comm, x, id, c);
  CheckpointWriter w(comm, file_for(comm.size()));
  w.write("particles/x", x);
  w.write("particles/id", id);
  w.write("particles/C", c);
  w.write("particles/id_ll", std::vector<long long>(id.begin(), id.end()));
  w.write("solids/empty", std::vector<double>(comm.rank() == 1 ? 3 : 0, -1.0));
  w.attribute("case", std::string("dam break ü"));
  w.attribute("step", 123456789012LL);
  w.attribute("time", 0.1 + 0.2);
  w.attribute("rng", std::vector<double>{1.0, 2.5, -0.0});
  w.commit();
}

// Sub-communicator of the first n ranks (MPI_COMM_NULL elsewhere).
MPI_Comm first(int n) {
  const Comm world;
  MPI_Comm sub;
  MPI_Comm_split(world.raw(), world.rank() < n ? 0 : MPI_UNDEFINED, world.rank(), &sub);
  return sub;
}

TEST(CheckpointRanks, SameRankCountRoundTripIsBitwise) {
  const Comm comm;
  write_on(comm);
  CheckpointReader r(comm, file_for(comm.size()));
  std::vector<double> x;
  std::vector<std::int64_t> id;
  std::vector<int> c;
  fill(comm, x, id, c);
  EXPECT_EQ(r.written_ranks(), comm.size());
  EXPECT_EQ(r.read_slice_double("particles/x"), x);
  EXPECT_EQ(r.read_slice_int64("particles/id"), id);
  EXPECT_EQ(r.read_slice_int("particles/C"), c);
  EXPECT_EQ(r.read_slice_int64("particles/id_ll"), id);
  EXPECT_EQ(r.length("particles/x"), global_length(comm.size()));
  EXPECT_EQ(r.read_slice_double("solids/empty").size(), comm.rank() == 1 ? 3u : 0u);
  EXPECT_EQ(r.attribute_string("case"), "dam break ü");
  EXPECT_EQ(r.attribute_int("step"), 123456789012LL);
  EXPECT_EQ(r.attribute_double("time"), 0.1 + 0.2);
  EXPECT_EQ(r.attribute_doubles("rng"), (std::vector<double>{1.0, 2.5, -0.0}));
}

// The resolved case is stored as an attribute; a case with many obstacles or solids written out
// (the granular column collapse's 300-tooth floor: 84 kB) exceeds the 64 kB that HDF5's original
// object header holds, so the files use the 1.8 format's dense attribute storage.
TEST(CheckpointRanks, AttributesLargerThan64kBRoundTrip) {
  const Comm comm;
  std::string big;
  for (int n = 0; big.size() < 300000; ++n) big += "tooth_" + std::to_string(n) + ": [0.1, 0.2]\n";
  const std::string path = "ckpt_big_attribute_np" + std::to_string(comm.size()) + ".h5";
  {
    CheckpointWriter w(comm, path);
    w.attribute("case_yaml", big);
    w.attribute("many", std::vector<double>(20000, 0.5));
    w.write("particles/x", std::vector<double>(3, 1.0));
    w.commit();
  }
  CheckpointReader r(comm, path);
  EXPECT_EQ(r.attribute_string("case_yaml"), big);
  EXPECT_EQ(r.attribute_doubles("many"), std::vector<double>(20000, 0.5));
}

TEST(CheckpointRanks, WrittenOnNReadOnMGivesTheSameGlobalArray) {
  const Comm world;
  for (int n = 1; n <= world.size(); ++n) {
    MPI_Comm wc = first(n);
    if (wc != MPI_COMM_NULL) {
      write_on(Comm(wc));
      MPI_Comm_free(&wc);
    }
    world.barrier();
    for (int m = 1; m <= world.size(); ++m) {
      MPI_Comm rc = first(m);
      if (rc == MPI_COMM_NULL) continue;
      const Comm comm(rc);
      {
        CheckpointReader r(comm, file_for(n));
        EXPECT_EQ(r.written_ranks(), n);
        const long long total = r.length("particles/x");
        ASSERT_EQ(total, global_length(n));
        EXPECT_EQ(r.slice_lengths("particles/id").size(), static_cast<std::size_t>(n));
        // Each reader takes an even block, which cuts across the writers' slices.
        long long b, e;
        picdem::io::even_split(total, comm.rank(), comm.size(), b, e);
        const auto x = r.read_range_double("particles/x", b, e);
        const auto id = r.read_range_int64("particles/id", b, e);
        ASSERT_EQ(x.size(), static_cast<std::size_t>(e - b));
        ASSERT_EQ(id.size(), static_cast<std::size_t>(e - b));
        for (long long g = b; g < e; ++g) {
          EXPECT_EQ(x[g - b], value_x(g)) << "n=" << n << " m=" << m << " g=" << g;
          EXPECT_EQ(id[g - b], value_id(g)) << "n=" << n << " m=" << m << " g=" << g;
        }
        // The assembled array equals the one written, element for element, after a sum over
        // the readers (each element read by exactly one reader).
        std::vector<long long> count(static_cast<std::size_t>(total), 0);
        for (long long g = b; g < e; ++g) count[static_cast<std::size_t>(g)] = 1;
        comm.sum_in_place(count);
        for (auto k : count) EXPECT_EQ(k, 1);
        if (m != n) {
          EXPECT_THROW((void)r.read_slice_double("particles/x"), picdem::core::InputError);
        }
      }
      MPI_Comm_free(&rc);
    }
    world.barrier();
  }
}

}  // namespace
