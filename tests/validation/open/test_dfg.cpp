// DFG benchmark 2D-1 (Schaefer & Turek 1996; cases/dfg_2d1, doc/validation.md "DFG 2D-1"): flow
// around a cylinder (D = 0.1 m) in a channel, Re = 20, steady. c_D = 2 F_x / (rho U^2 D), c_L =
// 2 F_z / (rho U^2 D) with U = 0.2 m/s the mean inflow, F the pressure and viscous loads on the
// cylinder (forces.csv's), Delta p = p(0.15, 0.2) - p(0.25, 0.2) (each extrapolated linearly from
// the two cells outside the cylinder along z = 0.2, the mean of the rows above and below).
// Averaged over t in [3, 4] s (steady from about 2 s to the particles' noise). References 5.5795,
// 0.0106, 0.1175. The cell sizes that fit the benchmark's 2.2 m x 0.41 m exactly are 0.41 m / (41
// n): h = 0.01 and 0.005 m here (D / h = 10, 20; 0.0025 m is beyond CI). The case runs the paper's
// transfer, pure FLIP (`transfer/flip_ratio: 1.0`): the default's 5% PIC share is a viscosity of
// order (1 - flip_ratio) h^2 / dt that made c_D +4.75% and +2.66% here, and +4.18% at half the
// time step (doc/validation.md, "DFG 2D-1"). Asserted: c_D within the 1% at h = 0.005 m
// (measured from forces.csv every 0.02 s: +0.78%; +1.43% at h = 0.01 m), and its error smaller
// there than at h = 0.01 m. Delta p is printed, not asserted: its error has not fallen
// monotonically at every setting tried (doc/validation.md), nor is c_L (its reference, 0.0106, is
// below the particles' noise here).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "case_loader.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/run/forces.hpp"

using namespace picdem;

namespace {

constexpr double kCd = 5.5795, kCl = 0.0106, kDp = 0.1175;

struct Figures {
  double cd = 0.0, cl = 0.0, dp = 0.0;
};

/// p at (x, 0.2) extrapolated from the cells centred at x + dir h / 2 and x + 3 dir h / 2, the
/// mean of the rows below and above z = 0.2 (a face line at the cell sizes run).
double surface_pressure(const fluid::FluidState& f, double x, double dir, double h) {
  double sum = 0.0;
  for (double z : {0.2 - 0.5 * h, 0.2 + 0.5 * h}) {
    const double p1 = f.pressure_at({x + 0.5 * dir * h, z});
    const double p2 = f.pressure_at({x + 1.5 * dir * h, z});
    sum += 1.5 * p1 - 0.5 * p2;  // linear, to the surface half a cell from the first centre
  }
  return 0.5 * sum;
}

Figures run_dfg(double h) {
  core::Comm comm(MPI_COMM_WORLD);
  const auto params = test_support::load_case(
      comm, "cases/dfg_2d1/case.yaml", {"grid/cell_size=" + std::to_string(h), "time/end=4.0"});
  test_support::print_resolution(comm, "DFG 2D-1", params);
  coupling::Simulation sim(comm, params);
  const double U = 0.2, D = 0.1, rho = 1.0, scale = 2.0 / (rho * U * U * D);
  Figures mean;
  int samples = 0;
  while (sim.time() < 4.0 - 1e-9) {
    sim.step();
    if (sim.time() < 3.0 - 1e-9) continue;
    for (const auto& b : run::body_forces(sim))
      if (b.obstacle) {
        mean.cd += scale * (b.pressure.x + b.viscous.x);
        mean.cl += scale * (b.pressure.z + b.viscous.z);
      }
    const auto& f = sim.fluid();
    mean.dp += surface_pressure(f, 0.15, -1.0, h) - surface_pressure(f, 0.25, 1.0, h);
    ++samples;
  }
  mean.cd /= samples, mean.cl /= samples, mean.dp /= samples;
  if (comm.is_root())
    std::printf(
        "DFG 2D-1 at h = %.4f m (D / h = %.0f), mean over t in [3, 4] s (%d steps): c_D = %.4f "
        "(%+.2f%% of 5.5795), c_L = %.4f (ref 0.0106), Delta p = %.4f Pa (%+.2f%% of 0.1175)\n",
        h, D / h, samples, mean.cd, 100.0 * (mean.cd / kCd - 1.0), mean.cl, mean.dp,
        100.0 * (mean.dp / kDp - 1.0));
  return mean;
}

}  // namespace

TEST(Dfg, Benchmark2D1DragWithinOnePercentAtTwentyCellsPerDiameter) {
  const Figures coarse = run_dfg(0.01), fine = run_dfg(0.005);
  EXPECT_LT(std::abs(fine.cd - kCd), std::abs(coarse.cd - kCd));
  EXPECT_LT(std::abs(fine.cd / kCd - 1.0), 0.01);
}
