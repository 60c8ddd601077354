// Dam break with 6 and 12 layers of cylinders (paper section 3.2) at 6.7 cells per cylinder
// diameter (h = 1.5 mm, to keep CI short; the paper's 20 in doc/validation.md), to 0.6 s:
// - the particles are conserved (the cases run without reseeding);
// - stable (a blown-up run throws), no body's real boundary crosses another's or a wall's;
// - fluid volume within 2% of the water's area at t = 0 (the dam's box less the cylinders' parts
//   inside it), at every step (the cases' density correction, doc/coupling.md);
// - the first arrival of a cylinder at the right wall, with gap damping (beta 0.5) and without
//   (beta 1.0): without, the cylinders arrive earlier;
// - the 12-layer collapse is less violent than the 6-layer one, measured by the peak kinetic energy
//   of the water per kg (that of the cylinders is printed too).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "case_loader.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/particles/particle_set.hpp"
#include "water_at_t0.hpp"

using namespace picdem;

namespace {
struct Outcome {
  double arrival = std::numeric_limits<double>::infinity();  // first contact with the right wall
  double worst_volume = 0.0;                                 // relative change
  double worst_overlap_over_gap = 0.0;  // max delta / gap (1: boundaries touch)
  double peak_specific_ke = 0.0;        // cylinders, J/kg
  double peak_fluid_ke = 0.0;           // water, J/kg
  long long particles = 0;              // at t = 0
  long long count_changes = 0;          // steps whose particle count differs from it
  double stack_top = 0.0;               // highest cylinder top at t = 0
  double water_top = 0.0;               // the dam's top, water/dam/z[1]
};

// One case at cell size h; `extra` adds case settings (the CI runs at 1.5 mm set time/dt_max);
// `progress` prints a line every 0.1 s of simulated time (the runs at the paper's resolution).
Outcome run(int layers, double beta, double h, std::vector<std::string> extra = {},
            bool progress = false) {
  core::Comm comm;
  const auto wall_start = std::chrono::steady_clock::now();
  extra.push_back("grid/cell_size=" + std::to_string(h));
  extra.push_back("coupling/beta=" + std::to_string(beta));
  const auto params = test_support::load_case(
      comm, "cases/dam_break_cylinders_" + std::to_string(layers) + "_layers/case.yaml", extra);
  test_support::print_resolution(comm, "DamBreakCylinders " + std::to_string(layers) + " layers",
                                 params);
  coupling::Simulation sim(comm, params);
  const double L = params.real("grid/length"), r = 0.005, gap = 2 * h;
  Outcome o;
  // the water at t = 0: the dam's box less the cylinders' parts inside it
  const double v0 = test_support::water_at_t0(params, "dam", sim.dem()->gather_all(), r);
  double first_step_volume = -1.0;
  o.particles = comm.sum(static_cast<long long>(sim.particles().size()));
  for (const auto& s : sim.dem()->gather_all()) o.stack_top = std::max(o.stack_top, s.x.z + r);
  o.water_top = params.reals("water/dam/z").at(1);
  double next_progress = 0.1;
  while (sim.time() < 0.6 - 1e-12) {
    sim.step();
    const auto& d = sim.diagnostics();
    if (first_step_volume < 0) first_step_volume = d.fluid_volume;
    o.count_changes += d.particles != o.particles;
    o.worst_volume = std::max(o.worst_volume, std::abs(d.fluid_volume - v0) / v0);
    o.worst_overlap_over_gap =
        std::max(o.worst_overlap_over_gap, sim.dem()->max_contact_overlap() / gap);
    double ke = 0.0, mass = 0.0, right = -1e300;
    for (const auto& s : sim.dem()->gather_all()) {
      ke += 0.5 * s.mass * core::norm2(s.v) + 0.5 * s.inertia * s.omega * s.omega;
      mass += s.mass;
      right = std::max(right, s.x.x + r);
    }
    o.peak_specific_ke = std::max(o.peak_specific_ke, ke / mass);
    o.peak_fluid_ke = std::max(o.peak_fluid_ke, d.kinetic_energy / (1000.0 * v0));
    // eq. 19 with the wall: contact once r + 2h exceeds the distance to the wall
    if (right + gap >= L && sim.time() < o.arrival) o.arrival = sim.time();
    if (progress && comm.is_root() && sim.time() >= next_progress - 1e-12) {
      const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - wall_start;
      std::printf("  t = %.3f s: worst volume change so far %.2f%%, %.0f s of wall time\n",
                  sim.time(), 100 * o.worst_volume, wall.count());
      std::fflush(stdout);
      next_progress += 0.1;
    }
  }
  if (comm.is_root())
    std::printf(
        "%d layers, beta %.1f: arrival %.3f s, volume change %.2f%% (of %.6e m^2 at t = 0; "
        "after the first step %+.2f%%), max overlap %.2f gap, peak KE of the water %.4f J/kg, "
        "of the cylinders %.4f J/kg; %lld particles, count changed in %lld steps; stack top "
        "%.4f m, water top %.4f m at t = 0\n",
        layers, beta, o.arrival, 100 * o.worst_volume, v0, 100 * (first_step_volume / v0 - 1),
        o.worst_overlap_over_gap, o.peak_fluid_ke, o.peak_specific_ke, o.particles, o.count_changes,
        o.stack_top, o.water_top);
  return o;
}
}  // namespace

// The three runs, made once per process and shared by the tests below.
struct Runs {
  Outcome six, six_free, twelve;
};
const Runs& runs() {
  const double h = 0.0015;
  const std::vector<std::string> dt{"time/dt_max=0.001"};
  static const Runs r{run(6, 0.5, h, dt), run(6, 1.0, h, dt), run(12, 0.5, h, dt)};
  return r;
}

TEST(DamBreakCylinders, StableAndTheFindingsOfThePaper) {
  const Runs& r = runs();
  for (const Outcome* o : {&r.six, &r.six_free, &r.twelve})
    EXPECT_LT(o->worst_overlap_over_gap, 1.0);  // real boundaries never cross
  EXPECT_TRUE(std::isfinite(r.six.arrival)) << "no cylinder reached the right wall by 0.6 s";
  EXPECT_LT(r.six_free.arrival, r.six.arrival);  // without gap damping the cylinders arrive earlier
  // "Less violent" (the paper, of the flow): the water's peak kinetic energy per kg. The cylinders'
  // peak (printed) does not separate the two at this resolution (doc/validation.md).
  EXPECT_LT(r.twelve.peak_fluid_ke, r.six.peak_fluid_ke);
}

// The water's area inside its free surface (less the cylinders), against the water's area at t = 0.
TEST(DamBreakCylinders, FluidVolumeWithinTwoPercent) {
  const Runs& r = runs();
  EXPECT_LE(r.six.worst_volume, 0.02);
  EXPECT_LE(r.six_free.worst_volume, 0.02);
  EXPECT_LE(r.twelve.worst_volume, 0.02);
}

// The cases run without reseeding (particles/min_per_cell 0): no particle is added or removed, at
// any step (trimming at max_per_cell removed 0.55% of them by 0.6 s at h = 0.5 mm before issue 14).
TEST(DamBreakCylinders, ParticlesConserved) {
  const Runs& r = runs();
  for (const Outcome* o : {&r.six, &r.six_free, &r.twelve}) EXPECT_EQ(o->count_changes, 0);
}

// At the paper's resolution (h = 0.5 mm, 20 cells per diameter; the case files' own settings),
// 6, 8, 10 and 12 layers with gap damping (beta 0.5) and without (1.0), as the paper's Figs. 8-10
// (issue 14): each run within the limits of the tests above, unchanged; and, as at 1.5 mm, the
// cylinders arriving earlier without gap damping and the 12 layers less violent than the 6. Not
// registered in CI (a run takes 3-8 min on 2 ranks on a quiet machine, all eight 46 min; 6 layers
// without gap damping fails the volume limit, 2.54%, doc/validation.md):
//   mpirun -n 2 build/tests/validation/coupled/test_validation_dam_break_cylinders
//       --gtest_filter='DamBreakCylindersAtPaperResolution.*'   (one line)
// Each run is made once per process and shared by the tests that read it. A run's line
// "N layers, beta B: arrival T s, ..." is what drivers/plot/arrival_against_layers.py plots.
namespace {
const Outcome& paper_run(int layers, double beta) {
  static std::map<std::pair<int, double>, Outcome> made;
  const auto key = std::make_pair(layers, beta);
  if (auto it = made.find(key); it != made.end()) return it->second;
  return made.emplace(key, run(layers, beta, 0.0005, {}, true)).first->second;
}

void expect_paper_limits(const Outcome& o) {
  EXPECT_LT(o.worst_overlap_over_gap, 1.0);  // real boundaries never cross
  EXPECT_TRUE(std::isfinite(o.arrival)) << "no cylinder reached the right wall by 0.6 s";
  EXPECT_LE(o.worst_volume, 0.02);
  EXPECT_EQ(o.count_changes, 0);
}
}  // namespace

TEST(DamBreakCylindersAtPaperResolution, SixLayersBetaHalf) {
  expect_paper_limits(paper_run(6, 0.5));
}
TEST(DamBreakCylindersAtPaperResolution, EightLayersBetaHalf) {
  expect_paper_limits(paper_run(8, 0.5));
}
TEST(DamBreakCylindersAtPaperResolution, TenLayersBetaHalf) {
  expect_paper_limits(paper_run(10, 0.5));
}

// At h = 1.5 mm the gaps of 2h lift the 12-layer stack's top above the water (gap + 2r + 11 x
// sqrt(3)/2 (2r + gap) = 0.137 m against 0.12 m); at the paper's resolution it stands in the water
// (0.116 m), as in the experiment.
TEST(DamBreakCylindersAtPaperResolution, TwelveLayersBetaHalf) {
  const Outcome& o = paper_run(12, 0.5);
  expect_paper_limits(o);
  EXPECT_LT(o.stack_top, o.water_top);
}

TEST(DamBreakCylindersAtPaperResolution, WithoutGapDampingWithinTheLimits) {
  for (int layers : {6, 8, 10, 12}) {
    SCOPED_TRACE(std::to_string(layers) + " layers, beta 1.0");
    expect_paper_limits(paper_run(layers, 1.0));
  }
}

// The paper's Figs. 8-9: without gap damping the cylinders are pushed to the right wall sooner.
TEST(DamBreakCylindersAtPaperResolution, ArrivalEarlierWithoutGapDamping) {
  for (int layers : {6, 8, 10, 12}) {
    SCOPED_TRACE(std::to_string(layers) + " layers");
    EXPECT_LT(paper_run(layers, 1.0).arrival, paper_run(layers, 0.5).arrival);
  }
}

// "In the 12 layers case the dam-break flow appears much less violent": the water's peak kinetic
// energy per kg, the measure of the test at 1.5 mm.
TEST(DamBreakCylindersAtPaperResolution, TwelveLayersLessViolent) {
  EXPECT_LT(paper_run(12, 0.5).peak_fluid_ke, paper_run(6, 0.5).peak_fluid_ke);
}
