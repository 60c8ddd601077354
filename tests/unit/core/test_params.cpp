// Case-file validation: every bad input gives a message naming the key, the value and what is
// allowed, and is an InputError (the driver turns it into a non-zero exit, never a crash).
#include <gtest/gtest.h>

#include <filesystem>

#include <Teuchos_ParameterList.hpp>
#include "picdem/core/error.hpp"

#include "picdem/core/params.hpp"

using namespace picdem::core;

namespace {
ParamSchema schema() {
  ParamSchema s;
  s.section("fluid", "the fluid");
  s.real("fluid/density", 1000.0, "density").positive();
  s.real("fluid/flip_ratio", 0.95, "FLIP share").at_least(0).at_most(1);
  s.integer("grid/nx", 10, "cells").at_least(4);
  s.boolean("output/png", true, "pictures");
  s.string("fluid/walls", "free_slip", {"free_slip", "no_slip"}, "wall condition");
  s.reals("grid/origin", {0.0, 0.0}, "origin").size(2, 2);
  s.real("time/end", 1.0, "end time").positive().is_required();
  s.passthrough("solver/MueLu", "verbosity: none\n\"smoother: type\": CHEBYSHEV\n", "MueLu");
  auto& f = s.family("obstacles", "fixed obstacles");
  f.variant("box", "a box").reals("lo", {0, 0}, "low corner").size(2, 2);
  f.variant("box", "a box").reals("hi", {1, 1}, "high corner").size(2, 2);
  f.variant("from_file", "an outline from a file")
      .string("file", "", {}, "outline file")
      .is_file_path();
  s.string("input/table", "", {}, "a table file").is_file_path();
  s.check([](const Params& p, std::vector<std::string>& e) {
    if (p.real("fluid/density") > 5000) e.push_back("key 'fluid/density' too heavy for a fluid");
  });
  return s;
}

std::string error_of(const std::string& text, std::vector<std::string> overrides = {}) {
  try {
    read_case_text(text, "case.yaml", overrides, schema());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_error(const std::string& text, std::initializer_list<const char*> parts,
                  std::vector<std::string> overrides = {}) {
  const std::string msg = error_of(text, overrides);
  ASSERT_FALSE(msg.empty()) << "accepted bad input:\n" << text;
  for (const char* p : parts)
    EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
}
}  // namespace

TEST(Params, ValidFileResolvesWithDefaults) {
  auto p = read_case_text("time:\n  end: 2\nfluid:\n  density: 998.2\n", "case.yaml", {}, schema());
  EXPECT_DOUBLE_EQ(p.real("fluid/density"), 998.2);
  EXPECT_DOUBLE_EQ(p.real("time/end"), 2.0);  // integer accepted for a real
  EXPECT_DOUBLE_EQ(p.real("fluid/flip_ratio"), 0.95);
  EXPECT_EQ(p.integer("grid/nx"), 10);
  EXPECT_EQ(p.string("fluid/walls"), "free_slip");
  EXPECT_EQ(p.reals("grid/origin").size(), 2u);
  EXPECT_TRUE(p.boolean("output/png"));
  EXPECT_EQ(p.teuchos("solver/MueLu").get<std::string>("smoother: type"), "CHEBYSHEV");
}

TEST(Params, OverridesAndPassthroughMerge) {
  auto p =
      read_case_text("time:\n  end: 1\nsolver:\n  MueLu:\n    \"smoother: type\": RELAXATION\n",
                     "case.yaml", {"grid/nx=20", "fluid/walls=no_slip"}, schema());
  EXPECT_EQ(p.integer("grid/nx"), 20);
  EXPECT_EQ(p.string("fluid/walls"), "no_slip");
  EXPECT_EQ(p.teuchos("solver/MueLu").get<std::string>("smoother: type"), "RELAXATION");
  EXPECT_EQ(p.teuchos("solver/MueLu").get<std::string>("verbosity"), "none");
}

TEST(Params, FamilyMembersValidatedByVariant) {
  auto p = read_case_text("time:\n  end: 1\nobstacles:\n  wall:\n    type: box\n    hi: [2, 3]\n",
                          "case.yaml", {}, schema());
  ASSERT_EQ(p.sublist_names("obstacles").size(), 1u);
  auto w = p.sub("obstacles/wall");
  EXPECT_EQ(w.reals("hi")[1], 3.0);
  EXPECT_EQ(w.reals("lo")[0], 0.0);
}

// At least fifteen kinds of bad input, each with its message.
// Teuchos' YAML reader refuses two forms YAML allows; the case reader takes both.
TEST(Params, FlowCollectionsOverSeveralLines) {
  auto p = read_case_text(
      "grid:\n  origin: [0.5,   # x\n           1.5]  # z\n  nx: 12\ntime: {end:\n  2}\n"
      "obstacles:\n  wall: {type: box,\n    hi: [2,\n     3]}\n",
      "case.yaml", {}, schema());
  EXPECT_EQ(p.reals("grid/origin"), (std::vector<double>{0.5, 1.5}));
  EXPECT_EQ(p.integer("grid/nx"), 12);
  EXPECT_DOUBLE_EQ(p.real("time/end"), 2.0);
  EXPECT_EQ(p.reals("obstacles/wall/hi"), (std::vector<double>{2.0, 3.0}));
}
TEST(Params, EmptyListIsAnEmptyArray) {
  // An empty list where the schema allows one is read; where it needs values, the key is named.
  expect_error("time:\n  end: 1\ngrid:\n  origin: []   # none\n", {"grid/origin", "has 0 values"});
  expect_error("time:\n  end: []\n", {"time/end"});
  expect_error("time:\n  end: 1\n", {"grid/origin", "has 0 values"}, {"grid/origin=[]"});
}
TEST(Params, BlockListAtTheKeysIndentation) {
  // "key:" with its items "- v" at the key's own column, as PyYAML writes lists (Teuchos' reader
  // takes only deeper items); an item's comment and a blank line inside the list are kept.
  auto p = read_case_text(
      "grid:\n  origin:\n  - 0.5   # x\n\n  - 1.5\n  nx: 12\nobstacles:\n  wall:\n    type: box\n"
      "    hi:\n    - 2\n    - 3\ntime:\n  end: 2\n",
      "case.yaml", {}, schema());
  EXPECT_EQ(p.reals("grid/origin"), (std::vector<double>{0.5, 1.5}));
  EXPECT_EQ(p.integer("grid/nx"), 12);
  EXPECT_EQ(p.reals("obstacles/wall/hi"), (std::vector<double>{2.0, 3.0}));
  EXPECT_DOUBLE_EQ(p.real("time/end"), 2.0);
  // the line numbers of the file still hold after such a list
  const std::string msg =
      error_of("grid:\n  origin:\n  - 0\n  - 0\ntime:\n  end: 1\n  x: \"a\" b\n");
  EXPECT_NE(msg.find("line 7"), std::string::npos) << msg;
}
// A case that names a file (a polygon's vertices) works from any working directory: the case
// file's relative path is its folder's; one given by --set is the working directory's, as a shell
// user means it; absolute paths and cases given as text (no folder) are kept as written.
TEST(Params, FilePathsRelativeToTheCaseFile) {
  const std::string text =
      "time:\n  end: 1\ninput:\n  table: data/t.txt\nobstacles:\n  rock:\n    type: "
      "from_file\n    file: ../shapes/rock.txt\n";
  const auto p = read_case_text(text, "/runs/c/case.yaml", {}, schema(), "/runs/c");
  EXPECT_EQ(p.string("input/table"), "/runs/c/data/t.txt");
  EXPECT_EQ(p.string("obstacles/rock/file"), "/runs/shapes/rock.txt");

  const auto cwd = std::filesystem::current_path();
  const auto q = read_case_text(text, "/runs/c/case.yaml", {"obstacles/rock/file=r2.txt"}, schema(),
                                "/runs/c");
  EXPECT_EQ(q.string("obstacles/rock/file"), (cwd / "r2.txt").lexically_normal().string());
  EXPECT_EQ(q.string("input/table"), "/runs/c/data/t.txt");

  const auto a = read_case_text("time:\n  end: 1\ninput:\n  table: /abs/t.txt\n", "c.yaml", {},
                                schema(), "/runs/c");
  EXPECT_EQ(a.string("input/table"), "/abs/t.txt");
  const auto t = read_case_text(text, "text", {}, schema());
  EXPECT_EQ(t.string("input/table"), "data/t.txt");
  EXPECT_EQ(t.string("fluid/walls"), "free_slip");  // other texts untouched
}

TEST(ParamsBad, LineNumbersCountTheJoinedLines) {
  // A flow list over three lines, then a bad line: the message names the file's line (7).
  const std::string msg =
      error_of("grid:\n  origin: [0,\n\n    0]\ntime:\n  end: 1\n  x: \"a\" b\n");
  EXPECT_NE(msg.find("line 7"), std::string::npos) << msg;
}

TEST(ParamsBad, UnknownKeySuggestsSpelling) {
  expect_error("time:\n  end: 1\nfluid:\n  densty: 1000\n",
               {"unknown key 'fluid/densty'", "did you mean 'fluid/density'", "density"});
}
TEST(ParamsBad, UnknownSection) {
  expect_error("time:\n  end: 1\nfluids: {}\n", {"unknown key 'fluids'"});
}
TEST(ParamsBad, WrongTypeTextForReal) {
  expect_error("time:\n  end: 1\nfluid:\n  density: heavy\n",
               {"'fluid/density'", "expects a real number", "heavy"});
}
TEST(ParamsBad, RealForInteger) {
  expect_error("time:\n  end: 1\ngrid:\n  nx: 12.5\n", {"'grid/nx'", "expects an integer", "12.5"});
}
TEST(ParamsBad, NegativeDensity) {
  expect_error("time:\n  end: 1\nfluid:\n  density: -1000\n",
               {"'fluid/density'", "-1000", "must be > 0"});
}
TEST(ParamsBad, OutOfClosedRange) {
  expect_error("time:\n  end: 1\nfluid:\n  flip_ratio: 1.5\n",
               {"'fluid/flip_ratio'", "1.5", "in [0, 1]"});
}
TEST(ParamsBad, BelowMinimumInteger) {
  expect_error("time:\n  end: 1\ngrid:\n  nx: 2\n", {"'grid/nx'", "= 2", ">= 4"});
}
TEST(ParamsBad, StringNotAChoice) {
  expect_error("time:\n  end: 1\nfluid:\n  walls: sticky\n",
               {"'fluid/walls'", "'sticky'", "free_slip, no_slip"});
}
TEST(ParamsBad, BooleanGivenNumber) {
  expect_error("time:\n  end: 1\noutput:\n  png: 3\n", {"'output/png'", "true or false", "3"});
}
TEST(ParamsBad, ArrayWrongSize) {
  expect_error("time:\n  end: 1\ngrid:\n  origin: [0, 0, 0]\n",
               {"'grid/origin'", "3 values", "2 values"});
}
TEST(ParamsBad, ScalarForArray) {
  expect_error("time:\n  end: 1\ngrid:\n  origin: 0.5\n", {"'grid/origin'", "list of reals"});
}
TEST(ParamsBad, SectionGivenValue) {
  expect_error("time:\n  end: 1\nfluid: 3\n", {"'fluid' is a section", "density"});
}
TEST(ParamsBad, ValueGivenSection) {
  expect_error("time:\n  end: 1\nfluid:\n  density:\n    a: 1\n",
               {"'fluid/density'", "not a section"});
}
TEST(ParamsBad, MissingRequired) {
  expect_error("fluid:\n  density: 1000\n", {"missing required key 'time/end'"});
}
TEST(ParamsBad, EmptyFile) {
  expect_error("", {"empty case file"});
}
TEST(ParamsBad, OnlyComments) {
  expect_error("# nothing here\n\n", {"empty case file"});
}
TEST(ParamsBad, NotYaml) {
  expect_error("time: [1, 2\nfluid: {\n", {"not valid YAML", "line"});
}
TEST(ParamsBad, PlainTextNotYaml) {
  expect_error("this is not a case file\n", {"not valid YAML"});
}
TEST(ParamsBad, NulBytes) {
  expect_error(std::string("time:\n  end: 1\n\0\0", 16), {"NUL"});
}
TEST(ParamsBad, FamilyUnknownType) {
  expect_error("time:\n  end: 1\nobstacles:\n  w:\n    type: cone\n",
               {"'obstacles/w/type'", "'cone'", "box"});
}
TEST(ParamsBad, FamilyMissingType) {
  expect_error("time:\n  end: 1\nobstacles:\n  w:\n    hi: [1, 1]\n",
               {"'obstacles/w'", "needs a key 'type'"});
}
TEST(ParamsBad, FamilyUnknownKey) {
  expect_error("time:\n  end: 1\nobstacles:\n  w:\n    type: box\n    high: [1, 1]\n",
               {"unknown key 'obstacles/w/high'", "did you mean 'obstacles/w/hi'"});
}
TEST(ParamsBad, CrossCheck) {
  expect_error("time:\n  end: 1\nfluid:\n  density: 8000\n", {"too heavy"});
}
TEST(ParamsBad, OverrideValidatedToo) {
  expect_error("time:\n  end: 1\n", {"'fluid/density'", "must be > 0"}, {"fluid/density=-3"});
  expect_error("time:\n  end: 1\n", {"unknown key 'fluid/dens'"}, {"fluid/dens=3"});
  expect_error("time:\n  end: 1\n", {"expected KEY=VALUE"}, {"fluid/density"});
}
TEST(ParamsBad, SeveralProblemsAllListed) {
  const auto msg = error_of("time:\n  end: -1\nfluid:\n  density: -1\n  densty: 2\n");
  EXPECT_NE(msg.find("3 problems"), std::string::npos) << msg;
}
TEST(ParamsBad, PassthroughMustBeSection) {
  expect_error("time:\n  end: 1\nsolver:\n  MueLu: 3\n", {"'solver/MueLu'", "section"});
}

TEST(ParamsReference, ListsEveryKey) {
  const auto md = schema().reference_markdown();
  for (const char* k : {"fluid/density", "fluid/flip_ratio", "grid/nx", "output/png", "time/end",
                        "obstacles/<name>", "lo", "hi", "solver/MueLu"})
    EXPECT_NE(md.find(k), std::string::npos) << k;
}
