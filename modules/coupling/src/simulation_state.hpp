#pragma once
// The state of a run, private to the coupling module: simulation.cpp advances it, checkpoint.cpp
// writes and restores it. Everything a restart needs is listed in doc/restart.md.
#include <memory>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"
#include "picdem/coupling/checkpoint.hpp"
#include "picdem/coupling/output.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/coupling/solids_in_fluid.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/particles/particle_set.hpp"

namespace picdem::coupling {

using grid::FaceField;

struct SimulationState {
  core::Comm comm;
  core::Params params;
  grid::GridSpec spec;
  std::unique_ptr<grid::Decomposition> decomp;
  std::unique_ptr<grid::Halo> halo;

  // fluid
  bool has_fluid = false;
  fluid::FluidConfig fluid_cfg;
  particles::ParticleConfig particle_cfg;
  std::unique_ptr<fluid::PressureSolver> pressure;
  particles::ParticleSet particles;
  fluid::FluidState fluid;  // u, w, p, cells, free surface, apertures
  grid::GridArray<int> count;
  bool ghost_fluid = true;  // sub-cell free surface (else p = 0 at air cell centres)
  double theta_min = 0.01;
  double particle_mass = 0.0;                             // per unit depth
  double density_relaxation = 0.0;                        // free_surface/density_correction
  long long density_interval = 1;                         // .../density_correction_interval
  std::unique_ptr<fluid::PressureSolver> density_solver;  // its Poisson equation

  // solids
  std::vector<geometry::Obstacle> obstacles;
  std::unique_ptr<dem::DemSolver> dem;
  bool has_bodies = false;  // solids or obstacles anywhere in the run (every rank alike)
  SolidScene scene;         // poses at the start of the step (cut cells), then after the DEM
  geometry::CutCells cut;   // at the start-of-step poses; cut body b is scene.placements[b]
  std::vector<core::SolidLoads> collision_loads, fluid_loads;
  double beta = 1.0;
  QuadratureOptions quadrature;

  // run
  double t = 0.0, t_end = 0.0;
  long long step = 0;
  Diagnostics diag;
  fluid::SolveStats last_solve;
  std::unique_ptr<Output> output;

  // checkpoints (checkpoint.hpp)
  CheckpointConfig checkpoint;  // directory empty: no checkpoints
  bool restarted = false;       // the state came from a checkpoint (no initial frame)
  bool stopped_by_signal = false;
};

}  // namespace picdem::coupling
