// The progress line: the share done never reads above 100% (the last step may end past
// time/end), and the closing call does not repeat the line of the step just printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>

#include "picdem/core/comm.hpp"
#include "picdem/core/log.hpp"

using picdem::core::Comm;
using picdem::core::Progress;

namespace {
std::string captured(const std::function<void()>& f) {
  std::ostringstream out;
  auto* old = std::cout.rdbuf(out.rdbuf());
  f();
  std::cout.rdbuf(old);
  return out.str();
}
int lines(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}
}  // namespace

TEST(Progress, CappedAtHundredPercentAndNoRepeatedLastLine) {
  const std::string text = captured([] {
    Progress p(Comm(), 0.0, 3e-4, 1e9);
    p.report(1e-3, 1, 1e-3, 1);        // first call: printed; 333% of the way
    p.report(1e-3, 1, 1e-3, 1, true);  // the closing call for the same step: not repeated
  });
  EXPECT_EQ(lines(text), 1) << text;
  EXPECT_NE(text.find("100.0%"), std::string::npos) << text;
  EXPECT_NE(text.find("[####################]"), std::string::npos) << text;
  EXPECT_EQ(text.find("333"), std::string::npos) << text;
}

TEST(Progress, ClosingLinePrintedForANewStep) {
  const std::string text = captured([] {
    Progress p(Comm(), 0.0, 1.0, 1e9);
    p.report(0.25, 1, 0.25, 3);       // printed (first)
    p.report(0.5, 2, 0.25, 3);        // within the interval: silent
    p.report(1.0, 4, 0.25, 3, true);  // the closing call: printed
  });
  EXPECT_EQ(lines(text), 2) << text;
  EXPECT_NE(text.find(" 25.0%"), std::string::npos) << text;
  EXPECT_NE(text.find("100.0%  t = 1.0000 s  step 4"), std::string::npos) << text;
}
