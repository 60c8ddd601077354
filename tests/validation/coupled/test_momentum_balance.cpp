// Momentum of fluid + solids: a disk of density 2000 sinks in a closed tank of still water
// (cases/neutral_disk, heavier and off-centre). Over 0.1 s, before it nears the floor, the change
// of the total momentum (particles + disk) must equal the impulse of gravity on both and of the
// pressure on the tank's walls (the only external forces; the disk touches nothing). The measured
// imbalance is stated against the disk's own momentum change.
//
// The viscous case (nu = 1e-2, fluid/viscosity_scheme: implicit, no-slip walls) adds the viscous
// loads: the disk receives those the fluid loses at its boundary (eq. 6, doc/viscous.md), and the
// impulse of the walls' viscous force joins the external impulse.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "case_loader.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/particles/particle_set.hpp"
#include "picdem/run/forces.hpp"

using namespace picdem;

namespace {
// Particles (each of mass particle_mass) + solids, summed over ranks.
core::Vec2 total_momentum(const coupling::Simulation& sim, const core::Comm& comm,
                          double particle_mass) {
  core::Vec2 P = particle_mass * particles::velocity_sum(sim.particles(), comm);
  for (const auto& s : sim.dem()->gather_all()) P += s.mass * s.v;
  return P;
}

struct Balance {
  core::Vec2 change, impulse, disk_change, viscous_impulse_on_disk;
  core::Vec2 gravity_on_disk;  // the impulse of gravity on the disk alone
  double disk_z = 0.0;
};

// Runs the sinking disk to 0.1 s with the extra settings `more` and returns the momentum budget.
Balance sinking_disk(const core::Comm& comm, const char* name, std::vector<std::string> more) {
  std::vector<std::string> settings{"solids/disk/density=2000", "solids/disk/center=[0.07, 0.05]",
                                    "time/end=0.1"};
  settings.insert(settings.end(), more.begin(), more.end());
  const auto params = test_support::load_case(comm, "cases/neutral_disk/case.yaml", settings);
  test_support::print_resolution(comm, name, params);
  coupling::Simulation sim(comm, params);
  const double h = params.real("grid/cell_size"), rho = 1000.0;
  const core::Vec2 g{0.0, -9.81};
  const double particle_mass = rho * h * h / 4.0;  // 2 x 2 particles per full cell
  const double solid_mass = sim.dem()->gather_all().at(0).mass;
  const core::Vec2 P0 = total_momentum(sim, comm, particle_mass),
                   disk0 = solid_mass * sim.dem()->gather_all().at(0).v;
  Balance b;
  long long particles = -1;  // reseeding in the disk's wake adds a few (their momentum counts)
  while (sim.time() < 0.1 - 1e-12) {
    sim.step();
    const auto& d = sim.diagnostics();
    if (particles < 0) particles = d.particles;
    const double mass = static_cast<double>(d.particles) * particle_mass + solid_mass;
    const auto& f = sim.fluid();  // viscous_wall_force: the fluid's force on the walls
    b.impulse += d.dt * (f.wall_pressure_force(fluid::config_from(params)) + mass * g -
                         f.viscous_wall_force);
    b.gravity_on_disk += d.dt * solid_mass * g;
    b.viscous_impulse_on_disk += d.dt * run::body_forces(sim).at(0).viscous;  // 0: explicit scheme
  }
  const auto disk = sim.dem()->gather_all().at(0);
  b.change = total_momentum(sim, comm, particle_mass) - P0;
  b.disk_change = solid_mass * disk.v - disk0;
  b.disk_z = disk.x.z;
  const core::Vec2 imbalance = b.change - b.impulse;
  const double fluid_on_disk = core::norm(b.disk_change - b.gravity_on_disk);
  if (comm.is_root())
    std::printf(
        "%s: momentum over 0.1 s: change (%.5e, %.5e), impulse of gravity + walls (%.5e, %.5e), "
        "imbalance (%.3e, %.3e) kg m/s per m = %.2f%% of the disk's change %.5e, %.2f%% of the "
        "fluid's impulse on the disk %.5e; viscous impulse on the disk (%.4e, %.4e); particles "
        "%lld -> %lld\n",
        name, b.change.x, b.change.z, b.impulse.x, b.impulse.z, imbalance.x, imbalance.z,
        100 * core::norm(imbalance) / core::norm(b.disk_change), core::norm(b.disk_change),
        100 * core::norm(imbalance) / fluid_on_disk, fluid_on_disk, b.viscous_impulse_on_disk.x,
        b.viscous_impulse_on_disk.z, particles, sim.diagnostics().particles);
  return b;
}

}  // namespace

TEST(MomentumBalance, SinkingDiskInClosedTank) {
  core::Comm comm;
  const Balance b = sinking_disk(comm, "MomentumBalance.SinkingDiskInClosedTank", {});
  EXPECT_GT(b.disk_z - 0.01, 0.01);  // still clear of the floor
  EXPECT_LT(core::norm(b.change - b.impulse), 0.05 * core::norm(b.disk_change));
}

// nu = 1e-2 m^2/s, no-slip walls: drag and buoyancy nearly balance the disk's weight, so its own
// momentum change is small and the imbalance is measured against the fluid's impulse on the disk
// (pressure + viscous, = its change - the impulse of gravity on it). The viscous part of that
// impulse is over 10%; without it in the disk's update (measured by leaving it out) the imbalance
// was 30% of the fluid's impulse (doc/validation.md).
TEST(MomentumBalance, ViscousSinkingDiskInClosedTank) {
  core::Comm comm;
  const Balance b = sinking_disk(
      comm, "MomentumBalance.ViscousSinkingDiskInClosedTank",
      {"fluid/viscosity=1e-2", "fluid/viscosity_scheme=implicit", "fluid/walls=no_slip"});
  const double fluid_on_disk = core::norm(b.disk_change - b.gravity_on_disk);
  EXPECT_GT(b.disk_z - 0.01, 0.01);
  EXPECT_GT(core::norm(b.viscous_impulse_on_disk), 0.1 * fluid_on_disk);
  EXPECT_LT(core::norm(b.change - b.impulse), 0.02 * fluid_on_disk);
}

// The same with the disk's rigid velocity an unknown of the viscous step
// (coupling/viscous_rigid_rows): the exchange stays exact, so the budget closes as well.
TEST(MomentumBalance, ViscousSinkingDiskRigidRows) {
  core::Comm comm;
  const Balance b = sinking_disk(comm, "MomentumBalance.ViscousSinkingDiskRigidRows",
                                 {"fluid/viscosity=1e-2", "fluid/viscosity_scheme=implicit",
                                  "fluid/walls=no_slip", "coupling/viscous_rigid_rows=true"});
  const double fluid_on_disk = core::norm(b.disk_change - b.gravity_on_disk);
  EXPECT_GT(b.disk_z - 0.01, 0.01);
  EXPECT_GT(core::norm(b.viscous_impulse_on_disk), 0.1 * fluid_on_disk);
  EXPECT_LT(core::norm(b.change - b.impulse), 0.02 * fluid_on_disk);
}
