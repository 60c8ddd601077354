// apply_viscosity_implicit on the step's distributed fields (1 and 2 ranks): without bodies its
// stencil is apply_viscosity's (no-slip ghost -u = a wall at h/2, free-slip and free surface zero
// gradient), so one explicit step of apply_viscosity with -dt taken from the implicit result
// gives back the old velocity on every face between two fluid cells, to the solver's tolerance,
// with air above a fluid block (the fluid-node mask) and with either wall condition. The key
// fluid/viscosity_scheme and the explicit time-step limit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "fluid_test_support.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/rng.hpp"
#include "picdem/fluid/viscous.hpp"

using namespace picdem;
using namespace picdem::grid;

namespace {

/// The closed box both tests use: 14 x 11 cells of h = 0.1 on the communicator's ranks, nu = 0.02.
struct ViscousBox {
  GridSpec s = [] {
    GridSpec g;
    g.nx = 14, g.nz = 11, g.h = 0.1;
    return g;
  }();
  core::Comm comm;
  Decomposition d{s, comm, 1};
  Halo halo{d};
  fluid::FluidConfig cfg;
  explicit ViscousBox(bool no_slip) {
    cfg.no_slip = no_slip;
    cfg.nu = 0.02;
    cfg.h = s.h;
  }
};

}  // namespace

class ViscousStepTest : public ::testing::TestWithParam<bool> {};

TEST_P(ViscousStepTest, BackwardEulerInvertsApplyViscosity) {
  ViscousBox box(GetParam());
  auto& [s, comm, d, halo, cfg] = box;
  // Fluid below k = 8 (air above), a dry notch at the right.
  fluid::CellStates cells(d, Stagger::Cell, static_cast<signed char>(CellState::Air));
  const auto& cb = cells.storage();
  for (int k = cb.k0; k < cb.k1; ++k)
    for (int i = cb.i0; i < cb.i1; ++i)
      if (k < 8 && !(i > 10 && k > 5)) cells(i, k) = static_cast<signed char>(CellState::Fluid);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  for (FaceField* f : {&u, &w}) {
    const auto& b = f->owned();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) (*f)(i, k) = core::uniform01(3, i + 50, k + 50) - 0.5;
    halo.forward(*f);
  }
  fluid::enforce_walls(u, w, cfg, d);
  const FaceField u0 = u, w0 = w;
  const double dt = 0.2;  // nu dt / h^2 = 0.4: beyond the explicit limit 0.25
  const auto r = fluid::apply_viscosity_implicit(u, w, cells, dt, cfg, d, halo, {});
  EXPECT_GT(r.iterations, 0);
  fluid::apply_viscosity(u, w, cells, -dt, cfg, d, halo);
  auto fluid_cell = [&](int i, int k) {
    return i >= 0 && k >= 0 && i < s.nx && k < s.nz &&
           cells(i, k) == static_cast<signed char>(CellState::Fluid);
  };
  double worst = 0.0;
  int checked = 0;
  const auto& bu = u.owned();
  for (int k = bu.k0; k < bu.k1; ++k)
    for (int i = std::max(bu.i0, 1); i < std::min(bu.i1, s.nx); ++i)
      if (fluid_cell(i - 1, k) && fluid_cell(i, k))
        worst = std::max(worst, std::abs(u(i, k) - u0(i, k))), ++checked;
  const auto& bw = w.owned();
  for (int k = std::max(bw.k0, 1); k < std::min(bw.k1, s.nz); ++k)
    for (int i = bw.i0; i < bw.i1; ++i)
      if (fluid_cell(i, k - 1) && fluid_cell(i, k))
        worst = std::max(worst, std::abs(w(i, k) - w0(i, k))), ++checked;
  EXPECT_GT(comm.sum(static_cast<long long>(checked)), 100);
  EXPECT_LT(worst, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Walls, ViscousStepTest, ::testing::Values(false, true));

namespace {

/// Marches a smooth field in a closed no-slip box full of fluid (h = 0.1, 14 x 11 cells, nu =
/// 0.02) to t = 1 with `steps` steps of apply_viscosity_implicit with implicit share beta; u
/// then w, owned samples, summed over the ranks into one vector per component.
std::vector<double> march(int steps, double beta) {
  ViscousBox box(true);
  auto& [s, comm, d, halo, cfg] = box;
  fluid::CellStates cells(d, Stagger::Cell, static_cast<signed char>(CellState::Fluid));
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  const double L = s.nx * s.h, H = s.nz * s.h;
  const auto& bu = u.owned();
  for (int k = bu.k0; k < bu.k1; ++k)
    for (int i = bu.i0; i < bu.i1; ++i)
      u(i, k) = std::sin(M_PI * i * s.h / L) * std::sin(M_PI * (k + 0.5) * s.h / H);
  const auto& bw = w.owned();
  for (int k = bw.k0; k < bw.k1; ++k)
    for (int i = bw.i0; i < bw.i1; ++i)
      w(i, k) = std::sin(2.0 * M_PI * (i + 0.5) * s.h / L) * std::sin(M_PI * k * s.h / H);
  halo.forward(u);
  halo.forward(w);
  fluid::enforce_walls(u, w, cfg, d);
  for (int n = 0; n < steps; ++n)
    fluid::apply_viscosity_implicit(u, w, cells, 1.0 / steps, cfg, d, halo, {}, beta);
  const int nu_ = (s.nx + 1) * s.nz;
  std::vector<double> all(static_cast<std::size_t>(nu_ + s.nx * (s.nz + 1)), 0.0);
  for (int k = bu.k0; k < bu.k1; ++k)
    for (int i = bu.i0; i < bu.i1; ++i) all[static_cast<std::size_t>(i + (s.nx + 1) * k)] = u(i, k);
  for (int k = bw.k0; k < bw.k1; ++k)
    for (int i = bw.i0; i < bw.i1; ++i) all[static_cast<std::size_t>(nu_ + i + s.nx * k)] = w(i, k);
  comm.sum_in_place(all);
  return all;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (std::size_t n = 0; n < a.size(); ++n) m = std::max(m, std::abs(a[n] - b[n]));
  return m;
}

}  // namespace

// fluid/viscosity_scheme crank_nicolson on the step's fields: errors at t = 1 against 64 steps of
// the same scheme fall at second order with dt (backward Euler: first order), nu dt / h^2 = 0.5
// and 0.25 at 4 and 8 steps.
TEST(ViscousScheme, CrankNicolsonStepIsSecondOrderInTime) {
  core::Comm comm;
  const auto ref_cn = march(64, 0.5), ref_be = march(64, 1.0);
  const double cn4 = max_difference(march(4, 0.5), ref_cn),
               cn8 = max_difference(march(8, 0.5), ref_cn);
  const double be4 = max_difference(march(4, 1.0), ref_be),
               be8 = max_difference(march(8, 1.0), ref_be);
  const double order_cn = std::log2(cn4 / cn8), order_be = std::log2(be4 / be8);
  if (comm.is_root())
    std::printf(
        "step-level free decay to t = 1: Crank-Nicolson %.3e, %.3e (order %.2f); backward "
        "Euler %.3e, %.3e (order %.2f) at 4, 8 steps\n",
        cn4, cn8, order_cn, be4, be8, order_be);
  EXPECT_GT(order_cn, 1.8);
  EXPECT_LT(order_be, 1.3);
  EXPECT_LT(cn8, be8);
}

TEST(ViscousScheme, KeyAndTimeStepLimit) {
  // Default explicit: the limit h^2 / (4 nu); implicit: none (infinity).
  const auto expl =
      fluid::config_from(fluid_test::tank_params(0.1, 0.1, 0.001, {"fluid/viscosity=1e-3"}));
  EXPECT_FALSE(expl.implicit_viscosity);
  EXPECT_DOUBLE_EQ(fluid::viscous_time_limit(expl), 0.001 * 0.001 / (4.0 * 1e-3));
  const auto impl = fluid::config_from(fluid_test::tank_params(
      0.1, 0.1, 0.001, {"fluid/viscosity=1e-3", "fluid/viscosity_scheme=implicit"}));
  EXPECT_TRUE(impl.implicit_viscosity);
  EXPECT_TRUE(std::isinf(fluid::viscous_time_limit(impl)));
  EXPECT_DOUBLE_EQ(impl.viscous_beta, 1.0);
  const auto cn = fluid::config_from(fluid_test::tank_params(
      0.1, 0.1, 0.001, {"fluid/viscosity=1e-3", "fluid/viscosity_scheme=crank_nicolson"}));
  EXPECT_TRUE(cn.implicit_viscosity);
  EXPECT_DOUBLE_EQ(cn.viscous_beta, 0.5);
  EXPECT_TRUE(std::isinf(fluid::viscous_time_limit(cn)));
  EXPECT_THROW(fluid::config_from(
                   fluid_test::tank_params(0.1, 0.1, 0.001, {"fluid/viscosity_scheme=crank"})),
               core::InputError);
}
