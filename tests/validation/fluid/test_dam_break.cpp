// Dam break against Martin & Moyce (1952): with 20 cells across a, the surge front is within 8% of
// the experiment for tau <= 3, allowing one constant shift |s| <= 0.2 in tau (gate release), and
// the fluid volume stays within 1% of its initial value to t = 0.19 s (the front's window).
// Without reseeding and with the density correction (the cylinder dam breaks' settings), the
// particles are conserved and the volume stays within 1% over the case's whole run (issue 14:
// with the defaults the whole run reaches +1.07%, reseeding's net creation, doc/validation.md).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "case_loader.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/particles/particle_set.hpp"

using namespace picdem;

namespace {
struct Point {
  double tau, z_over_a;
};
std::vector<Point> experiment() {
  std::ifstream in(std::string(PICDEM_DATA_DIR) + "/martin_moyce1952_surge_front.csv");
  std::vector<Point> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 't') continue;
    Point p;
    char comma;
    std::istringstream(line) >> p.tau >> comma >> p.z_over_a;
    out.push_back(p);
  }
  return out;
}
double interpolate(const std::vector<double>& t, const std::vector<double>& y, double at) {
  for (std::size_t n = 1; n < t.size(); ++n)
    if (t[n] >= at) return y[n - 1] + (y[n] - y[n - 1]) * (at - t[n - 1]) / (t[n] - t[n - 1]);
  return y.back();
}
}  // namespace

TEST(DamBreak, SurgeFrontAgainstMartinMoyce) {
  core::Comm comm;
  const double a = 0.05715, g = 9.81;
  const double tau_scale = std::sqrt(2.0 * g / a);
  const auto params = test_support::load_case(comm, "cases/dam_break/case.yaml", {"time/end=0.19"});
  test_support::print_resolution(comm, "DamBreak.SurgeFrontAgainstMartinMoyce", params);
  ASSERT_GE(a / params.real("grid/cell_size"), 20.0 - 1e-9);
  coupling::Simulation sim(comm, params);
  std::vector<double> tau{0.0}, front{1.0};
  const double v0 = 2.0 * a * a;  // the water at t = 0: the initial column, a x 2a
  double worst_volume = 0.0;
  while (sim.time() < 0.19 - 1e-12) {
    sim.step();
    const auto& d = sim.diagnostics();
    worst_volume = std::max(worst_volume, std::abs(d.fluid_volume - v0) / v0);
    tau.push_back(d.t * tau_scale);
    front.push_back(d.front_x / a);
  }
  const auto exp = experiment();
  ASSERT_EQ(exp.size(), 15u) << "the Martin & Moyce data file was not read";
  // The best constant shift s in [-0.2, 0.2]: simulated front at tau - s against the experiment.
  double best = 1e300, best_shift = 0.0;
  for (int n = -20; n <= 20; ++n) {
    const double s = 0.01 * n;
    double worst = 0.0;
    for (const auto& p : exp)
      if (p.tau <= 3.0)
        worst =
            std::max(worst, std::abs(interpolate(tau, front, p.tau - s) - p.z_over_a) / p.z_over_a);
    if (worst < best) best = worst, best_shift = s;
  }
  if (comm.is_root()) {
    std::printf(
        "dam break: worst front error for tau <= 3 = %.2f%% with shift %.2f; worst volume "
        "change %.3f%%\n",
        100 * best, best_shift, 100 * worst_volume);
    std::ofstream out("dam_break_front.csv");
    out << "tau,front_over_a\n";
    for (std::size_t n = 0; n < tau.size(); ++n) out << tau[n] << "," << front[n] << "\n";
  }
  EXPECT_LE(best, 0.08);
  EXPECT_LE(worst_volume, 0.01);
}

// The case's whole run (0.33 s, tau 6.1: the surge runs up the far wall from 0.29 s) without
// reseeding and with the density correction every 2 steps: no particle is added or removed, and
// the area inside the particles' surface stays within 1% of the column's, 2a^2, at every step.
TEST(DamBreak, VolumeOverTheWholeRunWithoutReseeding) {
  core::Comm comm;
  const double a = 0.05715;
  const auto params =
      test_support::load_case(comm, "cases/dam_break/case.yaml",
                              {"particles/min_per_cell=0", "free_surface/density_correction=1.0",
                               "free_surface/density_correction_interval=2"});
  test_support::print_resolution(comm, "DamBreak.VolumeOverTheWholeRunWithoutReseeding", params);
  const double end = params.real("time/end");
  ASSERT_GE(end, 0.33 - 1e-12);
  coupling::Simulation sim(comm, params);
  const long long start = comm.sum(static_cast<long long>(sim.particles().size()));
  const double v0 = 2.0 * a * a;  // the initial column, a x 2a
  double worst_volume = 0.0, worst_t = 0.0;
  long long changed = 0;  // steps whose particle count differs from the start's
  while (sim.time() < end - 1e-12) {
    sim.step();
    const auto& d = sim.diagnostics();
    if (std::abs(d.fluid_volume - v0) / v0 > worst_volume)
      worst_volume = std::abs(d.fluid_volume - v0) / v0, worst_t = d.t;
    changed += d.particles != start;
  }
  if (comm.is_root())
    std::printf(
        "dam break without reseeding, to %.3f s: worst volume change %.3f%% at %.4f s; "
        "%lld particles, count changed in %lld steps\n",
        sim.time(), 100 * worst_volume, worst_t, start, changed);
  EXPECT_EQ(changed, 0);
  EXPECT_LE(worst_volume, 0.01);
}
