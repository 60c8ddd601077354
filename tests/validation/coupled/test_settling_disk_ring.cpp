// A disk settling at the centre of a fixed ring in a viscous fluid (cases/settling_disk_ring,
// doc/viscous.md "Settling disk in a ring"), Stokes regime (Re = 0.025), against the exact Stokes
// drag of a cylinder of radius a translating at the centre of a fixed concentric cylinder of
// radius b, F = 4 pi mu U / K per unit length, K = ln(b / a) - (b^2 - a^2) / (b^2 + a^2) (the
// biharmonic stream function A r^3 + B r ln r + C r + D / r times sin theta with no-slip on both
// circles; derived with sympy for doc/viscous.md): terminal velocity U_t = (rho_s - rho_f) g a^2 K
// / (4 mu) = 12.36 mm/s for a = 0.01 m, b = 0.04 m, rho_s = 2000, rho_f = 1000 kg/m^3, nu = 1e-2
// m^2/s. The disk's vertical speed is averaged over t in [0.04, 0.06] s (steady from about 0.035 s)
// at a / h = 4 and 8: measured -1.6% and -0.6% (a / h = 16 outside CI: doc). Asserted: within 3% at
// a / h = 4, within 1.5% at a / h = 8, and the error falls with h.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "case_loader.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "ring_stokes.hpp"

using namespace picdem;

namespace {

double terminal_speed_reference() {  // a = 0.01, b = 0.04 m, rho_s = 2000, nu = 1e-2 m^2/s
  return test_support::ring_stokes_terminal_speed(0.01, 0.04, 2000.0, 1000.0, 1e-2);
}

/// Mean downward speed of the disk over t in [0.04, 0.06] s at cell size h.
double mean_settling_speed(double h) {
  core::Comm comm;
  const auto params = test_support::load_case(comm, "cases/settling_disk_ring/case.yaml",
                                              {"grid/cell_size=" + std::to_string(h)});
  test_support::print_resolution(comm, "SettlingDiskRing", params);
  coupling::Simulation sim(comm, params);
  double sum = 0.0;
  int samples = 0;
  while (sim.time() < 0.06 - 1e-9) {
    sim.step();
    if (sim.time() < 0.04 - 1e-9) continue;
    sum += -sim.dem()->gather_all().at(0).v.z;
    ++samples;
  }
  const double mean = sum / samples;
  if (comm.is_root())
    std::printf(
        "settling disk in a ring, a / h = %.0f: mean speed over [0.04, 0.06] s %.5f m/s "
        "(%d steps), reference %.5f m/s, error %+.2f%%\n",
        0.01 / h, mean, samples, terminal_speed_reference(),
        100.0 * (mean / terminal_speed_reference() - 1.0));
  return mean;
}

}  // namespace

TEST(SettlingDiskRing, TerminalSpeedMatchesTheExactStokesDrag) {
  const double ref = terminal_speed_reference();
  EXPECT_NEAR(ref, 0.012359, 1e-6);  // the figure of the case file and doc
  const double coarse = mean_settling_speed(0.0025), fine = mean_settling_speed(0.00125);
  const double e_coarse = std::abs(coarse / ref - 1.0), e_fine = std::abs(fine / ref - 1.0);
  EXPECT_LT(e_coarse, 0.03);
  EXPECT_LT(e_fine, 0.015);
  EXPECT_LT(e_fine, e_coarse);
}
