// Wall conditions (free-slip / no-slip ghosts, zero normal velocity) and explicit viscosity:
// a shear mode decays at the rate of the discrete Laplacian's eigenvalue (to round-off) and at
// the analytic rate nu pi^2 (1/L^2 + 1/H^2) within 1 %, on 1, 2 and 3 ranks.
#include <gtest/gtest.h>

#include <cmath>

#include "fluid_test_support.hpp"
#include "picdem/core/rng.hpp"
#include "picdem/fluid/fluid.hpp"

using namespace picdem;
using namespace picdem::grid;
using fluid_test::all_fluid;

namespace {

GridSpec make_spec(int nx, int nz, double h) {
  GridSpec s;
  s.nx = nx, s.nz = nz, s.h = h;
  return s;
}

}  // namespace

class WallTest : public ::testing::TestWithParam<bool> {};

TEST_P(WallTest, NormalZeroAndTangentialGhostsMirrored) {
  const bool no_slip = GetParam();
  const GridSpec s = make_spec(12, 9, 0.1);
  core::Comm comm;
  Decomposition d(s, comm, 2);
  Halo halo(d);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  for (FaceField* f : {&u, &w}) {
    const auto& b = f->owned();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) (*f)(i, k) = core::uniform01(7, i + 100, k + 100) - 0.5;
    halo.forward(*f);
  }
  fluid::FluidConfig cfg;
  cfg.no_slip = no_slip;
  fluid::enforce_walls(u, w, cfg, d);
  const double t = no_slip ? -1.0 : 1.0;
  int checked = 0;
  const auto& bu = u.storage();
  for (int k = bu.k0; k < bu.k1; ++k)
    for (int i = bu.i0; i < bu.i1; ++i) {
      if (k < 0 || k >= s.nz) continue;
      if (i == 0 || i == s.nx) {
        EXPECT_EQ(u(i, k), 0.0);
      }
      if (i < 0 && u.in_storage(-i, k)) {
        EXPECT_EQ(u(i, k), -u(-i, k));
        ++checked;
      }
      if (i > s.nx && u.in_storage(2 * s.nx - i, k)) {
        EXPECT_EQ(u(i, k), -u(2 * s.nx - i, k));
      }
    }
  for (int k = bu.k0; k < 0; ++k)
    for (int i = std::max(bu.i0, 0); i < std::min(bu.i1, s.nx + 1); ++i) {
      EXPECT_EQ(u(i, k), t * u(i, -k - 1));
      ++checked;
    }
  for (int k = s.nz; k < bu.k1; ++k)
    for (int i = std::max(bu.i0, 0); i < std::min(bu.i1, s.nx + 1); ++i) {
      EXPECT_EQ(u(i, k), t * u(i, 2 * s.nz - 1 - k));
      ++checked;
    }
  const auto& bw = w.storage();
  for (int k = bw.k0; k < bw.k1; ++k)
    for (int i = bw.i0; i < bw.i1; ++i) {
      if (i < 0 || i >= s.nx) continue;
      if (k == 0 || k == s.nz) {
        EXPECT_EQ(w(i, k), 0.0);
      }
      if (k < 0 && w.in_storage(i, -k)) {
        EXPECT_EQ(w(i, k), -w(i, -k));
        ++checked;
      }
    }
  for (int i = bw.i0; i < 0; ++i)
    for (int k = std::max(bw.k0, 0); k < std::min(bw.k1, s.nz + 1); ++k) {
      EXPECT_EQ(w(i, k), t * w(-i - 1, k));
      ++checked;
    }
  for (int i = s.nx; i < bw.i1; ++i)
    for (int k = std::max(bw.k0, 0); k < std::min(bw.k1, s.nz + 1); ++k) {
      EXPECT_EQ(w(i, k), t * w(2 * s.nx - 1 - i, k));
      ++checked;
    }
  // Every rank touches at least one wall on these process grids.
  EXPECT_GT(checked, 0);
  // The wall-normal faces really are zero and a no-slip ghost really flips sign.
  if (u.owned().k0 == 0 && u.owned().i0 <= 3 && 3 < u.owned().i1) {
    EXPECT_NE(u(3, 0), 0.0);
    EXPECT_EQ(u(3, -1), t * u(3, 0));
  }
}

INSTANTIATE_TEST_SUITE_P(FreeAndNoSlip, WallTest, ::testing::Values(false, true));

class ViscosityTest : public ::testing::TestWithParam<bool> {};

// u = sin(pi x / L) cos(pi z / H) (free-slip) or sin(pi x / L) sin(pi z / H) (no-slip) is an
// eigenfunction of the discrete Laplacian with the wall ghosts, eigenvalue
//   lambda = -(4/h^2) (sin^2(pi h / 2L) + sin^2(pi h / 2H)),
// so n explicit steps multiply it by (1 + dt nu lambda)^n; the continuous rate is
// exp(-nu pi^2 (1/L^2 + 1/H^2) t).
TEST_P(ViscosityTest, ShearModeDecaysAtAnalyticRate) {
  const bool no_slip = GetParam();
  const int nx = 32, nz = 16;
  const double h = 1.0 / 32, L = nx * h, H = nz * h;
  const GridSpec s = make_spec(nx, nz, h);
  core::Comm comm;
  Decomposition d(s, comm, fluid::required_halo());
  Halo halo(d);
  const auto cells = all_fluid(d);
  fluid::FluidConfig cfg;
  cfg.nu = 1e-3;
  cfg.no_slip = no_slip;
  cfg.h = h;
  const double pi = std::acos(-1.0);
  auto mode = [&](int i, int k) {
    const Vec2 p = s.position(Stagger::FaceX, i, k);
    return std::sin(pi * p.x / L) * (no_slip ? std::sin(pi * p.z / H) : std::cos(pi * p.z / H));
  };
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  const auto& b = u.owned();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) u(i, k) = mode(i, k);
  const double dt = 0.1;
  const int steps = 100;
  for (int n = 0; n < steps; ++n) fluid::apply_viscosity(u, w, cells, dt, cfg, d, halo);

  const double lambda =
      -4.0 / (h * h) *
      (std::pow(std::sin(pi * h / (2 * L)), 2) + std::pow(std::sin(pi * h / (2 * H)), 2));
  const double discrete = std::pow(1.0 + dt * cfg.nu * lambda, steps);
  const double analytic = std::exp(-cfg.nu * pi * pi * (1 / (L * L) + 1 / (H * H)) * dt * steps);
  double max_dev = 0.0, num = 0.0, den = 0.0;
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) {
      max_dev = std::max(max_dev, std::abs(u(i, k) - discrete * mode(i, k)));
      num += u(i, k) * mode(i, k), den += mode(i, k) * mode(i, k);
    }
  max_dev = comm.max(max_dev);
  const double amplitude = comm.sum(num) / comm.sum(den);
  EXPECT_LT(max_dev, 1e-12);
  EXPECT_NEAR(amplitude / analytic, 1.0, 0.01)
      << "amplitude " << amplitude << " analytic " << analytic;
  // The decay is real: about 0.61 of the initial amplitude remains.
  EXPECT_NEAR(analytic, 0.6105, 1e-3);
  // w stayed zero.
  double wmax = 0.0;
  for (int k = w.owned().k0; k < w.owned().k1; ++k)
    for (int i = w.owned().i0; i < w.owned().i1; ++i) wmax = std::max(wmax, std::abs(w(i, k)));
  EXPECT_EQ(comm.max(wmax), 0.0);
}

INSTANTIATE_TEST_SUITE_P(FreeAndNoSlip, ViscosityTest, ::testing::Values(false, true));
