#pragma once
// The coupled PIC-DEM step: owns every module and advances them one step at a time in the order
// of the paper's Fig. 4. The run around it (time loop, output, checkpoints) is run/run.hpp.
// Nothing here includes Trilinos or CGAL.
#include <memory>
#include <string>
#include <vector>

#include "picdem/core/solid_state.hpp"

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"

namespace picdem::fluid {
struct FluidState;
}
namespace picdem::particles {
struct ParticleSet;
}
namespace picdem::dem {
class DemSolver;
}
namespace picdem::grid {
class Decomposition;
}
namespace picdem::geometry {
struct Obstacle;
}

namespace picdem::coupling {

/// Figures of the state, recorded every step in timeseries.csv (its columns:
/// run/src/diagnostic_columns.hpp).
struct Diagnostics {
  double t = 0.0;
  double dt = 0.0;
  long long step = 0;
  double fluid_volume = 0.0;  ///< area inside the particles' free surface [m^2] (free_surface.hpp)
  double kinetic_energy = 0.0;  ///< fluid, from the particles, per unit depth [J/m]
  int ppe_iterations = 0;
  double ppe_residual = 0.0;
  bool ppe_structure_reused = false;  ///< pressure solve kept its Tpetra structure (not in csv)
  double front_x = 0.0;               ///< largest x of any fluid particle, from the left wall [m]
  long long particles = 0;
  double max_speed = 0.0;
  double solid_kinetic_energy = 0.0;
  double advected = 0.0;  ///< largest distance the grid velocity moved a particle [m] (not in csv)
  std::vector<double> levels;   ///< free-surface height at output/level_probes [m]
  long long solids_in_box = 0;  ///< solids with their centre in output/solid_count_box
  /// With open sides (open/): the volumes that entered through the inflows and left through the
  /// outflows since t = 0 [m^2 per unit depth], from the face velocities; empty without.
  std::vector<double> open_volumes;
};

/// The fluid's loads on the solids and obstacles over the last step, per unit depth (forces.csv:
/// run::body_forces), the same on every rank. Pressure: J p^{n+1} + F_q (eq. 6) of every solid
/// with rows, by id (none in a dry run), and of every obstacle; viscous (fluid::ViscousExchange):
/// every solid by id and every obstacle, empty with the explicit scheme.
struct StepLoads {
  std::vector<core::SolidLoads> pressure, obstacle_pressure, viscous, obstacle_viscous;
};

class Simulation {
 public:
  /// The modules of the case, the water seeded; no files are written (the run layer,
  /// run/run.hpp, adds output and checkpoints).
  Simulation(core::Comm comm, core::Params params);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// One coupled step.
  void step();

  /// The modules whose state a checkpoint holds (saved and restored by each module:
  /// particles/checkpoint.hpp, fluid/checkpoint.hpp, dem/checkpoint.hpp). fluid: nullptr in a
  /// case without water; dem: nullptr without solids.
  struct Modules {
    const core::Comm& comm;
    const core::Params& params;
    const grid::Decomposition& decomposition;
    particles::ParticleSet& particles;
    fluid::FluidState* fluid;
    dem::DemSolver* dem;
  };
  Modules modules();
  /// After a restore of the modules: the clock, the last step's dt (the time-step rule's
  /// time/dt_growth bound) and the last step's records of the checkpoint.
  void resume(double t, long long step, double last_dt, const Diagnostics& diag);
  /// The dt of the last step (0 before the first): state of the time-step rule.
  double last_time_step() const;
  /// Before a restore: grid/decomposition = weighted on more than one rank with water takes the
  /// cut lines of a checkpoint's owned cell boxes (io::checkpoint_cell_boxes) when they fit this
  /// run (rank count, grid/ranks_x, grid/ranks_z). Returns whether it did.
  bool take_cuts_of(const std::vector<core::IndexBox>& cell_boxes);
  /// grid/decomposition = weighted: new cut lines from the particles when they lighten the
  /// heaviest block by grid/rebalance_gain (also called every grid/rebalance_interval steps).
  void rebalance();
  /// solver/pressure_structure fixed: the pressure solvers choose their rows again at the next
  /// solve, as after a restart (called where a checkpoint is written: bitwise restarts).
  void choose_pressure_rows_again();

  /// The grid's split over the ranks now, as strip starts {0, ..., nx} along x and {0, ..., nz}
  /// along z (ranks along x = x_cuts.size() - 1); weighted cuts move at each rebalance.
  struct GridSplit {
    std::vector<int> x_cuts, z_cuts;
  };
  GridSplit grid_split() const;

  const Diagnostics& diagnostics() const;
  double time() const;
  long long step_count() const;
  const core::Params& params() const;

  // Read-only access to the modules' state (their probes: fluid::FluidState::pressure_at,
  // wall_pressure_force, viscous_wall_force, max_grid_speed, surface_height;
  // dem::DemSolver::gather_all,
  // max_contact_overlap; particles::velocity_sum).

  /// The fluid's grid state; throws std::logic_error when the case has no water.
  const fluid::FluidState& fluid() const;
  /// This rank's fluid particles (none without water).
  const particles::ParticleSet& particles() const;
  /// The DEM solver, or nullptr when the case has no solids.
  const dem::DemSolver* dem() const;
  /// The fixed obstacles of the case.
  const std::vector<geometry::Obstacle>& obstacles() const;
  bool has_fluid() const;
  /// The fluid's loads of the last step on the solids and obstacles.
  StepLoads last_loads() const;

  /// The modules and the run's records (simulation.cpp); opaque outside it.
  struct Impl;

 private:
  std::unique_ptr<Impl> m_;
};

}  // namespace picdem::coupling
