#include "picdem/coupling/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/core/log.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/coupling/free_surface.hpp"
#include "picdem/coupling/output.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/dem/parameters.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/geometry/obstacles.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/particles/particles.hpp"

namespace picdem::coupling {

using core::Vec2;
using grid::CellState;
using grid::FaceField;
using grid::Stagger;

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
  FaceField u, w, u_old, w_old, weight_u, weight_w;
  grid::CellField p;
  fluid::CellStates cells;
  grid::GridArray<int> count;
  grid::CellField occupancy;  // S of free_surface.hpp
  fluid::Apertures apertures;
  double particle_mass = 0.0;  // per unit depth

  // solids
  std::vector<geometry::Obstacle> obstacles;
  std::unique_ptr<dem::DemSolver> dem;

  // run
  double t = 0.0, t_end = 0.0;
  long long step = 0;
  Diagnostics diag;
  std::unique_ptr<Output> output;
};

namespace {

bool inside_water(const core::Params& params, const Vec2& c) {
  for (const auto& name : params.sublist_names("water")) {
    const auto w = params.sub("water/" + name);
    if (w.string("type") == "box") {
      const auto x = w.reals("x"), z = w.reals("z");
      if (c.x >= x[0] && c.x <= x[1] && c.z >= z[0] && c.z <= z[1]) return true;
    } else if (c.z <= w.real("z")) {
      return true;
    }
  }
  return false;
}

std::vector<core::Box2> rank_regions(const grid::Decomposition& d) {
  std::vector<core::Box2> out;
  const auto& s = d.spec();
  for (int r = 0; r < d.size(); ++r) {
    const auto b = d.owned_cells(r);
    out.push_back({{s.origin.x + b.i0 * s.h, s.origin.z + b.k0 * s.h},
                   {s.origin.x + b.i1 * s.h, s.origin.z + b.k1 * s.h}});
  }
  return out;
}

}  // namespace

Simulation::Simulation(core::Comm comm, core::Params params, std::string output_dir)
    : s_(std::make_unique<SimulationState>()) {
  SimulationState& s = *s_;
  s.comm = comm;
  s.params = params;
  s.spec = grid::spec_from(params);
  s.t_end = params.real("time/end");
  s.has_fluid = !params.sublist_names("water").empty();
  s.particle_cfg = particles::config_from(params);
  const int halo = std::max(3, particles::required_halo(s.particle_cfg));
  s.decomp = std::make_unique<grid::Decomposition>(s.spec, comm, halo,
                                                   static_cast<int>(params.integer("grid/ranks_x")),
                                                   static_cast<int>(params.integer("grid/ranks_z")));
  s.halo = std::make_unique<grid::Halo>(*s.decomp);
  const auto& d = *s.decomp;

  s.obstacles = geometry::obstacles_from(params);
  const auto solids = dem::solids_from(params);
  if (s.has_fluid && (!solids.empty() || !s.obstacles.empty()))
    throw core::InputError(
        "this case has water together with solids or obstacles: the fluid-solid coupling is not "
        "part of this version; remove `solids`/`obstacles` or `water`");

  if (!solids.empty() || !s.has_fluid) {
    const core::Box2 tank{s.spec.origin, s.spec.origin + Vec2{s.spec.length(), s.spec.height()}};
    std::vector<std::vector<Vec2>> polys;
    for (const auto& o : s.obstacles)
      for (const auto& poly : o.polygons) polys.push_back(poly);
    s.dem = std::make_unique<dem::DemSolver>(comm, dem::config_from(params, s.spec.h),
                                             rank_regions(d), tank, polys);
    s.dem->add_solids(solids);
  }

  if (s.has_fluid) {
    s.fluid_cfg = fluid::config_from(params);
    s.pressure = std::make_unique<fluid::PressureSolver>(d, params);
    s.u = FaceField(d, Stagger::FaceX);
    s.w = FaceField(d, Stagger::FaceZ);
    s.u_old = s.u, s.w_old = s.w, s.weight_u = s.u, s.weight_w = s.w;
    s.p = grid::CellField(d, Stagger::Cell);
    s.cells = fluid::CellStates(d, Stagger::Cell, static_cast<signed char>(CellState::Air));
    s.count = grid::GridArray<int>(d, Stagger::Cell, 0);
    s.occupancy = grid::CellField(d, Stagger::Cell);
    s.apertures = fluid::open_apertures(d);
    s.particles = particles::seed(d, s.particle_cfg,
                                  [&](Vec2 c) { return inside_water(params, c); });
    const double n = static_cast<double>(s.particle_cfg.per_cell_1d);
    s.particle_mass = s.fluid_cfg.rho * s.spec.h * s.spec.h / (n * n);
  }
  if (!output_dir.empty()) s.output = std::make_unique<Output>(comm, params, d, output_dir);
}

Simulation::~Simulation() = default;

const Diagnostics& Simulation::diagnostics() const { return s_->diag; }
double Simulation::time() const { return s_->t; }
long long Simulation::step_count() const { return s_->step; }
const core::Params& Simulation::params() const { return s_->params; }

// ---------------------------------------------------------------------------------------------
// Phases of a step (paper Fig. 4). Each reads the state left by the one before it.

namespace {

// transfer (cells): a cell holding particles is fluid, else air.
void mark_cells(SimulationState& s) {
  core::ScopedTimer timer("transfer: mark cells");
  particles::count_per_cell(s.particles, *s.halo, s.count);
  const auto b = s.cells.storage();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i)
      s.cells(i, k) = static_cast<signed char>(s.count(i, k) > 0 ? CellState::Fluid : CellState::Air);
}

void extend(SimulationState& s, FaceField& u, FaceField& w) {
  grid::GridArray<signed char> vu(*s.decomp, Stagger::FaceX, 0), vw(*s.decomp, Stagger::FaceZ, 0);
  fluid::fluid_faces(s.cells, s.apertures, vu, vw);
  fluid::extend_velocity(u, w, vu, vw, s.decomp->halo(), *s.halo);
}

}  // namespace

void Simulation::step() {
  SimulationState& s = *s_;
  if (!s.has_fluid) {
    const double dt = std::min(s.params.real("time/dt_max"), s.t_end - s.t);
    s.dem->advance(dt, {});
    s.t += dt;
    ++s.step;
    s.diag.t = s.t, s.diag.dt = dt, s.diag.step = s.step;
    return;
  }
  const auto& d = *s.decomp;
  const auto& cfg = s.fluid_cfg;

  // time step from the CFL condition on the last grid velocity
  double dt = fluid::cfl_time_step(s.u, s.w, s.spec.h, s.params.real("time/cfl"),
                                   s.params.real("time/dt_max"), s.comm);
  dt = std::min(dt, s.t_end - s.t);
  if (!(dt >= s.params.real("time/dt_min")) && s.t_end - s.t > s.params.real("time/dt_min")) {
    std::ostringstream m;
    m << "step " << s.step << " at t = " << s.t << " s: the time step fell to " << dt
      << " s (below time/dt_min): the flow has blown up";
    throw core::SolverError(m.str());
  }

  // transfer: particles -> grid (u~ before forces is kept for the FLIP increment)
  mark_cells(s);
  {
    core::ScopedTimer timer("transfer: particles to grid");
    particles::to_grid(s.particles, d, *s.halo, s.particle_cfg, s.u, s.w, s.weight_u, s.weight_w);
    fluid::enforce_walls(s.u, s.w, cfg, d);
    extend(s, s.u, s.w);
    s.u_old = s.u, s.w_old = s.w;
  }

  // forces: gravity and explicit viscosity -> u~
  {
    core::ScopedTimer timer("forces");
    fluid::apply_gravity(s.u, s.w, s.cells, dt, cfg);
    fluid::apply_viscosity(s.u, s.w, s.cells, dt, cfg, d, *s.halo);
    fluid::enforce_walls(s.u, s.w, cfg, d);
  }

  // pressure: E-weighted PPE, previous pressure as the initial guess
  fluid::SolveStats stats;
  {
    core::ScopedTimer timer("pressure");
    stats = s.pressure->solve(s.cells, s.apertures, s.u, s.w, {}, dt, cfg, s.p);
  }

  // project: u^{n+1} = u~ - dt/rho grad p; extend into air; walls
  {
    core::ScopedTimer timer("project");
    fluid::project(s.u, s.w, s.p, s.cells, s.apertures, dt, cfg);
    fluid::enforce_walls(s.u, s.w, cfg, d);
    extend(s, s.u, s.w);
    fluid::enforce_walls(s.u, s.w, cfg, d);
  }

  // transfer: grid -> particles
  {
    core::ScopedTimer timer("transfer: grid to particles");
    particles::from_grid(s.particles, s.particle_cfg, s.u_old, s.w_old, s.u, s.w, s.spec);
  }

  // advect: move, reseed, migrate
  {
    core::ScopedTimer timer("advect");
    particles::advect(s.particles, s.particle_cfg, s.u, s.w, s.spec, dt);
    particles::migrate(s.particles, d);
    particles::count_per_cell(s.particles, *s.halo, s.count);
    particles::reseed(s.particles, s.particle_cfg, d, s.count, s.cells, s.u, s.w, s.step);
  }

  s.t += dt;
  ++s.step;

  // diagnostics
  Diagnostics& g = s.diag;
  g.t = s.t, g.dt = dt, g.step = s.step;
  g.ppe_iterations = stats.iterations;
  g.ppe_residual = stats.relative_residual;
  double ke = 0.0, front = -std::numeric_limits<double>::infinity(), vmax = 0.0;
  const auto& P = s.particles;
  for (std::size_t n = 0; n < P.x.size(); ++n) {
    const double v2 = P.u[n] * P.u[n] + P.w[n] * P.w[n];
    ke += 0.5 * s.particle_mass * v2;
    front = std::max(front, P.x[n]);
    vmax = std::max(vmax, std::sqrt(v2));
    if (!std::isfinite(v2) || !std::isfinite(P.x[n]) || !std::isfinite(P.z[n])) {
      std::ostringstream m;
      m << "step " << s.step << " at t = " << s.t << " s: particle " << P.id[n]
        << " has a non-finite position or velocity: the flow has blown up";
      throw core::SolverError(m.str());
    }
  }
  g.kinetic_energy = s.comm.sum(ke);
  g.front_x = s.comm.max(front) - s.spec.origin.x;
  g.max_speed = s.comm.max(vmax);
  g.particles = s.comm.sum(static_cast<long long>(P.x.size()));
  particle_occupancy(s.particles, d, *s.halo, s.particle_cfg.per_cell_1d * s.particle_cfg.per_cell_1d,
                     s.occupancy);
  g.fluid_volume = occupied_area(s.occupancy, d, s.comm);
}

double Simulation::pressure_at(double x, double z) const {
  const SimulationState& s = *s_;
  int i, k;
  s.spec.cell_of({x, z}, i, k);
  const double mine = s.has_fluid && s.decomp->owned_cells().contains(i, k) ? s.p(i, k) : 0.0;
  return s.comm.sum(mine);
}

double Simulation::max_grid_speed() const {
  const SimulationState& s = *s_;
  if (!s.has_fluid) return 0.0;
  grid::GridArray<signed char> vu(*s.decomp, Stagger::FaceX, 0), vw(*s.decomp, Stagger::FaceZ, 0);
  fluid::fluid_faces(s.cells, s.apertures, vu, vw);
  double m = 0.0;
  const auto bu = s.decomp->owned(Stagger::FaceX), bw = s.decomp->owned(Stagger::FaceZ);
  for (int k = bu.k0; k < bu.k1; ++k)
    for (int i = bu.i0; i < bu.i1; ++i)
      if (vu(i, k)) m = std::max(m, std::abs(s.u(i, k)));
  for (int k = bw.k0; k < bw.k1; ++k)
    for (int i = bw.i0; i < bw.i1; ++i)
      if (vw(i, k)) m = std::max(m, std::abs(s.w(i, k)));
  return s.comm.max(m);
}

void Simulation::run(long long max_steps) {
  SimulationState& s = *s_;
  core::Progress progress(s.comm, s.t, s.t_end, s.params.real("output/progress_seconds"));
  if (s.output) s.output->frame(s.t, s.step, s.diag, s.particles, s.p, s.cells, s.dem.get(), s.obstacles, true);
  while (s.t < s.t_end * (1.0 - 1e-12) && (max_steps <= 0 || s.step < max_steps)) {
    step();
    if (s.output) {
      s.output->record(s.diag);
      s.output->frame(s.t, s.step, s.diag, s.particles, s.p, s.cells, s.dem.get(), s.obstacles, false);
    }
    progress.report(s.t, s.step, s.diag.dt, s.diag.ppe_iterations);
  }
  progress.report(s.t, s.step, s.diag.dt, s.diag.ppe_iterations, true);
  if (s.output) s.output->finish(s.t, s.step, s.diag, s.particles, s.p, s.cells, s.dem.get(), s.obstacles);
}

}  // namespace picdem::coupling
