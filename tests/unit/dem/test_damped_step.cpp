// dt_DEM with the dashpot (doc/dem.md, "Damped time step"): eq. 18 sizes the step on the spring
// alone, so a large dem/alpha made the explicit step unstable (a dry pile blew up at step 1 with
// alpha = 1e3). The paper's law now takes the smaller of eq. 18 and a share of the damped spring's
// stability limit omega dt < 2 (sqrt(1 + zeta^2) - zeta) of eqs. 21-24.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "dem_fixtures.hpp"
#include "picdem/dem/contact_law.hpp"

using namespace picdem;
using namespace picdem::dem;
using namespace picdem::dem::testing;

namespace {
constexpr double h = 5e-4, r = 0.01, rho = 2700.0;

DemConfig with_alpha(double alpha) {
  DemConfig c;
  c.h = h;
  c.alpha = alpha;
  return c;
}

/// x'' = -x - 2 zeta x' (time in 1 / omega) advanced by eqs. 21-24 with U^n = U_{k-1}, n steps of
/// u = omega dt from x = 1; returns |x| + |x'| at the end.
double damped_spring(double u, double zeta, int n) {
  const auto f = [zeta](double x, double v) { return -x - 2.0 * zeta * v; };
  double x = 1.0, v = 0.0;
  for (int k = 0; k < n; ++k) {
    const double va = v + u * f(x, v), xa = x + 0.5 * u * (v + va);
    const double vn = v + 0.5 * u * (f(x, v) + f(xa, va));
    x += 0.5 * u * (v + vn);
    v = vn;
  }
  return std::abs(x) + std::abs(v);
}

/// A pile of 10 disks (rows of 4, 3, 2, 1), each touching its neighbours' and the floor's
/// imaginary boundaries at rest.
std::vector<SolidSpec> pile(const DemConfig& cfg) {
  std::vector<SolidSpec> s;
  const double d = 2.0 * r + cfg.gap(), x0 = 0.05;
  for (int row = 0; row < 4; ++row)
    for (int i = 0; i < 4 - row; ++i)
      s.push_back(disk(static_cast<std::int64_t>(s.size()), r, rho,
                       {x0 + (i + 0.5 * row) * d, r + cfg.gap() + row * d * std::sqrt(3.0) / 2}));
  return s;
}

double mechanical_energy(const std::vector<core::SolidState>& s, double g) {
  double e = kinetic_energy(s);
  for (const auto& b : s) e += b.mass * g * b.x.z;
  return e;
}
}  // namespace

// The limit is that of eqs. 21-24: just below it a damped spring decays, just above it grows
// (u = omega dt; the predictor-corrector's characteristic polynomial gives
// 1 - tr + det = u^2 (4 - 4 zeta u - u^2) / 8 for U^n of the step and u^2 (1 - zeta u - u^2 / 4)
// for U_{k-1}: the same root).
TEST(DampedStep, LimitOfThePredictorCorrector) {
  for (double zeta : {0.0, 0.4, 1.0, 10.0, 1414.2}) {
    const double u = 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta);
    const double below = damped_spring(0.99 * u, zeta, 2000),
                 above = damped_spring(1.01 * u, zeta, 2000);
    std::printf(
        "zeta %g: omega dt limit %.6g; |x| + |v| after 2000 steps at 0.99x %.3e, 1.01x %.3e\n",
        zeta, u, below, above);
    EXPECT_LT(below, 1.0);
    EXPECT_GT(above, 1e3);
  }
}

// At the default alpha eq. 18 is the smaller, so dt_DEM is the paper's bit for bit (for equal and
// unequal masses); a large alpha takes the damped limit.
TEST(DampedStep, PaperStepAtTheDefaultAlphaDampedLimitAtLargeAlpha) {
  const DemConfig paper = with_alpha(0.4);
  for (double ratio : {1.0, 10.0, 1000.0}) {
    const auto law = linear_spring_dashpot(paper)->for_masses(1.0, ratio);
    const double eq18 =
        ratio == 1.0 ? dem_time_step(paper) : dem_time_step(paper) * std::sqrt(1.0 / ratio);
    EXPECT_EQ(law->time_step(1.0, ratio), eq18);
    EXPECT_LT(eq18, damped_step_limit(paper, ratio));
  }
  const DemConfig big = with_alpha(1e3);
  const auto law = linear_spring_dashpot(big)->for_masses(1.0, 1.0);
  EXPECT_EQ(law->time_step(1.0, 1.0), damped_step_limit(big, 1.0));
  // the tangential-rotational mode of two disks binds: omega_t = omega_n sqrt(3 / 2.6), zeta_t =
  // sqrt(6) alpha
  const double w_n = std::sqrt(2.0 * 9.81 / (0.01 * h)), w_t = w_n * std::sqrt(3.0 / 2.6);
  const double z_t = std::sqrt(6.0) * 1e3;
  // 2 (sqrt(1 + z^2) - z) written as 2 / (sqrt(1 + z^2) + z), which does not cancel
  const double want = kDampedStepShare * 2.0 / ((std::sqrt(1.0 + z_t * z_t) + z_t) * w_t);
  EXPECT_NEAR(law->time_step(1.0, 1.0), want, 1e-9 * want);
}

// A dry pile at alpha = 1e3 (zeta = 1414 between disks): with eq. 18's step it blew up at the first
// step; with the damped step its mechanical energy (kinetic + gravity; the springs start unloaded)
// never exceeds the initial one and every disk stays in the tank.
TEST(DampedStep, PileAtLargeAlphaDoesNotGainEnergy) {
  const DemConfig cfg = with_alpha(1e3);
  DemSolver s = solver(cfg, 0.2, 0.2);
  s.add_solids(pile(cfg));
  const double g = 9.81, e0 = mechanical_energy(s.owned(), g);
  double worst = -1e300;
  for (int n = 0; n < 100; ++n) {
    s.advance(1e-4, {});
    worst = std::max(worst, mechanical_energy(s.owned(), g) - e0);
    for (const auto& b : s.owned()) {
      ASSERT_TRUE(std::isfinite(b.x.x) && std::isfinite(b.x.z))
          << "solid " << b.id << " step " << n;
      ASSERT_GT(b.x.z, 0.0);
      ASSERT_LT(b.x.z, 0.2);
    }
  }
  std::printf(
      "alpha 1e3: dt_DEM %.4g s (eq. 18: %.4g s), %d subcycles a step; worst energy gain "
      "%.3e J of %.4f J, drop after 0.01 s %.3e J\n",
      s.dt_dem(), dem_time_step(cfg), s.last_subcycles(), worst, e0,
      e0 - mechanical_energy(s.owned(), g));
  EXPECT_LE(worst, 1e-12 * e0);
  EXPECT_GT(e0 - mechanical_energy(s.owned(), g), 0.0);  // it settles
}
