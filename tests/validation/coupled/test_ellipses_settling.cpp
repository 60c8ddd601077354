// Ellipses settling in water (cases/ellipses_settling): the heavy ellipses come to rest on the
// floor and on each other without their real boundaries ever crossing (largest overlap of the
// imaginary boundaries below the gap), the light one floats with half its area submerged
// (Archimedes, as the floating disk), and the fluid volume holds within 2%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "case_loader.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/fluid/fluid_state.hpp"

using namespace picdem;

namespace {

/// Half height of the ellipse of semi-axes a, b turned by theta: its extent above its centre.
double half_height(double a, double b, double theta) {
  return std::sqrt(a * a * std::sin(theta) * std::sin(theta) +
                   b * b * std::cos(theta) * std::cos(theta));
}

/// Area of the ellipse below the level line, its centre `above` the level: the map (x/a, z/b)
/// takes the ellipse to the unit disc and the line to one at distance above / half_height from
/// its centre, and multiplies areas by 1 / (a b).
double submerged_area(double a, double b, double theta, double above) {
  const double d = std::clamp(above / half_height(a, b, theta), -1.0, 1.0);
  return a * b * (std::acos(d) - d * std::sqrt(1.0 - d * d));
}

}  // namespace

TEST(EllipsesSettling, HeavyOnesComeToRestAndTheLightOneFloatsHalfSubmerged) {
  core::Comm comm;
  const auto params = test_support::load_case(comm, "cases/ellipses_settling/case.yaml");
  test_support::print_resolution(
      comm, "EllipsesSettling.HeavyOnesComeToRestAndTheLightOneFloatsHalfSubmerged", params);
  coupling::Simulation sim(comm, params);
  const double h = params.real("grid/cell_size"), gap = params.real("dem/gap_cells") * h;
  const double t_end = params.real("time/end"), length = params.real("grid/length");
  const double a = 0.014, b = 0.007, fa = 0.016, fb = 0.008;  // heavy, floater (case.yaml)
  const std::size_t floater = 4;
  // the fluid volume at t = 0, from the case's geometry: the water below the still level less the
  // four heavy ellipses (all below it) and the floater's part below it
  const double level0 = params.real("water/still/z");
  const auto f0 = sim.dem()->gather_all().at(floater);
  const double volume0 =
      length * level0 - 4.0 * M_PI * a * b - submerged_area(fa, fb, f0.theta, f0.x.z - level0);
  double worst_volume = 0.0, worst_overlap = 0.0, submerged = 0.0;
  int n = 0;
  std::vector<core::SolidState> late;  // the heavy ones a quarter second before the end
  while (sim.time() < t_end - 1e-12) {
    sim.step();
    const auto& d = sim.diagnostics();
    worst_volume = std::max(worst_volume, std::abs(d.fluid_volume - volume0) / volume0);
    worst_overlap = std::max(worst_overlap, sim.dem()->max_contact_overlap() / gap);
    if (late.empty() && sim.time() >= t_end - 0.25) late = sim.dem()->gather_all();
    if (sim.time() < 0.5 * t_end) continue;
    // the still-water level: the mean surface height every centimetre away from the floater
    const auto f = sim.dem()->gather_all().at(floater);
    double level = 0.0;
    int probes = 0;
    for (double x = 0.005; x < length; x += 0.01) {
      if (std::abs(x - f.x.x) < fa + 2 * h) continue;
      const double z = sim.fluid().surface_height(x);
      if (std::isfinite(z)) level += z, ++probes;
    }
    level /= probes;
    submerged += submerged_area(fa, fb, f.theta, f.x.z - level);
    ++n;
  }
  const double half = 0.5 * M_PI * fa * fb;  // (rho_s / rho_f) pi a b
  const auto end = sim.dem()->gather_all();
  if (comm.is_root()) {
    std::printf(
        "ellipses settling: floater's mean submerged area / expected = %.4f over the second "
        "half; max overlap %.2f gap; volume change %.2f%%\n",
        submerged / n / half, worst_overlap, 100 * worst_volume);
    for (std::size_t s = 0; s < floater; ++s)
      std::printf(
          "  heavy %zu: lowest point %.5f m (gap %.4f), tilt %.4f rad, moved %.2e m and "
          "turned %.2e rad in the last 0.25 s, speed %.2e m/s\n",
          s, end[s].x.z - half_height(a, b, end[s].theta), gap, std::abs(std::sin(end[s].theta)),
          core::norm(end[s].x - late[s].x), std::abs(end[s].theta - late[s].theta),
          core::norm(end[s].v));
  }
  EXPECT_NEAR(submerged / n / half, 1.0, 0.05);
  EXPECT_LT(worst_overlap, 1.0);  // real boundaries never cross
  EXPECT_LE(worst_volume, 0.02);
  int on_floor = 0;
  for (std::size_t s = 0; s < floater; ++s) {
    SCOPED_TRACE("heavy ellipse " + std::to_string(s));
    // at rest: less than half a cell and 0.05 rad of motion in the last quarter second
    EXPECT_LT(core::norm(end[s].x - late[s].x), 0.5 * h);
    EXPECT_LT(std::abs(end[s].theta - late[s].theta), 0.05);
    // resting on the floor (its real boundary the gap above it) or, denser than water and at
    // rest above that, on another heavy ellipse: one lower down within touching distance
    const double lowest = end[s].x.z - half_height(a, b, end[s].theta);
    EXPECT_GT(lowest, gap - 0.1 * h);
    if (lowest < gap + 0.1 * h) {
      ++on_floor;
      continue;
    }
    bool supported = false;
    for (std::size_t o = 0; o < floater; ++o)
      supported = supported || (o != s && end[o].x.z < end[s].x.z &&
                                core::norm(end[o].x - end[s].x) < 2 * a + gap);
    EXPECT_TRUE(supported) << "lowest point " << lowest << " m, not on the floor";
  }
  if (comm.is_root()) std::printf("  %d of 4 heavy ellipses on the floor\n", on_floor);
  EXPECT_GE(on_floor, 2);
}
