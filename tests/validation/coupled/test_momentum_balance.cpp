// Momentum of fluid + solids: a disk of density 2000 sinks in a closed tank of still water
// (cases/neutral_disk, heavier and off-centre). Over 0.1 s, before it nears the floor, the change
// of the total momentum (particles + disk) must equal the impulse of gravity on both and of the
// pressure on the tank's walls (the only external forces; the disk touches nothing). The measured
// imbalance is stated against the disk's own momentum change.
#include <gtest/gtest.h>

#include <cmath>

#include "case_loader.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/particles/particle_set.hpp"

using namespace picdem;

namespace {
// Particles (each of mass particle_mass) + solids, summed over ranks.
core::Vec2 total_momentum(const coupling::Simulation& sim, const core::Comm& comm,
                          double particle_mass) {
  core::Vec2 P = particle_mass * particles::velocity_sum(sim.particles(), comm);
  for (const auto& s : sim.dem()->gather_all()) P += s.mass * s.v;
  return P;
}
}  // namespace

TEST(MomentumBalance, SinkingDiskInClosedTank) {
  core::Comm comm;
  const auto params = test_support::load_case(
      comm, "cases/neutral_disk/case.yaml",
      {"solids/disk/density=2000", "solids/disk/center=[0.07, 0.05]", "time/end=0.1"});
  test_support::print_resolution(comm, "MomentumBalance.SinkingDiskInClosedTank", params);
  coupling::Simulation sim(comm, params, "");
  const double h = params.real("grid/cell_size"), rho = 1000.0;
  const core::Vec2 g{0.0, -9.81};
  const double particle_mass = rho * h * h / 4.0;  // 2 x 2 particles per full cell
  const double solid_mass = sim.dem()->gather_all().at(0).mass;
  const core::Vec2 P0 = total_momentum(sim, comm, particle_mass),
                   disk0 = solid_mass * sim.dem()->gather_all().at(0).v;
  core::Vec2 impulse;
  long long particles = -1;  // reseeding in the disk's wake adds a few (their momentum counts)
  while (sim.time() < 0.1 - 1e-12) {
    sim.step();
    const auto& d = sim.diagnostics();
    if (particles < 0) particles = d.particles;
    const double mass = static_cast<double>(d.particles) * particle_mass + solid_mass;
    impulse += d.dt * (sim.fluid().wall_pressure_force(fluid::config_from(params)) + mass * g);
  }
  const auto disk = sim.dem()->gather_all().at(0);
  const core::Vec2 dP = total_momentum(sim, comm, particle_mass) - P0,
                   ddisk = solid_mass * disk.v - disk0;
  const core::Vec2 imbalance = dP - impulse;
  if (comm.is_root())
    std::printf(
        "momentum over 0.1 s: change (%.5e, %.5e), impulse of gravity + walls (%.5e, %.5e), "
        "imbalance (%.3e, %.3e) kg m/s per m = %.2f%% of the disk's change %.5e; particles "
        "%lld -> %lld\n",
        dP.x, dP.z, impulse.x, impulse.z, imbalance.x, imbalance.z,
        100 * core::norm(imbalance) / core::norm(ddisk), core::norm(ddisk), particles,
        sim.diagnostics().particles);
  EXPECT_GT(disk.x.z - 0.01, 0.01);  // still clear of the floor
  EXPECT_LT(core::norm(imbalance), 0.05 * core::norm(ddisk));
}
