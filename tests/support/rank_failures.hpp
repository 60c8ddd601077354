// On ranks other than 0 the tests' progress is not printed (it would repeat rank 0's), but a
// failure there must still be seen: this listener prints each failed assertion of its rank, with
// the rank and the test's name, to stderr.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace picdem::test {

class RankFailurePrinter : public ::testing::EmptyTestEventListener {
 public:
  explicit RankFailurePrinter(int rank) : rank_(rank) {}
  // The test's name is kept when it starts: GoogleTest holds its own lock while it reports a
  // result, so asking it for the current test here would deadlock.
  void OnTestStart(const ::testing::TestInfo& test) override {
    test_ = std::string(test.test_suite_name()) + "." + test.name();
  }
  void OnTestPartResult(const ::testing::TestPartResult& r) override {
    if (!r.failed()) return;
    std::fprintf(stderr, "[rank %d] FAILED %s: %s:%d\n%s\n", rank_, test_.c_str(),
                 r.file_name() ? r.file_name() : "?", r.line_number(), r.message());
  }

 private:
  int rank_;
  std::string test_;
};

/// Rank 0 keeps GoogleTest's printer; the other ranks print their failures only.
inline void print_failures_only_off_root(int rank) {
  if (rank == 0) return;
  auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
  delete listeners.Release(listeners.default_result_printer());
  listeners.Append(new RankFailurePrinter(rank));
}

}  // namespace picdem::test
