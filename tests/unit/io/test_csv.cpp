// CsvWriter: header, full-precision rows, append mode for restarts, header mismatch error.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "picdem/core/error.hpp"
#include "picdem/io/csv_writer.hpp"

namespace {

using picdem::core::Comm;
using picdem::io::CsvWriter;

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string name(const std::string& base) {
  return base + "_np" + std::to_string(Comm().size()) + ".csv";
}

TEST(Csv, HeaderAndFullPrecisionRows) {
  const Comm comm;
  const std::string path = name("csv_basic");
  {
    CsvWriter w(comm, path, {"t", "x", "n"});
    w.row({0.1, 1.0 / 3.0, 7});
    // Every row is on disk as soon as row() returns (flushed), before the writer closes.
    if (comm.is_root()) {
      EXPECT_EQ(slurp(path), "t,x,n\n0.10000000000000001,0.33333333333333331,7\n");
    }
    w.row({2e-300, -1.5, 1e20});
  }
  comm.barrier();
  const std::string text = slurp(path);
  EXPECT_EQ(text,
            "t,x,n\n0.10000000000000001,0.33333333333333331,7\n2.0000000000000001e-300,-1.5,"
            "1e+20\n");
  // %.17g round-trips: the value read back is bitwise the one written.
  EXPECT_EQ(std::strtod("0.33333333333333331", nullptr), 1.0 / 3.0);
  comm.barrier();
}

TEST(Csv, WrongRowLengthThrows) {
  const Comm comm;
  CsvWriter w(comm, name("csv_len"), {"a", "b"});
  EXPECT_THROW(w.row({1.0}), std::invalid_argument);
  comm.barrier();
}

TEST(Csv, AppendContinuesAndDropsRowsAfterRestartTime) {
  const Comm comm;
  const std::string path = name("csv_append");
  {
    CsvWriter w(comm, path, {"t", "v"});
    for (int n = 0; n < 4; ++n) w.row({0.5 * n, 10.0 * n});
  }
  comm.barrier();
  {
    // A restart from t = 1.0: rows at t = 1.5 (written after that checkpoint) are dropped.
    CsvWriter w(comm, path, {"t", "v"}, /*append=*/true, /*keep_rows_up_to=*/1.0);
    w.row({1.5, -1.0});
  }
  comm.barrier();
  EXPECT_EQ(slurp(path), "t,v\n0,0\n0.5,10\n1,20\n1.5,-1\n");
  comm.barrier();  // every rank has read before rank 0 appends again
  {
    CsvWriter w(comm, path, {"t", "v"}, /*append=*/true);
    w.row({2.0, -2.0});
  }
  comm.barrier();
  EXPECT_EQ(slurp(path), "t,v\n0,0\n0.5,10\n1,20\n1.5,-1\n2,-2\n");
  comm.barrier();
}

TEST(Csv, AppendDropsARowCutShortByACrash) {
  const Comm comm;
  const std::string path = name("csv_cut");
  if (comm.is_root()) std::ofstream(path) << "t,v\n0,1\n0.5,2\n1,3";  // last row unfinished
  comm.barrier();
  {
    CsvWriter w(comm, path, {"t", "v"}, true);
    w.row({1.0, 4.0});
  }
  comm.barrier();
  EXPECT_EQ(slurp(path), "t,v\n0,1\n0.5,2\n1,4\n");
  comm.barrier();
}

TEST(Csv, AppendToMissingFileWritesHeader) {
  const Comm comm;
  const std::string path = name("csv_missing");
  if (comm.is_root()) std::remove(path.c_str());
  comm.barrier();
  {
    CsvWriter w(comm, path, {"t"}, true);
    w.row({3.0});
  }
  comm.barrier();
  EXPECT_EQ(slurp(path), "t\n3\n");
  comm.barrier();
}

TEST(Csv, AppendWithOtherHeaderIsInputErrorOnEveryRank) {
  const Comm comm;
  const std::string path = name("csv_header");
  { CsvWriter w(comm, path, {"t", "a"}); }
  comm.barrier();
  try {
    CsvWriter w(comm, path, {"t", "b"}, true);
    FAIL() << "no error";
  } catch (const picdem::core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("t,b"), std::string::npos) << e.what();
  }
  comm.barrier();
}

}  // namespace
