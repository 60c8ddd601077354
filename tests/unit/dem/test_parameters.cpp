// Case-file keys of the DEM: defaults as the paper, the solids family and its generator, and
// input errors that name the key, the value and what is allowed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "picdem/core/error.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/dem/parameters.hpp"
#include "picdem/geometry/circle.hpp"

using namespace picdem;
using namespace picdem::dem;

namespace {
core::ParamSchema schema() {
  core::ParamSchema s;
  s.real("grid/cell_size", 0.01, "h");
  declare_parameters(s);
  return s;
}
core::Params read(const std::string& text) {
  return core::read_case_text(text, "case.yaml", {}, schema());
}
}  // namespace

TEST(DemParameters, DefaultsAreThePapers) {
  const auto c = config_from(read("grid:\n  cell_size: 0.0005\n"), 0.0005);
  EXPECT_EQ(c.alpha, 0.4);
  EXPECT_EQ(c.psi, 0.3);
  EXPECT_EQ(c.mu, 0.3);
  EXPECT_EQ(c.theta, 0.01);
  EXPECT_EQ(c.gamma, 150.0);
  EXPECT_EQ(c.gap(), 0.001);
  EXPECT_EQ(c.tangential, TangentialModel::OneStep);
  EXPECT_EQ(c.position_update, PositionUpdate::StepStart);
  EXPECT_EQ(c.gravity.z, -9.81);
}

TEST(DemParameters, CylinderStackOf33) {
  const auto p = read(
      "grid:\n  cell_size: 0.0005\nsolids:\n  stack:\n    type: cylinder_stack\n    radius: 0.005\n"
      "    density: 2700\n    layers: 6\n    first_layer: 6\n    corner: [0, 0]\n"
      "  lone:\n    type: disk\n    radius: 0.01\n    density: 1000\n    center: [0.2, 0.1]\n");
  const auto s = solids_from(p);
  ASSERT_EQ(s.size(), 34u);
  for (std::size_t n = 0; n < s.size(); ++n) EXPECT_EQ(s[n].state.id, static_cast<std::int64_t>(n));
  // bottom layer: gap 2h = 1 mm to wall and floor, pitch 2r + gap = 11 mm
  EXPECT_NEAR(s[0].state.x.x, 0.006, 1e-15);
  EXPECT_NEAR(s[0].state.x.z, 0.006, 1e-15);
  EXPECT_NEAR(s[5].state.x.x, 0.006 + 5 * 0.011, 1e-15);
  // second layer (5) in the hollows, touching both below at the same gap
  EXPECT_NEAR(s[6].state.x.x, 0.006 + 0.0055, 1e-15);
  EXPECT_NEAR(core::norm(s[6].state.x - s[0].state.x), 0.011, 1e-15);
  EXPECT_NEAR(s[32].state.x.z, 0.006 + 5 * 0.011 * std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(s[0].state.mass, 2700 * 3.141592653589793 * 0.005 * 0.005, 1e-12);
  EXPECT_EQ(s[33].shape->kind(), "circle");
  EXPECT_EQ(s[33].state.x.x, 0.2);
}

TEST(DemParameters, PolygonCentroidIsTheCentre) {
  const auto p = read(
      "solids:\n  block:\n    type: polygon\n    vertices: [0, 0, 0.02, 0, 0.02, 0.01, 0, 0.01]\n"
      "    density: 500\n");
  const auto s = solids_from(p);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_NEAR(s[0].state.x.x, 0.01, 1e-15);
  EXPECT_NEAR(s[0].state.x.z, 0.005, 1e-15);
  EXPECT_NEAR(s[0].state.mass, 500 * 0.0002, 1e-15);
  {
    std::ofstream f("dem_test_triangle.txt");
    f << "# x z\n0 0\n0.03 0\n0 0.03\n";
  }
  const auto q =
      solids_from(read("solids:\n  tri:\n    type: polygon_file\n    file: "
                       "dem_test_triangle.txt\n    offset: [1, 0]\n    density: 1000\n"));
  std::remove("dem_test_triangle.txt");
  ASSERT_EQ(q.size(), 1u);
  EXPECT_NEAR(q[0].state.x.x, 1.01, 1e-14);
  EXPECT_NEAR(q[0].state.x.z, 0.01, 1e-14);
}

TEST(DemParameters, BadInputNamesKeyValueAndAllowed) {
  try {
    read("dem:\n  tangential_model: sticky\n");
    FAIL() << "accepted a bad model";
  } catch (const core::InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("tangential_model"), std::string::npos) << m;
    EXPECT_NE(m.find("sticky"), std::string::npos) << m;
    EXPECT_NE(m.find("accumulated"), std::string::npos) << m;
  }
  EXPECT_THROW(read("dem:\n  psi: 0.7\n"), core::InputError);
  EXPECT_THROW(
      read("solids:\n  a:\n    type: disk\n    radius: -1\n    density: 1\n    center: [0, 0]\n"),
      core::InputError);
  EXPECT_THROW(
      solids_from(read("solids:\n  a:\n    type: polygon\n    vertices: [0, 0, 1, 0, 1, 1, 0]\n"
                       "    density: 1\n")),
      core::InputError);
}

TEST(DemSolverInput, RegionsPerRankAndUniqueIds) {
  DemConfig c;
  c.h = 1e-3;
  const core::Box2 tank{{0, 0}, {1, 1}};
  const core::Comm self(MPI_COMM_SELF);
  EXPECT_THROW(DemSolver(self, c, {tank, tank}, tank, {}), core::InputError);
  DemSolver s(self, c, {tank}, tank, {});
  SolidSpec a;
  a.shape = std::make_shared<const geometry::Circle>(0.01);
  a.density = 1000;
  a.state.x = {0.5, 0.5};
  SolidSpec b = a;
  b.state.x = {0.2, 0.5};
  try {
    s.add_solids({a, b});
    FAIL() << "accepted a repeated id";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("id 0"), std::string::npos) << e.what();
  }
  b.density = -1;
  b.state.id = 1;
  DemSolver s2(self, c, {tank}, tank, {});
  EXPECT_THROW(s2.add_solids({a, b}), core::InputError);
}
