// Per-wall conditions (fluid/wall_left, _right, _bottom, _top over fluid/walls). A film on a
// no-slip floor under a free-slip lid is half a plane Poiseuille channel: driven by G along x,
// u(z) = G / (2 nu) z (2 H - z). Its discrete form through the explicit operator (apply_viscosity,
// marched to the steady state) and the implicit one (the stencil's steady solve) is second order:
// the no-slip ghost -u puts the wall at h/2 through a straight line, which shifts the discrete
// profile by G h^2 / (8 nu), i.e. h^2 / (4 H^2) of the largest speed. The keys reach both step
// operators: the implicit step inverts the explicit one with mixed walls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "fluid_test_support.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/rng.hpp"
#include "picdem/fluid/viscous.hpp"

using namespace picdem;
using namespace picdem::grid;
using core::Vec2;
using fluid::TankWall;
using fluid_test::all_fluid;

namespace {

constexpr double kNu = 1.0, kG = 1.0, kH = 1.0;
constexpr double kUmax = kG * kH * kH / (2.0 * kNu);

/// Half-Poiseuille: no-slip floor at z = 0, free-slip lid at z = H.
double half_poiseuille(double z) {
  return kG / (2.0 * kNu) * z * (2.0 * kH - z);
}

double order(double coarse, double fine) {
  return std::log2(coarse / fine);
}

/// Explicit: gravity G along x and apply_viscosity marched from rest to t = 8 H^2 / nu (the
/// slowest mode, nu pi^2 / (4 H^2), down by e^-20) in a tank 16 H long; the end walls (u = 0)
/// reach the middle column as e^(-pi 8 H / (2 H)) ~ 4e-6. Largest error there / U_max.
double explicit_error(int n) {
  GridSpec s;
  s.nz = n, s.nx = 16 * n, s.h = kH / n;
  core::Comm comm;
  Decomposition d(s, comm, 1);
  Halo halo(d);
  fluid::FluidConfig cfg = fluid::config_from(fluid_test::tank_params(
      16.0 * kH, kH, s.h, {"fluid/walls=free_slip", "fluid/wall_bottom=no_slip"}));
  cfg.nu = kNu, cfg.g = {kG, 0.0};
  const fluid::CellStates cells = all_fluid(d);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  const double dt = 0.2 * s.h * s.h / kNu;
  const int steps = static_cast<int>(std::ceil(8.0 * kH * kH / kNu / dt));
  for (int step = 0; step < steps; ++step) {
    fluid::apply_gravity(u, w, cells, dt, cfg);
    fluid::apply_viscosity(u, w, cells, dt, cfg, d, halo);
    halo.forward(u), halo.forward(w);
    fluid::enforce_walls(u, w, cfg, d);
  }
  double worst = 0.0;
  const int im = s.nx / 2;
  const auto& b = u.owned();
  if (im >= b.i0 && im < b.i1)
    for (int k = b.k0; k < b.k1; ++k)
      worst = std::max(worst, std::abs(u(im, k) - half_poiseuille((k + 0.5) * s.h)));
  return comm.max(worst) / kUmax;
}

/// Implicit: the stencil's steady solve -nu L u = G with no-slip bottom, free-slip top (per-side
/// ViscousWalls), the end walls given the exact profile (a periodic direction's stand-in).
double implicit_error(int n) {
  const fluid::ViscousGrid g{{0.0, 0.0}, kH / n, 2 * n, n};
  fluid::ViscousWalls walls;
  walls.kind = fluid::WallKind::Prescribed;
  walls.velocity = [](const Vec2& x) { return Vec2{half_poiseuille(x.z), 0.0}; };
  walls.side[static_cast<std::size_t>(TankWall::Bottom)] = fluid::WallKind::NoSlip;
  walls.side[static_cast<std::size_t>(TankWall::Top)] = fluid::WallKind::FreeSlip;
  const auto su = fluid::build_viscous_stencil(0, g, {}, walls);
  std::vector<double> u(su.unknown_of.size(), 0.0), f(su.unknown_of.size(), kG);
  fluid::solve_viscous_implicit(su, kNu, std::numeric_limits<double>::infinity(), f, u);
  double worst = 0.0;
  for (int node : su.node_of)
    worst = std::max(worst, std::abs(u[static_cast<std::size_t>(node)] -
                                     half_poiseuille(su.position(node, g).z)));
  return worst / kUmax;
}

}  // namespace

TEST(WallSides, HalfPoiseuilleExplicit) {
  const double e8 = explicit_error(8), e16 = explicit_error(16);
  std::printf(
      "explicit half-Poiseuille: max error / U_max %.3e %.3e (h^2/(4H^2): %.3e %.3e), "
      "order %.2f\n",
      e8, e16, 0.25 / 64, 0.25 / 256, order(e8, e16));
  // The discrete profile's shift h^2 / (4 H^2), 1 % allowed for the end walls and the transient.
  EXPECT_LT(e8, 1.01 * 0.25 / 64);
  EXPECT_LT(e16, 1.01 * 0.25 / 256);
  EXPECT_GT(order(e8, e16), 1.9);
}

TEST(WallSides, HalfPoiseuilleImplicit) {
  const double e8 = implicit_error(8), e16 = implicit_error(16), e32 = implicit_error(32);
  std::printf("implicit half-Poiseuille: max error / U_max %.3e %.3e %.3e, orders %.2f %.2f\n", e8,
              e16, e32, order(e8, e16), order(e16, e32));
  // No more than the discrete profile's shift h^2 / (4 H^2) (the exact end walls pull it down).
  EXPECT_LT(e32, 1.01 * 0.25 / (32.0 * 32.0));
  EXPECT_GT(order(e16, e32), 1.9);
}

TEST(WallSides, KeysDefaultToWallsAndNameTheirValue) {
  const auto same =
      fluid::config_from(fluid_test::tank_params(1.0, 1.0, 0.1, {"fluid/walls=no_slip"}));
  for (TankWall wall : {TankWall::Left, TankWall::Right, TankWall::Bottom, TankWall::Top})
    EXPECT_TRUE(fluid::no_slip_at(same, wall));
  const auto mixed = fluid::config_from(fluid_test::tank_params(
      1.0, 1.0, 0.1,
      {"fluid/walls=no_slip", "fluid/wall_top=free_slip", "fluid/wall_left=default"}));
  EXPECT_TRUE(fluid::no_slip_at(mixed, TankWall::Left));
  EXPECT_TRUE(fluid::no_slip_at(mixed, TankWall::Right));
  EXPECT_TRUE(fluid::no_slip_at(mixed, TankWall::Bottom));
  EXPECT_FALSE(fluid::no_slip_at(mixed, TankWall::Top));
  const auto walls = fluid::viscous_walls_of(mixed);
  EXPECT_EQ(walls.kind_at(TankWall::Bottom), fluid::WallKind::NoSlip);
  EXPECT_EQ(walls.kind_at(TankWall::Top), fluid::WallKind::FreeSlip);
  try {
    fluid::config_from(fluid_test::tank_params(1.0, 1.0, 0.1, {"fluid/wall_right=sticky"}));
    ADD_FAILURE() << "fluid/wall_right=sticky accepted";
  } catch (const core::InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("fluid/wall_right"), std::string::npos) << msg;
    EXPECT_NE(msg.find("sticky"), std::string::npos) << msg;
  }
}

// The per-wall keys reach both operators of the step: apply_viscosity with -dt taken from
// apply_viscosity_implicit's result gives back the old velocity (as test_viscous_step with one
// condition on all walls) with no-slip left and top walls, free-slip right and bottom ones; and the
// result differs from the all-free-slip one.
TEST(WallSides, ImplicitStepInvertsExplicitWithMixedWalls) {
  GridSpec s;
  s.nx = 14, s.nz = 11, s.h = 0.1;
  core::Comm comm;
  Decomposition d(s, comm, 1);
  Halo halo(d);
  fluid::FluidConfig cfg = fluid::config_from(fluid_test::tank_params(
      1.4, 1.1, s.h,
      {"fluid/walls=free_slip", "fluid/wall_left=no_slip", "fluid/wall_top=no_slip"}));
  cfg.nu = 0.02;
  fluid::FluidConfig free_cfg = cfg;
  free_cfg.wall_no_slip = {};
  // All fluid but a dry notch at the lower right.
  fluid::CellStates cells = all_fluid(d);
  const auto& cb = cells.storage();
  for (int k = cb.k0; k < cb.k1; ++k)
    for (int i = cb.i0; i < cb.i1; ++i)
      if (i > 10 && i < s.nx && k >= 0 && k < 3)
        cells(i, k) = static_cast<signed char>(CellState::Air);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  for (FaceField* f : {&u, &w}) {
    const auto& b = f->owned();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) (*f)(i, k) = core::uniform01(5, i + 50, k + 50) - 0.5;
    halo.forward(*f);
  }
  fluid::enforce_walls(u, w, cfg, d);
  const FaceField u0 = u, w0 = w;
  FaceField uf = u, wf = w;
  const double dt = 0.2;  // nu dt / h^2 = 0.4: beyond the explicit limit 0.25
  fluid::apply_viscosity_implicit(u, w, cells, dt, cfg, d, halo, {});
  fluid::apply_viscosity_implicit(uf, wf, cells, dt, free_cfg, d, halo, {});
  double differs = 0.0;
  const auto& bu = u.owned();
  const auto& bw = w.owned();
  for (int k = bu.k0; k < bu.k1; ++k)
    for (int i = bu.i0; i < bu.i1; ++i) differs = std::max(differs, std::abs(u(i, k) - uf(i, k)));
  for (int k = bw.k0; k < bw.k1; ++k)
    for (int i = bw.i0; i < bw.i1; ++i) differs = std::max(differs, std::abs(w(i, k) - wf(i, k)));
  EXPECT_GT(comm.max(differs), 1e-2);
  fluid::apply_viscosity(u, w, cells, -dt, cfg, d, halo);
  auto fluid_cell = [&](int i, int k) {
    return i >= 0 && k >= 0 && i < s.nx && k < s.nz &&
           cells(i, k) == static_cast<signed char>(CellState::Fluid);
  };
  double worst = 0.0;
  long long checked = 0;
  for (int k = bu.k0; k < bu.k1; ++k)
    for (int i = std::max(bu.i0, 1); i < std::min(bu.i1, s.nx); ++i)
      if (fluid_cell(i - 1, k) && fluid_cell(i, k))
        worst = std::max(worst, std::abs(u(i, k) - u0(i, k))), ++checked;
  for (int k = std::max(bw.k0, 1); k < std::min(bw.k1, s.nz); ++k)
    for (int i = bw.i0; i < bw.i1; ++i)
      if (fluid_cell(i, k - 1) && fluid_cell(i, k))
        worst = std::max(worst, std::abs(w(i, k) - w0(i, k))), ++checked;
  EXPECT_GT(comm.sum(checked), 200);
  EXPECT_LT(comm.max(worst), 1e-9);
}
