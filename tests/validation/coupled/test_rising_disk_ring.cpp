// A light disk rising from the centre of a fixed ring in a viscous fluid (cases/rising_disk_ring,
// doc/viscous.md "Rising disk in a ring"), Stokes regime (Re = 0.005), the mirror of
// test_settling_disk_ring: the exact Stokes drag of a cylinder of radius a translating at the
// centre of a fixed concentric cylinder of radius b, F = 4 pi mu U / K per unit length, K = ln(b /
// a) - (b^2 - a^2) / (b^2 + a^2) (Happel & Brenner 1965), gives the terminal velocity U_t = (rho_f
// - rho_s) g a^2 K / (4 mu) = 2.472 mm/s upwards for a = 0.01 m, b = 0.04 m, rho_s = 800, rho_f =
// 1000 kg/m^3, nu = 1e-2 m^2/s. The disk's rise speed is averaged over t in [0.10, 0.15] s (the
// rise is steady from about 0.08 s; by 0.15 s the disk has moved 0.35 mm, 0.009 b) at a / h = 4
// and 8 (a / h = 16 outside CI: doc), with its spin (the split makes it grow from round-off for
// this light disk; fluid/viscous_rotation_rows solves it with the fluid) below 1% of U_t / a.
// Measured +0.11% and -0.15% at a / h = 4 and 8 (a / h = 16: doc), largest |omega| 4.9e-6 and
// 4.4e-7 rad/s (the split alone: 0.14 rad/s by 0.06 s at a / h = 4). Asserted: within 1% at both
// (the a / h = 8 rise still gains 0.25% between [0.10, 0.12] and [0.12, 0.15] s, so the two errors
// are within the remaining transient of each other and no order is claimed: the error is not
// asserted to fall), spin below 1% of U_t / a.
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

double terminal_speed_reference() {  // a = 0.01, b = 0.04 m, rho_s = 800, nu = 1e-2 m^2/s
  return test_support::ring_stokes_terminal_speed(0.01, 0.04, 800.0, 1000.0, 1e-2);
}

struct Rise {
  double speed = 0.0;  ///< mean upward speed over [0.10, 0.15] s
  double spin = 0.0;   ///< largest |omega| over the run
};

Rise rise_at(double h) {
  core::Comm comm;
  const auto params = test_support::load_case(comm, "cases/rising_disk_ring/case.yaml",
                                              {"grid/cell_size=" + std::to_string(h)});
  test_support::print_resolution(comm, "RisingDiskRing", params);
  coupling::Simulation sim(comm, params);
  Rise r;
  int samples = 0;
  while (sim.time() < 0.15 - 1e-9) {
    sim.step();
    const auto disk = sim.dem()->gather_all().at(0);
    r.spin = std::max(r.spin, std::abs(disk.omega));
    if (sim.time() < 0.10 - 1e-9) continue;
    r.speed += disk.v.z;
    ++samples;
  }
  r.speed /= samples;
  if (comm.is_root())
    std::printf(
        "rising disk in a ring, a / h = %.0f: mean rise speed over [0.10, 0.15] s %.6f m/s (%d "
        "steps), reference %.6f m/s, error %+.2f%%; largest |omega| %.3e rad/s\n",
        0.01 / h, r.speed, samples, terminal_speed_reference(),
        100.0 * (r.speed / terminal_speed_reference() - 1.0), r.spin);
  return r;
}

}  // namespace

TEST(RisingDiskRing, TerminalSpeedMatchesTheExactStokesDrag) {
  const double ref = terminal_speed_reference();
  EXPECT_NEAR(ref, 0.0024718, 1e-7);  // the figure of the case file and doc
  const Rise coarse = rise_at(0.0025), fine = rise_at(0.00125);
  const double e_coarse = std::abs(coarse.speed / ref - 1.0);
  const double e_fine = std::abs(fine.speed / ref - 1.0);
  EXPECT_LT(e_coarse, 0.01);
  EXPECT_LT(e_fine, 0.01);
  for (const Rise* r : {&coarse, &fine}) EXPECT_LT(r->spin, 0.01 * ref / 0.01);
}
