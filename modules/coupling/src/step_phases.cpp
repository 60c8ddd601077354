#include "step_phases.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/dem/figures.hpp"
#include "picdem/dem/gap_damping.hpp"
#include "picdem/fluid/bodies.hpp"
#include "picdem/fluid/density_correction.hpp"
#include "picdem/fluid/free_surface.hpp"
#include "picdem/fluid/open_flow.hpp"
#include "picdem/fluid/open_particles.hpp"
#include "picdem/fluid/step_forces.hpp"
#include "picdem/particles/figures.hpp"
#include "picdem/particles/particles.hpp"

namespace picdem::coupling {

using core::Vec2;
using grid::CellState;
using grid::FaceField;
using grid::Stagger;

StepSettings step_settings_from(const core::Params& params) {
  StepSettings s;
  s.spec = grid::spec_from(params);
  s.particles = particles::config_from(params);
  s.time = fluid::time_step_limits_from(params);
  s.balance = grid::balance_rule_from(params);
  s.has_fluid = !params.sublist_names("water").empty();
  s.beta = params.real("coupling/beta");
  s.viscous_rigid_rows = params.boolean("coupling/viscous_rigid_rows");
  s.tiny_fraction = params.real("coupling/tiny_cell_fraction");
  s.mixture_cut_faces = params.boolean("coupling/mixture_cut_faces");
  s.level_probes = params.reals("output/level_probes");
  s.solid_count_box = params.reals("output/solid_count_box");
  if (!s.has_fluid) return s;
  s.fluid = fluid::config_from(params);
  s.quadrature = {params.boolean("coupling/hydrostatic_quadrature"), s.fluid.rho, s.fluid.g};
  s.surface = fluid::free_surface_config_from(params);
  const double n = static_cast<double>(s.particles.per_cell_1d);
  s.particle_mass = s.fluid.rho * s.spec.h * s.spec.h / (n * n);
  return s;
}

fluid::StepMotion cfl_extra_motion(const Layout& L, const StepSettings& set,
                                   const particles::ParticleSet& particles,
                                   particles::OccupancyPass& occupancy, const dem::DemSolver* dem) {
  if (set.time.cfl_from_particles) return {particles::max_speed(particles, L.comm), 0.0};
  if (!dem || !set.has_fluid) return {};  // dem: on every rank or on none; dry: dt_max
  // the count of the step's cells (mark_cells), taken now: the same pass, the same result
  occupancy.update(particles, L.d, L.halo, set.particles, true);
  const core::Vec2 g = dem->config().gravity;
  const double dt = set.time.dt_max, a = std::sqrt(g.x * g.x + g.z * g.z);
  // a solid counts when its surface can come within (1 + cfl) h of water in the longest step
  const auto near_water = [&](const core::SolidState& s, double radius, double speed) {
    const double reach = radius + (speed + a * dt) * dt + (1.0 + set.time.cfl) * set.spec.h;
    return particles::near_particles(occupancy.count, set.spec, s.x, reach);
  };
  const dem::SurfaceMotion s = dem::surface_motion(*dem, L.comm, near_water);
  return {s.speed, s.accel};
}

// Built on every rank of a run with bodies, also where none is near this step: a rank a solid
// has just left must not keep its old apertures, nor one it is about to enter lack cut cells.
bool CutCellsAhead::matches(const dem::SolidScene& scene, const grid::Decomposition& d) const {
  if (!valid || !(window == d.storage(Stagger::Cell))) return false;
  if (placements.size() != scene.placements.size() || obstacles.size() != scene.obstacles.size())
    return false;
  for (std::size_t b = 0; b < placements.size(); ++b) {
    const geometry::SolidPlacement &a = placements[b], &s = scene.placements[b];
    if (a.id != s.id || a.shape != s.shape || !(a.pose.x == s.pose.x) ||
        a.pose.theta != s.pose.theta)
      return false;
  }
  for (std::size_t o = 0; o < obstacles.size(); ++o)
    if (obstacles[o].name != scene.obstacles[o].name ||
        obstacles[o].polygons != scene.obstacles[o].polygons)
      return false;
  return true;
}

SolidsAtStart place_solids(const Layout& L, const StepSettings& set, const dem::DemSolver* dem,
                           const std::vector<geometry::Obstacle>& obstacles,
                           fluid::Apertures& apertures, CutCellsAhead& ahead) {
  core::ScopedTimer timer("geometry");
  SolidsAtStart out;
  out.scene = dem::scene_of(dem, obstacles);
  if (set.has_bodies) {
    const bool still = dem == nullptr;  // obstacles alone: the same cut cells every step
    if (ahead.matches(out.scene, L.d)) {
      out.cut = still ? ahead.cut : std::move(ahead.cut);
      apertures = still ? ahead.apertures : std::move(ahead.apertures);
      ahead.valid = still;
    } else {
      out.cut = fluid::cut_cells(out.scene.placements, out.scene.obstacles, set.tiny_fraction, L.d,
                                 apertures);
      ahead.valid = false;
      if (still)
        ahead = {true,
                 out.scene.placements,
                 out.scene.obstacles,
                 L.d.storage(Stagger::Cell),
                 out.cut,
                 apertures};
    }
  }
  if (set.fluid.open.any()) fluid::open_side_apertures(apertures, set.fluid.open, L.d);
  return out;
}

// The occupancy S, divided by the tent's open share next to bodies, the level set and the cell
// states (fluid::mark_cells).
void mark_cells(const Layout& L, const StepSettings& set, const geometry::CutCells& cut,
                const particles::ParticleSet& particles, particles::OccupancyPass& occ,
                fluid::FluidState& fluid) {
  core::ScopedTimer timer("transfer: mark cells");
  occ.update(particles, L.d, L.halo, set.particles, true);
  fluid.occupancy = occ.S;
  occ.current = false;  // the particles move before the next use
  fluid::mark_cells(occ.count, set.has_bodies ? &cut : nullptr, L.d, L.halo,
                    set.surface.ghost_fluid, set.surface.theta_min, set.surface.theta_open_length,
                    fluid);
  // p = 0 on the outflow faces themselves (doc/open_boundaries.md)
  if (set.surface.ghost_fluid && set.fluid.open.any())
    fluid::open_surface_fractions(fluid.surface, set.fluid.open, L.d);
}

// u~ before forces is kept for the FLIP increment.
void particles_to_grid(const Layout& L, const StepSettings& set, const SolidsAtStart& solids,
                       const particles::ParticleSet& particles, particles::OccupancyPass& occ,
                       fluid::FluidState& f) {
  core::ScopedTimer timer("transfer: particles to grid");
  if (occ.sums_current)  // the sums of the occupancy's pass: the same particles
    particles::to_grid(occ.sums, L.halo, f.u, f.w, f.weight_u, f.weight_w);
  else
    particles::to_grid(particles, L.d, L.halo, set.particles, f.u, f.w, f.weight_u, f.weight_w);
  occ.sums_current = false;
  fluid::enforce_walls(f.u, f.w, set.fluid, L.d);
  const geometry::CutCells* cut = set.has_bodies ? &solids.cut : nullptr;
  fluid::extend_around_fluid(solids.scene.states, cut, L.d, L.halo, true, f);
  f.u_old = f.u, f.w_old = f.w;
}

// Viscosity explicit, or implicit at the true boundaries of every solid (at X^n) and obstacle.
fluid::ViscousExchange add_forces(const Layout& L, const fluid::FluidConfig& cfg, bool rigid_rows,
                                  const dem::DemSolver* dem,
                                  const std::vector<geometry::Obstacle>& obstacles, double dt,
                                  const fluid::SurfaceFractions* surface, fluid::FluidState& f) {
  core::ScopedTimer timer("forces");
  fluid::ViscousExchange viscous;
  if (!cfg.implicit_viscosity) {
    fluid::add_forces_explicit(cfg, dt, L.d, L.halo, f);
  } else {
    // every rank solves the whole grid
    const dem::SolidScene all = dem::scene_of_all(dem, obstacles);
    viscous = fluid::add_forces_implicit(
        cfg, fluid::viscous_bodies(all.placements, all.states, all.obstacles, rigid_rows),
        all.states, dem::owned_solids(dem), rigid_rows, dt, surface, L.d, L.halo, L.comm, f);
  }
  // outflow faces with du_n / dn = 0 before the projection (doc/open_boundaries.md)
  if (std::any_of(cfg.open.side.begin(), cfg.open.side.end(),
                  [](const fluid::OpenSide& s) { return s.zero_gradient; })) {
    fluid::zero_gradient_outflow(f.u, f.w, cfg.open, L.d);
    fluid::enforce_walls(f.u, f.w, cfg, L.d);
  }
  return viscous;
}

// Collision loads for eq. 6 inside the PPE.
std::vector<core::SolidLoads> predict_contacts(const dem::DemSolver* dem, double dt) {
  core::ScopedTimer timer("contact prediction");
  return dem ? dem->predicted_collision_loads(dt) : std::vector<core::SolidLoads>{};
}

// The E-weighted PPE with the solids' velocities substituted (eqs. 5-6), solved implicitly.
fluid::SolveStats solve_pressure(const Layout& L, const StepSettings& set,
                                 const SolidsAtStart& solids,
                                 const std::vector<core::SolidLoads>& collision, double dt,
                                 fluid::PressureSolver& solver, fluid::FluidState& f) {
  std::vector<fluid::SolidCoupling> couplings;
  if (set.has_solids) {  // collective: on every rank of a run with solids
    core::ScopedTimer timer("geometry");
    couplings = fluid::solid_couplings(solids.scene.states, solids.cut, f.cells, L.d, collision,
                                       set.quadrature, dt);
  }
  core::ScopedTimer timer("pressure");
  return solver.solve(f.cells, f.apertures, f.u, f.w, couplings, dt, set.fluid, f.p,
                      set.surface.ghost_fluid ? &f.surface : nullptr);
}

void project(const Layout& L, const StepSettings& set, double dt, fluid::FluidState& f) {
  core::ScopedTimer timer("project");
  fluid::project(f.u, f.w, f.p, f.cells, f.apertures, dt, set.fluid,
                 set.surface.ghost_fluid ? &f.surface : nullptr);
  fluid::enforce_walls(f.u, f.w, set.fluid, L.d);
}

// F_fluid = J p^{n+1} + F_q from the rows of the pressure solve plus the step's viscous loads,
// then K DEM subcycles with it fixed (the DEM takes the loads of the solids it owns).
std::vector<core::SolidLoads> advance_solids(const fluid::PressureSolver* pressure,
                                             const fluid::FluidState* fluid, double dt,
                                             const fluid::ViscousExchange& viscous,
                                             dem::DemSolver& dem) {
  core::ScopedTimer timer("solids");
  std::vector<core::SolidLoads> loads;
  if (pressure && fluid) loads = pressure->solid_loads(fluid->p);
  dem.advance(dt,
              viscous.solids.empty() ? loads : fluid::plus_viscous(loads, viscous, dem.owned()));
  return loads;
}

// Faces closed by solids carry the solids' new rigid velocities, in u_old as well: the FLIP
// increment u - u_old is the fluid's change only, not a body sweeping over a face.
void grid_to_particles(const Layout& L, const StepSettings& set, const SolidsAtStart& solids,
                       const dem::SolidScene& after, const dem::DemSolver* dem,
                       fluid::FluidState& f, particles::ParticleSet& particles) {
  core::ScopedTimer timer("transfer: grid to particles");
  // the faces closed by bodies at X^n carry their velocities at X^{n+1}; the fluid-face mask of
  // P2G is kept (cells and apertures unchanged since)
  const geometry::CutCells* cut = set.has_bodies ? &solids.cut : nullptr;
  const auto motions = dem::motions_at(solids.scene, after);
  fluid::extend_around_fluid(motions, cut, L.d, L.halo, false, f);
  fluid::enforce_walls(f.u, f.w, set.fluid, L.d);
  if (set.has_bodies) fluid::rigid_faces_into_flip_base(set.spec, f);
  // the particles and their advection see the cut faces' mixture velocity
  if (cut && set.mixture_cut_faces) fluid::mix_cut_faces(motions, *cut, L.d, f);
  particles::from_grid(particles, set.particles, f.u_old, f.w_old, f.u, f.w, set.spec);
  if (dem && set.beta < 1.0)
    damp_gap_particles(particles, dem::all_contacts(*dem, L.comm), set.spec.h, set.beta);
}

namespace {

// A particle that ends inside a solid goes just outside it (none without bodies).
std::function<void(double&, double&)> push_out_of_solids(const StepSettings& set,
                                                         const dem::SolidLocator& locator) {
  if (!set.has_bodies) return {};
  const double h = set.spec.h;
  return [&locator, h](double& x, double& z) { geometry::push_out(locator, h, x, z); };
}

}  // namespace

// Particles crowded above the bulk density (S > 1), or thinned inside the water, are moved
// (positions only: velocities untouched) by the displacement of fluid::density_displacement.
bool correct_density(const Layout& L, const StepSettings& set, long long step,
                     const SolidsAtStart& solids, const fluid::FluidState& f,
                     fluid::PressureSolver* solver, particles::ParticleSet& particles) {
  if (!set.surface.corrects_density(step)) return false;
  core::ScopedTimer timer("density correction");
  FaceField dx(L.d, Stagger::FaceX, 0.0), dz(L.d, Stagger::FaceZ, 0.0);
  if (!fluid::density_displacement(
          f, set.has_bodies ? &solids.cut : nullptr, set.fluid, set.surface.density_relaxation,
          set.surface.ghost_fluid ? &f.surface : nullptr, *solver, L.d, L.halo, L.comm, dx, dz))
    return false;
  const dem::SolidLocator locator(solids.scene);
  particles::advect(particles, set.particles, dx, dz, set.spec, 1.0,
                    push_out_of_solids(set, locator));
  particles::migrate(particles, L.d);
  return true;
}

// A cut cell holds fewer particles than a full one (its fluid part is smaller): reseeding it up
// to particles/min_per_cell would add water every step. Cut cells are left out of reseeding.
double advect_particles(const Layout& L, const StepSettings& set, long long step,
                        const geometry::CutCells& cut, const dem::SolidScene& after, double dt,
                        const fluid::FluidState& f, particles::ParticleSet& particles) {
  core::ScopedTimer timer("advect");
  const dem::SolidLocator locator(after);
  const bool solids = set.has_bodies;
  const auto out_of_solids = push_out_of_solids(set, locator);
  // A blown-up advection is found on one rank: stop every rank with the message, never just one.
  std::string failure;
  double moved = 0.0;
  try {
    moved = particles::advect(particles, set.particles, f.u, f.w, set.spec, dt, out_of_solids);
  } catch (const core::SolverError& e) {
    failure = e.what();
  }
  L.comm.throw_if_any(failure);
  if (set.fluid.open.any()) {  // open sides: out through the outflows, in through the inflows
    std::vector<char> keep(particles.size(), 1);
    if (fluid::mark_outflow_particles(particles.x, particles.z, set.fluid.open, set.spec, keep) > 0)
      particles.keep_if(keep);
    std::function<bool(Vec2)> inside;
    if (solids) inside = [&](Vec2 p) { return locator.inside(p); };
    const fluid::InflowSeeding seeding{set.particles.per_cell_1d, set.particles.jitter,
                                       set.particles.seed};
    const double zero[4] = {0.0, 0.0, 0.0, 0.0};
    for (const auto& q : fluid::inflow_particles(seeding, set.fluid.open, L.d, inside))
      particles.push_back(q.id, q.position, q.velocity, zero);
  }
  particles::migrate(particles, L.d);
  grid::GridArray<int> count(L.d, Stagger::Cell, 0);
  particles::count_per_cell(particles, L.halo, count);
  std::function<bool(Vec2)> reject;
  if (solids) reject = [&](Vec2 p) { return locator.inside(p); };
  // The states are read only for cells below min_per_cell: without that bound, the fluid's own.
  fluid::CellStates cut_states;
  const fluid::CellStates* states = &f.cells;
  if (solids && set.particles.min_per_cell > 0) {
    cut_states = fluid::reseed_cells(f.cells, cut);
    states = &cut_states;
  }
  // Rank by rank (reseed has no collective): a rank with nothing to change is left as it is.
  if (particles::reseed_changes(set.particles, L.d, count, *states))
    particles::reseed(particles, set.particles, L.d, count, *states, f.u, f.w, step, reject);
  return L.comm.max(moved);
}

Diagnostics record_diagnostics(const Layout& L, const StepSettings& set, double t, long long step,
                               double dt, double advected, const fluid::SolveStats& solve,
                               const particles::ParticleSet& P, const dem::DemSolver* dem,
                               const geometry::CutCells* cut, particles::OccupancyPass& occ,
                               fluid::FluidState* fluid) {
  const core::Comm& comm = L.comm;
  Diagnostics g;
  g.t = t, g.dt = dt, g.step = step;
  g.advected = advected;
  g.ppe_iterations = solve.iterations;
  g.ppe_residual = solve.relative_residual;
  g.ppe_structure_reused = solve.reused_structure;
  const auto mine = particles::local_figures(P, set.particle_mass);
  const auto solid = dem ? dem::owned_figures(*dem, set.solid_count_box) : dem::OwnedFigures{};
  const bool finite = mine.finite && solid.finite;
  if (comm.any(!finite)) {
    std::ostringstream m;
    m << "step " << step << " at t = " << t
      << " s: a particle or solid has a non-finite position or velocity: the run has blown up";
    throw core::SolverError(m.str());
  }
  g.kinetic_energy = comm.sum(mine.kinetic_energy);
  g.solid_kinetic_energy = comm.sum(solid.kinetic_energy);
  g.front_x = fluid ? comm.max(mine.front) - set.spec.origin.x : 0.0;
  g.max_speed = comm.max(mine.max_speed);
  g.particles = comm.sum(static_cast<long long>(P.x.size()));
  if (fluid) {
    // S of the particles where the step leaves them: kept for the next step's cells, with P2G's
    // sums when the particles stay unmoved
    occ.update(P, L.d, L.halo, set.particles, !set.surface.corrects_density(step));
    fluid->occupancy = occ.S;
    if (cut) fluid::open_share_correction(fluid->occupancy, *cut, L.d);
    g.fluid_volume = fluid::occupied_area(fluid->occupancy, L.d, comm, cut);
  }
  for (double x : set.level_probes)
    g.levels.push_back(fluid ? fluid->surface_height(x) : std::nan(""));
  g.solids_in_box = comm.sum(solid.in_box);
  return g;
}

}  // namespace picdem::coupling
