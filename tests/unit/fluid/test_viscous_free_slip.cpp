// Free-slip obstacles in the implicit viscous operator (obstacles/<name>/wall: free_slip,
// ViscousBody::free_slip, doc/viscous.md): a film of depth H = 0.5 on a no-slip floor under a
// free-slip box obstacle filling z >= H, driven by G along x, is half a plane Poiseuille channel,
// u(z) = G z (2 H - z) / (2 nu); under a no-slip box the full channel, u = G z (H - z) / (2 nu).
// The tank's side walls get the exact profile (they stand in for a periodic direction). And the
// key reaches FluidConfig::obstacle_free_slip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "picdem/core/error.hpp"
#include "picdem/fluid/viscous.hpp"
#include "picdem/geometry/obstacles.hpp"

using namespace picdem;
using core::Vec2;

namespace {

/// Largest nodal error of u / U_max at n cells over the unit square.
double film_error(int n, bool free_slip) {
  const double nu = 0.01, G = 0.02, H = 0.5;
  auto exact = [=](const Vec2& x) {
    const double z = std::min(x.z, H);
    return Vec2{free_slip ? G * z * (2 * H - z) / (2 * nu) : G * z * (H - z) / (2 * nu), 0.0};
  };
  fluid::ViscousBody lid{[=](const Vec2& x) { return x.z >= H; }, {}, 0.0, {}};
  lid.free_slip = free_slip;
  const fluid::ViscousWalls walls{fluid::WallKind::Prescribed, exact};
  const fluid::ViscousGrid g{{0.0, 0.0}, 1.0 / n, n, n};
  const auto su = fluid::build_viscous_stencil(0, g, {lid}, walls);
  std::vector<double> u(su.unknown_of.size(), 0.0);
  fluid::solve_viscous_implicit(su, nu, std::numeric_limits<double>::infinity(),
                                std::vector<double>(u.size(), G), u);
  double e = 0.0;
  for (int node : su.node_of) e = std::max(e, std::abs(u[node] - exact(su.position(node, g)).x));
  const double u_max = free_slip ? G * H * H / (2 * nu) : G * H * H / (8 * nu);
  return e / u_max;
}

}  // namespace

TEST(ViscousFreeSlip, FilmUnderAFreeSlipObstacle) {
  const double e16 = film_error(16, true), e32 = film_error(32, true), e64 = film_error(64, true);
  const double n16 = film_error(16, false), n64 = film_error(64, false);
  std::printf(
      "film under a free-slip box: max error / U_max %.3e %.3e %.3e (orders %.2f %.2f); under a "
      "no-slip box %.3e %.3e\n",
      e16, e32, e64, std::log2(e16 / e32), std::log2(e32 / e64), n16, n64);
  EXPECT_LT(e64, 1e-3);
  EXPECT_GT(std::log2(e32 / e64), 1.8);
  EXPECT_LT(n64, 1e-3);  // the same obstacle no-slip: the full channel
}

TEST(ViscousFreeSlip, KeyReachesTheFluidConfig) {
  core::ParamSchema schema;
  grid::declare_parameters(schema);
  fluid::declare_parameters(schema);
  geometry::declare_obstacle_parameters(schema);
  const std::string yaml =
      "grid: {length: 0.4, height: 0.2, cell_size: 0.01}\n"
      "obstacles:\n"
      "  a: {type: box, lo: [0.1, 0.0], hi: [0.2, 0.05], wall: free_slip}\n"
      "  b: {type: box, lo: [0.3, 0.0], hi: [0.35, 0.05]}\n";
  const auto cfg = fluid::config_from(core::read_case_text(yaml, "test", {}, schema));
  ASSERT_EQ(cfg.obstacle_free_slip.size(), 2u);
  EXPECT_TRUE(cfg.obstacle_free_slip[0]);
  EXPECT_FALSE(cfg.obstacle_free_slip[1]);
  try {
    core::read_case_text(yaml, "test", {"obstacles/b/wall=slippery"}, schema);
    FAIL() << "an unknown wall value was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("obstacles/b/wall"), std::string::npos) << e.what();
  }
}
