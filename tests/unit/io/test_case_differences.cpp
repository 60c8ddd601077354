// A checkpoint's case against the restarted one (io::case_differences): every shipped case
// written and read back differs in nothing; a key declared after the checkpoint was written
// counts as its default (so a newer picdem restarts an older run), but not when the restarted case
// sets it to something else; a key this picdem no longer knows is still reported.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"
#include "picdem/coupling/schema.hpp"
#include "picdem/io/checkpoint_files.hpp"
#include "picdem/run/run.hpp"

namespace {

using picdem::core::Comm;
using picdem::core::Params;

const std::string kCase = "cases/dam_break/case.yaml";

// The schema picdem reads case files with, which restart resolves the checkpoint's case by (with
// coupling::case_schema alone the run section the executable writes made every stored case
// unresolvable, so a key declared since a checkpoint was reported as a change).
Params load(const std::string& relative, const std::vector<std::string>& overrides = {}) {
  return picdem::core::read_case(Comm(), std::string(PICDEM_SOURCE_DIR) + "/" + relative, overrides,
                                 picdem::run::case_schema());
}

// The written case without the line of `key` (a leaf "name: value" under its section), as an
// older picdem that did not declare the key would have written it.
std::string without_key(const std::string& yaml, const std::string& leaf) {
  const auto at = yaml.find(" " + leaf + ": ");
  EXPECT_NE(at, std::string::npos) << leaf << " not in the written case";
  if (at == std::string::npos) return yaml;
  const auto begin = yaml.rfind('\n', at) + 1;
  const auto end = yaml.find('\n', at);
  return yaml.substr(0, begin) + yaml.substr(end + 1);
}

TEST(CaseDifferences, EveryShippedCaseMatchesItselfAfterWritingAndResolvingAgain) {
  const auto schema = picdem::run::case_schema();
  int cases = 0;
  for (const auto& dir :
       std::filesystem::directory_iterator(std::string(PICDEM_SOURCE_DIR) + "/cases")) {
    const auto file = dir.path() / "case.yaml";
    if (!std::filesystem::exists(file)) continue;
    const auto relative = "cases/" + dir.path().filename().string() + "/case.yaml";
    const Params p = load(relative);
    const std::string yaml = p.to_yaml();
    // resolving the written case again must succeed (not fall back to the text comparison) ...
    // resolving the written case again must succeed (not fall back to the text comparison) ...
    EXPECT_NO_THROW(picdem::core::resolve_written_case(yaml, relative, schema)) << relative;
    // ... and find no difference
    EXPECT_TRUE(picdem::io::case_differences(yaml, p, schema).empty()) << relative;
    ++cases;
  }
  EXPECT_GE(cases, 20);
}

TEST(CaseDifferences, AKeyDeclaredSinceTheCheckpointCountsAsItsDefault) {
  const auto schema = picdem::run::case_schema();
  const Params now = load(kCase);
  const std::string older = without_key(now.to_yaml(), "viscous_pressure_predictor");
  EXPECT_TRUE(picdem::io::case_differences(older, now, schema).empty());
}

TEST(CaseDifferences, AKeyDeclaredSinceTheCheckpointButSetOtherwiseIsReported) {
  const auto schema = picdem::run::case_schema();
  const std::string older = without_key(load(kCase).to_yaml(), "viscous_pressure_predictor");
  const Params now = load(kCase, {"fluid/viscous_pressure_predictor=true"});
  const auto diff = picdem::io::case_differences(older, now, schema);
  ASSERT_EQ(diff.size(), 1u);
  EXPECT_EQ(diff[0], "fluid/viscous_pressure_predictor: false -> true");
}

TEST(CaseDifferences, AKeyThisPicdemNoLongerKnowsIsReported) {
  const auto schema = picdem::run::case_schema();
  const Params now = load(kCase);
  std::string yaml = now.to_yaml();
  const auto at = yaml.find("\n  fluid:");  // the section's line; its keys are indented by 4
  ASSERT_NE(at, std::string::npos);
  yaml.insert(yaml.find('\n', at + 1) + 1, "    retired_key: 3\n");
  const auto diff = picdem::io::case_differences(yaml, now, schema);
  ASSERT_EQ(diff.size(), 1u);
  EXPECT_EQ(diff[0], "fluid/retired_key: 3 -> (absent)");
}

TEST(CaseDifferences, ACaseValueChangedIsReported) {
  const auto schema = picdem::run::case_schema();
  const std::string stored = load(kCase).to_yaml();
  const auto diff =
      picdem::io::case_differences(stored, load(kCase, {"fluid/density=1100"}), schema);
  ASSERT_EQ(diff.size(), 1u);
  EXPECT_EQ(diff[0].rfind("fluid/density: ", 0), 0u) << diff[0];
}

}  // namespace

// A simulation set up from coupling's schema alone (the tests' and library users' way: no run
// section) restarts from its own checkpoint: the restart resolves both cases with picdem's schema,
// so the run section's default is on both sides (test_mpi_work_decomposition hung on this).
TEST(CaseDifferences, ACaseWithoutTheRunSectionMatchesItsOwnCheckpoint) {
  const Params lib = picdem::core::read_case(Comm(), std::string(PICDEM_SOURCE_DIR) + "/" + kCase,
                                             {}, picdem::coupling::case_schema());
  EXPECT_TRUE(picdem::io::case_differences(lib.to_yaml(), lib, picdem::run::case_schema()).empty());
}
