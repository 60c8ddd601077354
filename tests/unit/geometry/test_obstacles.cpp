// Obstacles from the case file: every variant builds valid polygons, the cut cells of a fall
// pipe with a funnel and holes keep the divergence identity and the exact covered area, and bad
// geometry is an InputError naming the key.
#include <gtest/gtest.h>

#include <map>

#include "picdem/core/error.hpp"
#include "picdem/core/params.hpp"
#include "picdem/geometry/obstacles.hpp"
#include "picdem/geometry/polygon.hpp"

using namespace picdem;
using namespace picdem::geometry;

namespace {

core::Params read(const std::string& yaml) {
  core::ParamSchema s;
  declare_obstacle_parameters(s);
  return core::read_case_text(yaml, "case.yaml", {}, s);
}

std::string error_of(const std::string& yaml) {
  try {
    obstacles_from(read(yaml));
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

double area(const std::vector<Vec2>& v) {
  double a2 = 0;
  for (std::size_t j = 0; j < v.size(); ++j) a2 += core::cross(v[j], v[(j + 1) % v.size()]);
  return 0.5 * a2;
}

const char* kPipe = R"(
obstacles:
  pipe:
    type: fall_pipe
    centre_x: 0.5
    inner_width: 0.1
    wall_thickness: 0.02
    bottom: 0.2
    top: 0.8
    funnel_top_width: 0.3
    funnel_height: 0.1
    hole_size: 0.03
    hole_spacing: 0.1
  slope:
    type: polyline
    x: [0.02, 0.3, 0.45]
    z: [0.3, 0.1, 0.05]
    thickness: 0.02
  block:
    type: polygon
    x: [0.7, 0.9, 0.8]
    z: [0.1, 0.1, 0.3]
  floor_step:
    type: box
    lo: [0.6, 0.0]
    hi: [1.0, 0.05]
)";

}  // namespace

TEST(Obstacles, VariantsBuildTheExpectedPolygons) {
  const auto obs = obstacles_from(read(kPipe));
  ASSERT_EQ(obs.size(), 4u);
  EXPECT_EQ(obs[0].name, "pipe");
  // holes centred at 0.25, 0.35, ..., 0.75 -> 7 wall pieces per side, plus 2 funnel walls
  EXPECT_EQ(obs[0].polygons.size(), 2u * 7u + 2u);
  double wall = 0;
  for (const auto& p : obs[0].polygons) wall += area(p);
  // two walls of 0.6 minus 6 holes of 0.03, 0.02 thick; funnel walls: parallelograms 0.02 x 0.1
  EXPECT_NEAR(wall, 2 * 0.02 * (0.6 - 6 * 0.03) + 2 * 0.02 * 0.1, 1e-14);
  ASSERT_EQ(obs[1].polygons.size(), 1u);
  EXPECT_EQ(obs[1].polygons[0].size(), 6u);
  // a thick polyline's area is thickness x length (mitred joints)
  const double L = std::hypot(0.28, 0.2) + std::hypot(0.15, 0.05);
  EXPECT_NEAR(area(obs[1].polygons[0]), 0.02 * L, 1e-14);
  EXPECT_NEAR(area(obs[2].polygons[0]), 0.02, 1e-15);
  EXPECT_NEAR(area(obs[3].polygons[0]), 0.02, 1e-15);
  const auto lines = outlines(obs[0]);
  ASSERT_EQ(lines.size(), obs[0].polygons.size());
  EXPECT_EQ(lines[0].size(), 5u);
  EXPECT_EQ(lines[0].front(), lines[0].back());
}

TEST(Obstacles, CutCellsOfAPerforatedFallPipe) {
  const auto obs = obstacles_from(read(kPipe));
  const double h = 1.0 / 97;  // not aligned with any obstacle edge
  const GridWindow w{{0.0, 0.0}, h, {0, 97, 0, 97}};
  CutCellOptions opt;
  opt.tiny_fraction = 0.0;
  const CutCells cc = build_cut_cells(w, {}, obs, opt);
  std::map<std::pair<int, int>, Vec2> ndl;
  for (const auto& p : cc.pieces) {
    ndl[{p.i, p.k}] += p.n_dl;
    EXPECT_LT(p.body, 0);
    EXPECT_EQ(p.r_cross_n_dl, 0.0);
  }
  double covered = 0, worst = 0;
  for (int k = 0; k < 97; ++k) {
    for (int i = 0; i < 97; ++i) {
      const Vec2 r =
          Vec2{cc.E_x(i + 1, k) - cc.E_x(i, k), cc.E_z(i, k + 1) - cc.E_z(i, k)} - ndl[{i, k}];
      worst = std::max({worst, std::fabs(r.x) / h, std::fabs(r.z) / h});
      covered += (1.0 - cc.fluid_fraction(i, k)) * h * h;
    }
  }
  EXPECT_LT(worst, 1e-12);
  double expected = 0;
  for (const auto& o : obs) {
    for (const auto& p : o.polygons) expected += area(p);
  }
  EXPECT_NEAR(covered, expected, 1e-12 * expected);
  // Through a hole (centre z = 0.35) the wall faces are open; between holes they are closed.
  const int k_hole = static_cast<int>(0.35 / h);
  const int k_wall = static_cast<int>(0.30 / h);
  const int i_wall = static_cast<int>((0.5 - 0.05 - 0.01) / h);  // inside the left wall
  EXPECT_GT(cc.E_z(i_wall, k_hole), 0.0);
  EXPECT_EQ(cc.fluid_fraction(i_wall, k_hole), 1.0);
  EXPECT_LT(cc.fluid_fraction(i_wall, k_wall), 1.0);
  EXPECT_EQ(cc.cutting_obstacle(i_wall, k_wall), 0);
  EXPECT_EQ(cc.cutting_body(i_wall, k_wall), -1);
}

TEST(Obstacles, BadGeometryNamesTheKey) {
  EXPECT_NE(error_of("obstacles:\n  b:\n    type: polygon\n    x: [0, 0, 1]\n    z: [0, 1, 0]\n")
                .find("clockwise"),
            std::string::npos);
  EXPECT_NE(error_of("obstacles:\n  b:\n    type: polygon\n    x: [0, 1, 1, 0]\n    z: [0, 0, 1]\n")
                .find("obstacles/b/z"),
            std::string::npos);
  const std::string funnel = error_of(
      "obstacles:\n  p:\n    type: fall_pipe\n    centre_x: 0.5\n    inner_width: 0.2\n"
      "    wall_thickness: 0.01\n    bottom: 0.1\n    top: 0.5\n    funnel_top_width: 0.1\n"
      "    funnel_height: 0.1\n");
  EXPECT_NE(funnel.find("funnel_top_width"), std::string::npos) << funnel;
  EXPECT_NE(funnel.find("obstacles/p"), std::string::npos) << funnel;
  EXPECT_NE(error_of("obstacles:\n  s:\n    type: polyline\n    x: [0, 1, 0]\n    z: [0, 0, 0.01]\n"
                     "    thickness: 0.1\n")
                .find("sharper"),
            std::string::npos);
  // A perforated pipe's hole count is bounded before the holes are laid out: with a top of 1e30
  // the loop over the holes would not end (zc + spacing == zc).
  const std::string holes = error_of(
      "obstacles:\n  p:\n    type: fall_pipe\n    centre_x: 0.5\n    inner_width: 0.2\n"
      "    wall_thickness: 0.01\n    bottom: 0.1\n    top: 1e30\n    hole_size: 0.001\n"
      "    hole_spacing: 0.02\n");
  EXPECT_NE(holes.find("holes per wall; allowed: at most 10000"), std::string::npos) << holes;
  EXPECT_EQ(error_of("obstacles:\n  p:\n    type: fall_pipe\n    centre_x: 0.5\n"
                     "    inner_width: 0.2\n    wall_thickness: 0.01\n    bottom: 0.0\n"
                     "    top: 199.0\n    hole_size: 0.001\n    hole_spacing: 0.02\n"),
            "");  // 9,950 holes: allowed
  EXPECT_EQ(error_of("obstacles: {}\n"), "");
}
