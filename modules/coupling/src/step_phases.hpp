#pragma once
// The phases of the coupled step (paper Fig. 4), each a function of what it reads (values and
// const references) and what it changes (the one non-const module it advances). Simulation::step
// calls them in order; nothing here keeps state between steps but CutCellsAhead, which
// Simulation holds and hands to place_solids. Private to the coupling module.
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/solid_state.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/coupling/solids_in_fluid.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/dem/scene.hpp"
#include "picdem/fluid/body_loads.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/fluid/time_step.hpp"
#include "picdem/fluid/viscous_bodies.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/grid/balance.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/particles/occupancy_pass.hpp"
#include "picdem/particles/particle_set.hpp"
#include "picdem/particles/transfer.hpp"

namespace picdem::coupling {

/// The parallel layout every phase works on.
struct Layout {
  const grid::Decomposition& d;
  const grid::Halo& halo;
  const core::Comm& comm;
};

/// The step's settings, read once from the validated case.
struct StepSettings {
  grid::GridSpec spec;
  fluid::FluidConfig fluid;
  fluid::FreeSurfaceConfig surface;  ///< free_surface/*
  particles::ParticleConfig particles;
  fluid::TimeStepLimits time;  ///< time/* (fluid::choose_time_step)
  grid::BalanceRule balance;   ///< grid/decomposition and rebalancing (grid::worthwhile_cuts)
  bool has_fluid = false;
  bool has_solids = false;          ///< the run has a DEM (solids; or no water)
  bool has_bodies = false;          ///< solids or obstacles anywhere in the run (every rank alike)
  double tiny_fraction = 0;         ///< coupling/tiny_cell_fraction
  double beta = 1.0;                ///< coupling/beta, eq. 20
  bool viscous_rigid_rows = false;  ///< coupling/viscous_rigid_rows (doc/viscous.md)
  bool mixture_cut_faces = false;   ///< coupling/mixture_cut_faces (fluid::mix_cut_faces)
  fluid::QuadratureOptions quadrature;
  double particle_mass = 0.0;                         ///< per unit depth
  std::vector<double> level_probes, solid_count_box;  ///< output/*
};
StepSettings step_settings_from(const core::Params& params);

/// The solids as the fluid sees them at X^n: poses and velocities (the scene) and the cut cells
/// built from them (cut body b is scene.placements[b]). Built once per step, then only read.
struct SolidsAtStart {
  dem::SolidScene scene;
  geometry::CutCells cut;
};

/// What besides the grid's face velocities bounds the step (time/cfl_speed), from its owner: the
/// particles' fastest speed (particles::max_speed), or the surface motion (dem::surface_motion:
/// speed and gravity's change) of the solids that can reach a cell holding water within dt_max
/// (particles::near_particles on the particles' count, which this computes as the step's cells
/// would). Collective.
fluid::StepMotion cfl_extra_motion(const Layout& L, const StepSettings& set,
                                   const particles::ParticleSet& particles,
                                   particles::OccupancyPass& occupancy, const dem::DemSolver* dem);

/// Cut cells built for one scene and window, kept for the next step's place_solids: the step
/// builds them at X^{n+1} for its diagnostics, and the next step starts from those poses; a scene
/// of obstacles alone keeps them for the whole run. Used only when the scene (every placement's
/// id, shape and pose, every obstacle) and the rank's cell window are equal to the kept ones, so
/// that a rebalance, a restart or a changed solid builds them again: the result is the same bits.
struct CutCellsAhead {
  bool valid = false;
  std::vector<geometry::SolidPlacement> placements;
  std::vector<geometry::Obstacle> obstacles;
  core::IndexBox window;
  geometry::CutCells cut;
  fluid::Apertures apertures;  ///< fluid::cut_cells' apertures of `cut` (before open sides)

  bool matches(const dem::SolidScene& scene, const grid::Decomposition& d) const;
};

/// geometry: solids at X^n -> cut cells and the fluid's apertures E; from `ahead` when it
/// matches (moved out of it when dem moves the solids, copied for a scene of obstacles alone).
SolidsAtStart place_solids(const Layout& L, const StepSettings& set, const dem::DemSolver* dem,
                           const std::vector<geometry::Obstacle>& obstacles,
                           fluid::Apertures& apertures, CutCellsAhead& ahead);

/// transfer (cells): occupancy S (from `occ` when current), level set phi, cell states, surface
/// fractions.
void mark_cells(const Layout& L, const StepSettings& set, const geometry::CutCells& cut,
                const particles::ParticleSet& particles, particles::OccupancyPass& occ,
                fluid::FluidState& fluid);

/// density: moves crowded or thinned particles (positions only); true when they moved. `solver`
/// (its Poisson equation) may be null when free_surface/density_correction is 0.
bool correct_density(const Layout& L, const StepSettings& set, long long step,
                     const SolidsAtStart& solids, const fluid::FluidState& fluid,
                     fluid::PressureSolver* solver, particles::ParticleSet& particles);

/// transfer: particles -> faces (from occ.sums when current), walls, fluid-face mask, rigid faces,
/// extension; u_old = u.
void particles_to_grid(const Layout& L, const StepSettings& set, const SolidsAtStart& solids,
                       const particles::ParticleSet& particles, particles::OccupancyPass& occ,
                       fluid::FluidState& fluid);

/// forces: gravity and viscosity -> u~. Explicit, or implicit at the true boundaries of every
/// solid of `dem` (collective) and obstacle, the solids' rigid velocities unknowns of it with
/// `rigid_rows` (with fluid/viscous_pressure_predictor on u + dt (g - grad p^n / rho), taken off
/// after; `surface`: the ghost fluid's, as for the projection); returns the implicit scheme's
/// viscous loads (empty for the explicit one).
fluid::ViscousExchange add_forces(const Layout& L, const fluid::FluidConfig& cfg, bool rigid_rows,
                                  const dem::DemSolver* dem,
                                  const std::vector<geometry::Obstacle>& obstacles, double dt,
                                  const fluid::SurfaceFractions* surface, fluid::FluidState& fluid);

/// contact: collision loads predicted at level n with dt in eq. 8 (none without solids).
std::vector<core::SolidLoads> predict_contacts(const dem::DemSolver* dem, double dt);

/// pressure: the augmented PPE (eqs. 5-6) for p^{n+1}, the previous p as initial guess.
fluid::SolveStats solve_pressure(const Layout& L, const StepSettings& set,
                                 const SolidsAtStart& solids,
                                 const std::vector<core::SolidLoads>& collision, double dt,
                                 fluid::PressureSolver& solver, fluid::FluidState& fluid);

/// project: u^{n+1} = u~ - dt/rho grad p on open faces.
void project(const Layout& L, const StepSettings& set, double dt, fluid::FluidState& fluid);

/// solids: F_fluid = J p^{n+1} + F_q from the rows of the last solve of `pressure`
/// (PressureSolver::solid_loads; none in a dry run: pressure = fluid = nullptr) plus the viscous
/// loads of the step, then the DEM subcycles (eqs. 21-25). Returns the pressure loads used:
/// every solid with rows, by id, the same on every rank.
std::vector<core::SolidLoads> advance_solids(const fluid::PressureSolver* pressure,
                                             const fluid::FluidState* fluid, double dt,
                                             const fluid::ViscousExchange& viscous,
                                             dem::DemSolver& dem);

/// transfer: grid -> particles with the solids at X^{n+1} on covered faces, then gap damping
/// (eq. 20) at the contacts of X^{n+1}.
void grid_to_particles(const Layout& L, const StepSettings& set, const SolidsAtStart& solids,
                       const dem::SolidScene& after, const dem::DemSolver* dem,
                       fluid::FluidState& fluid, particles::ParticleSet& particles);

/// advect: through the divergence-free field, out of the solids at X^{n+1}, migrate, reseed.
/// Returns the largest distance the grid velocity moved a particle (collective: every rank's).
double advect_particles(const Layout& L, const StepSettings& set, long long step,
                        const geometry::CutCells& cut, const dem::SolidScene& after, double dt,
                        const fluid::FluidState& fluid, particles::ParticleSet& particles);

/// Figures of the state after the step (t, step: its end); a non-finite particle or solid
/// anywhere stops the run on every rank. fluid: nullptr without water; cut: the cut cells of the
/// bodies where the step leaves them (X^{n+1}), nullptr without bodies or water: the fluid volume
/// weights the particles' occupancy with them. The occupancy of the particles is left in `occ`
/// for the next step. advected: advect_particles'.
Diagnostics record_diagnostics(const Layout& L, const StepSettings& set, double t, long long step,
                               double dt, double advected, const fluid::SolveStats& solve,
                               const particles::ParticleSet& particles, const dem::DemSolver* dem,
                               const geometry::CutCells* cut, particles::OccupancyPass& occ,
                               fluid::FluidState* fluid);

}  // namespace picdem::coupling
