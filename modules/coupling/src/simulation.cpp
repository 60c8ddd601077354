#include "picdem/coupling/simulation.hpp"

#include "checkpoint_state.hpp"
#include "simulation_state.hpp"
#include "viscous_bodies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "picdem/core/error.hpp"
#include "picdem/core/log.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/coupling/free_surface.hpp"
#include "picdem/coupling/output.hpp"
#include "picdem/coupling/solids_in_fluid.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/dem/parameters.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/fluid/viscous.hpp"
#include "picdem/geometry/obstacles.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/particles/particles.hpp"

namespace picdem::coupling {

using core::Vec2;
using grid::CellState;
using grid::FaceField;
using grid::Stagger;

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
  s.beta = params.real("coupling/beta");
  s.particle_cfg = particles::config_from(params);
  const int halo = std::max(3, particles::required_halo(s.particle_cfg));
  s.decomp = std::make_unique<grid::Decomposition>(
      s.spec, comm, halo, static_cast<int>(params.integer("grid/ranks_x")),
      static_cast<int>(params.integer("grid/ranks_z")));
  s.halo = std::make_unique<grid::Halo>(*s.decomp);
  const auto& d = *s.decomp;

  s.obstacles = geometry::obstacles_from(params);
  const auto solids = dem::solids_from(params);
  if (!solids.empty() || !s.has_fluid) {
    const core::Box2 tank{s.spec.origin, s.spec.origin + Vec2{s.spec.length(), s.spec.height()}};
    std::vector<std::vector<Vec2>> polys;
    for (const auto& o : s.obstacles)
      for (const auto& poly : o.polygons) polys.push_back(poly);
    s.dem = std::make_unique<dem::DemSolver>(comm, dem::config_from(params, s.spec.h),
                                             rank_regions(d), tank, polys);
    s.dem->add_solids(solids);
  }
  s.has_bodies = s.dem || !s.obstacles.empty();

  if (s.has_fluid) {
    s.fluid_cfg = fluid::config_from(params);
    if (s.fluid_cfg.implicit_viscosity && s.dem && comm.size() > 1)
      throw core::InputError(
          "fluid/viscosity_scheme: implicit runs on one rank when there are solids (each rank "
          "sees only its solids; doc/viscous.md)");
    s.quadrature = {params.boolean("coupling/hydrostatic_quadrature"), s.fluid_cfg.rho,
                    s.fluid_cfg.g};
    s.pressure = std::make_unique<fluid::PressureSolver>(d, params);
    s.density_relaxation = params.real("free_surface/density_correction");
    s.density_interval = params.integer("free_surface/density_correction_interval");
    if (s.density_relaxation > 0.0)
      s.density_solver = std::make_unique<fluid::PressureSolver>(d, params);
    s.fluid = fluid::FluidState(d);
    s.count = grid::GridArray<int>(d, Stagger::Cell, 0);
    s.ghost_fluid = params.string("free_surface/method") == "ghost_fluid";
    s.theta_min = params.real("free_surface/theta_min");
    // Water is seeded where neither solids nor obstacles are.
    const SolidScene scene0 = scene_of(s.dem.get(), s.obstacles);
    const SolidLocator locator(scene0);
    // Cells are seeded by their centre; particles that fall inside a body are then removed, so
    // that cut cells whose centre is covered still get particles in their fluid part.
    s.particles = particles::seed(d, s.particle_cfg, [&](Vec2 c) {
      const double r = 0.5 * s.spec.h;
      return inside_water(params, c) || inside_water(params, c + Vec2{r, r}) ||
             inside_water(params, c + Vec2{-r, r}) || inside_water(params, c + Vec2{r, -r}) ||
             inside_water(params, c + Vec2{-r, -r});
    });
    std::vector<char> keep(s.particles.size());
    for (std::size_t n = 0; n < keep.size(); ++n) {
      const Vec2 p{s.particles.x[n], s.particles.z[n]};
      keep[n] = inside_water(params, p) && !locator.inside(p);
    }
    s.particles.keep_if(keep);
    const double n = static_cast<double>(s.particle_cfg.per_cell_1d);
    s.particle_mass = s.fluid_cfg.rho * s.spec.h * s.spec.h / (n * n);
  }
  if (!output_dir.empty()) s.output = std::make_unique<Output>(comm, params, d, output_dir);
}

Simulation::~Simulation() = default;

const std::vector<std::string>& Diagnostics::scalar_names() {
  static const std::vector<std::string> names{"t",
                                              "dt",
                                              "step",
                                              "fluid_volume",
                                              "kinetic_energy",
                                              "ppe_iterations",
                                              "ppe_residual",
                                              "front_x",
                                              "particles",
                                              "max_speed",
                                              "solid_kinetic_energy"};
  return names;
}

std::vector<double> Diagnostics::scalars() const {
  return {t,
          dt,
          static_cast<double>(step),
          fluid_volume,
          kinetic_energy,
          static_cast<double>(ppe_iterations),
          ppe_residual,
          front_x,
          static_cast<double>(particles),
          max_speed,
          solid_kinetic_energy};
}

void Diagnostics::set_scalars(const std::vector<double>& v) {
  if (v.size() != scalar_names().size())
    throw std::invalid_argument("Diagnostics::set_scalars: " + std::to_string(v.size()) +
                                " values, expected " + std::to_string(scalar_names().size()));
  t = v[0], dt = v[1], step = static_cast<long long>(v[2]);
  fluid_volume = v[3], kinetic_energy = v[4];
  ppe_iterations = static_cast<int>(v[5]);
  ppe_residual = v[6], front_x = v[7], particles = static_cast<long long>(v[8]);
  max_speed = v[9], solid_kinetic_energy = v[10];
}

const Diagnostics& Simulation::diagnostics() const {
  return s_->diag;
}
double Simulation::time() const {
  return s_->t;
}
long long Simulation::step_count() const {
  return s_->step;
}
const core::Params& Simulation::params() const {
  return s_->params;
}

// ---------------------------------------------------------------------------------------------
// The phases of a step (paper Fig. 4). Each reads what the one before it left.

namespace {

// time step: CFL on the last grid velocity, capped; a collapse below dt_min is a blown-up run.
double choose_time_step(SimulationState& s) {
  const double dt_max = std::min(s.params.real("time/dt_max"), s.t_end - s.t);
  if (!s.has_fluid) return dt_max;
  // The particles may outrun the grid (FLIP): the fastest of either sets the CFL limit.
  const double cfl = s.params.real("time/cfl");
  double dt = std::min(dt_max, fluid::cfl_time_step(s.fluid.u, s.fluid.w, s.spec.h, cfl,
                                                    s.params.real("time/dt_max"), s.comm));
  dt = std::min(dt, fluid::viscous_time_limit(s.fluid_cfg));  // explicit viscosity's stability
  if (s.diag.max_speed > 0.0) dt = std::min(dt, cfl * s.spec.h / s.diag.max_speed);
  if (!(dt >= s.params.real("time/dt_min")) && s.t_end - s.t > s.params.real("time/dt_min")) {
    std::ostringstream m;
    m << "step " << s.step << " at t = " << s.t << " s: the time step fell to " << dt
      << " s (below time/dt_min): the flow has blown up";
    throw core::SolverError(m.str());
  }
  return dt;
}

// geometry: solids at X^n -> cut cells, face apertures E, wetted boundary pieces. Built on every
// rank of a run with bodies, also where none is near this step: a rank a solid has just left
// must not keep its old apertures, nor one it is about to enter lack cut cells.
void place_solids(SimulationState& s) {
  core::ScopedTimer timer("geometry");
  s.scene = scene_of(s.dem.get(), s.obstacles);
  if (!s.has_bodies) return;
  s.cut = cut_cells(s.scene, *s.decomp, s.params.real("coupling/tiny_cell_fraction"),
                    s.fluid.apertures);
}

// A cut cell whose sliver of fluid holds no particle, with S <= 1/2 at its (covered) centre, would
// be air: p = 0 inside the water, and a pressure jump that drives the flow through its faces at
// many times the speed around it. Such cells are taken in groups connected through open faces
// (two slivers side by side on a body); a group whose every other neighbour across an open face
// is fluid (or solid) cannot be at the free surface: it is fluid.
void wet_enclosed_cut_cells(SimulationState& s) {
  const auto fluid = static_cast<signed char>(CellState::Fluid);
  const auto air = static_cast<signed char>(CellState::Air);
  const auto solid = static_cast<signed char>(CellState::Solid);
  const auto b = s.fluid.cells.storage();
  auto candidate = [&](int i, int k) {
    return s.fluid.cells.in_storage(i, k) && s.fluid.cells(i, k) == air &&
           s.cut.fluid_fraction(i, k) < 1.0;
  };
  grid::GridArray<signed char> seen(*s.decomp, Stagger::Cell, 0);
  std::vector<std::pair<int, int>> group, todo;
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) {
      if (seen(i, k) || !candidate(i, k)) continue;
      group.clear();
      todo.assign(1, {i, k});
      seen(i, k) = 1;
      bool enclosed = true;
      while (!todo.empty()) {
        const auto [ci, ck] = todo.back();
        todo.pop_back();
        group.emplace_back(ci, ck);
        const struct {
          double E;
          int i, k;
        } faces[4] = {{s.fluid.apertures.E_x(ci, ck), ci - 1, ck},
                      {s.fluid.apertures.E_x(ci + 1, ck), ci + 1, ck},
                      {s.fluid.apertures.E_z(ci, ck), ci, ck - 1},
                      {s.fluid.apertures.E_z(ci, ck + 1), ci, ck + 1}};
        for (const auto& f : faces) {
          if (f.E <= 0.0 || f.i < 0 || f.k < 0 || f.i >= s.spec.nx || f.k >= s.spec.nz) continue;
          if (!s.fluid.cells.in_storage(f.i, f.k)) {
            enclosed = false;  // the group reaches the edge of this rank's window
            continue;
          }
          if (candidate(f.i, f.k)) {
            if (!seen(f.i, f.k)) seen(f.i, f.k) = 1, todo.emplace_back(f.i, f.k);
            continue;
          }
          const signed char nb = s.fluid.cells(f.i, f.k);
          enclosed = enclosed && (nb == fluid || nb == solid);
        }
      }
      if (enclosed)
        for (const auto& [gi, gk] : group) s.fluid.cells(gi, gk) = fluid;
    }
}

// transfer (cells): the particle occupancy S and the level set phi = 1/2 - S (free_surface.hpp),
// S divided by the share of the tent kernel open to fluid so that solids do not read as air.
// Cells: fluid = holds particles, or is a cut cell below the free surface (phi < 0: a cut cell
// may hold no particle in its sliver of fluid); solid = covered; air otherwise.
void mark_cells(SimulationState& s) {
  core::ScopedTimer timer("transfer: mark cells");
  particles::count_per_cell(s.particles, *s.halo, s.count);
  particle_occupancy(s.particles, *s.decomp, *s.halo,
                     s.particle_cfg.per_cell_1d * s.particle_cfg.per_cell_1d, s.fluid.occupancy);
  if (s.has_bodies) open_share_correction(s.fluid.occupancy, s.cut, *s.decomp);
  const auto b = s.fluid.cells.storage();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) {
      CellState c = s.count(i, k) > 0 ? CellState::Fluid : CellState::Air;
      const double S = s.fluid.occupancy(i, k);
      if (s.has_bodies) {
        const double f = s.cut.fluid_fraction(i, k);
        if (f <= 0.0)
          c = CellState::Solid;
        else if (c == CellState::Air && f < 1.0 && S > 0.5)
          c = CellState::Fluid;
      }
      s.fluid.phi(i, k) = 0.5 - S;
      s.fluid.cells(i, k) = static_cast<signed char>(c);
    }
  if (s.has_bodies) {
    wet_enclosed_cut_cells(s);
    // A group reaching the edge of one rank's window is seen whole by its owner: owners decide.
    s.halo->forward(s.fluid.cells);
  }
  if (s.ghost_fluid)
    s.fluid.surface = fluid::surface_fractions(s.fluid.phi, s.fluid.cells, *s.decomp, s.theta_min);
}

// Faces carrying fluid velocity (open, next to a fluid cell), plus faces closed by a body, which
// carry its rigid velocity; then velocities are extended into the rest.
void extend(SimulationState& s, FaceField& u, FaceField& w) {
  fluid::fluid_faces(s.fluid.cells, s.fluid.apertures, s.fluid.u_valid, s.fluid.w_valid);
  if (s.has_bodies)
    rigid_face_velocities(s.scene, s.cut, s.fluid.apertures, *s.decomp, u, w, s.fluid.u_valid,
                          s.fluid.w_valid);
  fluid::extend_velocity(u, w, s.fluid.u_valid, s.fluid.w_valid, s.decomp->halo(), *s.halo);
}

// transfer: particles -> grid faces; u~ before forces is kept for the FLIP increment.
void particles_to_grid(SimulationState& s) {
  core::ScopedTimer timer("transfer: particles to grid");
  particles::to_grid(s.particles, *s.decomp, *s.halo, s.particle_cfg, s.fluid.u, s.fluid.w,
                     s.fluid.weight_u, s.fluid.weight_w);
  fluid::enforce_walls(s.fluid.u, s.fluid.w, s.fluid_cfg, *s.decomp);
  extend(s, s.fluid.u, s.fluid.w);
  s.fluid.u_old = s.fluid.u, s.fluid.w_old = s.fluid.w;
}

// forces: gravity and viscosity (explicit, or implicit at the true boundaries) -> u~.
void add_forces(SimulationState& s, double dt) {
  core::ScopedTimer timer("forces");
  fluid::apply_gravity(s.fluid.u, s.fluid.w, s.fluid.cells, dt, s.fluid_cfg);
  if (s.fluid_cfg.implicit_viscosity)
    fluid::apply_viscosity_implicit(s.fluid.u, s.fluid.w, s.fluid.cells, dt, s.fluid_cfg, *s.decomp,
                                    *s.halo, viscous_bodies(s.scene));
  else
    fluid::apply_viscosity(s.fluid.u, s.fluid.w, s.fluid.cells, dt, s.fluid_cfg, *s.decomp,
                           *s.halo);
  fluid::enforce_walls(s.fluid.u, s.fluid.w, s.fluid_cfg, *s.decomp);
}

// contact: collision loads predicted at level n with dt in eq. 8 (for eq. 6 inside the PPE).
void predict_contacts(SimulationState& s, double dt) {
  core::ScopedTimer timer("contact prediction");
  s.collision_loads =
      s.dem ? s.dem->predicted_collision_loads(dt) : std::vector<core::SolidLoads>{};
}

// pressure: the E-weighted PPE with the solids' velocities substituted (eqs. 5-6), solved
// implicitly for p^{n+1}; the previous pressure is the initial guess.
void solve_pressure(SimulationState& s, double dt) {
  std::vector<fluid::SolidCoupling> couplings;
  if (s.dem) {
    core::ScopedTimer timer("geometry");
    couplings = solid_couplings(s.scene, s.cut, s.fluid.cells, *s.decomp, s.collision_loads,
                                s.quadrature, dt, s.comm);
  }
  core::ScopedTimer timer("pressure");
  s.last_solve =
      s.pressure->solve(s.fluid.cells, s.fluid.apertures, s.fluid.u, s.fluid.w, couplings, dt,
                        s.fluid_cfg, s.fluid.p, s.ghost_fluid ? &s.fluid.surface : nullptr);
}

// project: u^{n+1} = u~ - dt/rho grad p on open faces.
void project(SimulationState& s, double dt) {
  core::ScopedTimer timer("project");
  fluid::project(s.fluid.u, s.fluid.w, s.fluid.p, s.fluid.cells, s.fluid.apertures, dt, s.fluid_cfg,
                 s.ghost_fluid ? &s.fluid.surface : nullptr);
  fluid::enforce_walls(s.fluid.u, s.fluid.w, s.fluid_cfg, *s.decomp);
}

// solids: F_fluid = J p^{n+1}, then K DEM subcycles (eqs. 21-25) with it held fixed.
void advance_solids(SimulationState& s, double dt) {
  if (!s.dem) return;
  core::ScopedTimer timer("solids");
  s.fluid_loads.clear();
  if (s.has_fluid) s.fluid_loads = fluid_loads(*s.pressure, s.fluid.p, *s.dem);
  s.dem->advance(dt, s.fluid_loads);
}

// transfer: grid -> particles (FLIP/PIC blend or APIC), then gap damping (eq. 20).
void grid_to_particles(SimulationState& s) {
  core::ScopedTimer timer("transfer: grid to particles");
  // Faces closed by solids carry the solids' new rigid velocities, in u_old as well: the FLIP
  // increment u - u_old is the fluid's change only, not a body sweeping over a face. The scene
  // keeps the cut cells' body order (solids may have migrated between ranks in the DEM).
  s.scene = advanced_scene(s.scene, s.dem.get());
  extend(s, s.fluid.u, s.fluid.w);
  fluid::enforce_walls(s.fluid.u, s.fluid.w, s.fluid_cfg, *s.decomp);
  if (s.has_bodies) {
    const auto& spec = s.spec;
    const auto bu = s.fluid.u.storage(), bw = s.fluid.w.storage();
    for (int k = bu.k0; k < bu.k1; ++k)
      for (int i = bu.i0; i < bu.i1; ++i)
        if (i > 0 && i < spec.nx && s.fluid.apertures.E_x(i, k) <= 0.0)
          s.fluid.u_old(i, k) = s.fluid.u(i, k);
    for (int k = bw.k0; k < bw.k1; ++k)
      for (int i = bw.i0; i < bw.i1; ++i)
        if (k > 0 && k < spec.nz && s.fluid.apertures.E_z(i, k) <= 0.0)
          s.fluid.w_old(i, k) = s.fluid.w(i, k);
  }
  particles::from_grid(s.particles, s.particle_cfg, s.fluid.u_old, s.fluid.w_old, s.fluid.u,
                       s.fluid.w, s.spec);
  if (s.dem && s.beta < 1.0)
    damp_gap_particles(s.particles, all_contacts(*s.dem, s.comm), s.spec.h, s.beta);
}

// A particle that ends inside a solid goes just outside it (none without bodies).
std::function<void(double&, double&)> push_out_of_solids(const SimulationState& s,
                                                         const SolidLocator& locator) {
  if (!s.has_bodies) return {};
  const double h = s.spec.h;
  return [&locator, h](double& x, double& z) { push_out(locator, h, x, z); };
}

// density: particles crowded above the bulk density (S > 1), or thinned inside the water, are
// moved (positions only: velocities untouched) by d = -grad q, with -L_E q = the excess area of
// free_surface.hpp: the divergence of the displacement is that excess. Solids are fixed walls of
// this Poisson equation; q = 0 on the free surface. Returns whether particles moved (the cells
// are then marked again).
bool correct_density(SimulationState& s) {
  if (s.density_relaxation <= 0.0 || s.step % s.density_interval != 0) return false;
  core::ScopedTimer timer("density correction");
  const auto& d = *s.decomp;
  constexpr double cap = 0.5;  // |S - 1| taken at most: half a cell's particles per step
  grid::CellField source(d, Stagger::Cell, 0.0);
  const bool mine = excess_area(s.fluid.occupancy, s.fluid.cells, s.has_bodies ? &s.cut : nullptr,
                                s.density_relaxation, cap, d, source);
  if (!s.comm.any(mine)) return false;
  fluid::FluidConfig unit = s.fluid_cfg;
  unit.rho = 1.0, unit.no_slip = false;
  const fluid::SurfaceFractions* surface = s.ghost_fluid ? &s.fluid.surface : nullptr;
  FaceField dx(d, Stagger::FaceX, 0.0), dz(d, Stagger::FaceZ, 0.0);
  grid::CellField q(d, Stagger::Cell, 0.0);
  s.density_solver->solve(s.fluid.cells, s.fluid.apertures, dx, dz, {}, 1.0, unit, q, surface,
                          &source);
  fluid::project(dx, dz, q, s.fluid.cells, s.fluid.apertures, 1.0, unit, surface);
  // A displacement of more than half a cell would skip the stencil: capped.
  const double most = 0.5 * s.spec.h;
  for (auto* f : {&dx, &dz}) {
    const auto b = f->storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) (*f)(i, k) = std::clamp((*f)(i, k), -most, most);
  }
  // Closed faces (walls, bodies) hold 0 and count as known; the rest is extended.
  grid::GridArray<signed char> du(d, Stagger::FaceX, 0), dw(d, Stagger::FaceZ, 0);
  fluid::fluid_faces(s.fluid.cells, s.fluid.apertures, du, dw);
  for (auto [valid, E] :
       {std::pair{&du, &s.fluid.apertures.E_x}, std::pair{&dw, &s.fluid.apertures.E_z}}) {
    const auto b = valid->storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i)
        if ((*E)(i, k) <= 0.0) (*valid)(i, k) = 1;
  }
  s.halo->forward(dx), s.halo->forward(dz);
  fluid::enforce_walls(dx, dz, unit, d);
  fluid::extend_velocity(dx, dz, du, dw, d.halo(), *s.halo);
  const SolidLocator locator(s.scene);
  particles::advect(s.particles, s.particle_cfg, dx, dz, s.spec, 1.0,
                    push_out_of_solids(s, locator));
  particles::migrate(s.particles, d);
  return true;
}

// advect: move through the divergence-free field, out of solids, reseed, migrate.
void advect_particles(SimulationState& s, double dt) {
  core::ScopedTimer timer("advect");
  const SolidLocator locator(s.scene);
  const bool solids = s.has_bodies;
  const auto out_of_solids = push_out_of_solids(s, locator);
  // A blown-up advection is found on one rank: stop every rank with the message, never just one.
  std::string failure;
  try {
    particles::advect(s.particles, s.particle_cfg, s.fluid.u, s.fluid.w, s.spec, dt, out_of_solids);
  } catch (const core::SolverError& e) {
    failure = e.what();
  }
  if (s.comm.any(!failure.empty())) {
    std::string first = failure;
    for (int r = 0; r < s.comm.size(); ++r) {
      const std::string theirs = s.comm.broadcast(failure, r);
      if (first.empty() && !theirs.empty()) first = theirs;
    }
    throw core::SolverError(first);
  }
  particles::migrate(s.particles, *s.decomp);
  particles::count_per_cell(s.particles, *s.halo, s.count);
  std::function<bool(Vec2)> reject;
  if (solids) reject = [&](Vec2 p) { return locator.inside(p); };
  // A cut cell holds fewer particles than a full one (its fluid part is smaller): reseeding it up
  // to particles/min_per_cell would add water every step. Cut cells are left out of reseeding.
  const fluid::CellStates* reseed_cells = &s.fluid.cells;
  fluid::CellStates uncut;
  if (solids) {
    uncut = s.fluid.cells;
    const auto b = uncut.storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i)
        if (s.cut.fluid_fraction(i, k) < 1.0)
          uncut(i, k) = static_cast<signed char>(CellState::Solid);
    reseed_cells = &uncut;
  }
  particles::reseed(s.particles, s.particle_cfg, *s.decomp, s.count, *reseed_cells, s.fluid.u,
                    s.fluid.w, s.step, reject);
}

// Figures of the new state; a non-finite value anywhere stops the run on every rank.
void record_diagnostics(SimulationState& s, double dt) {
  Diagnostics& g = s.diag;
  g.t = s.t, g.dt = dt, g.step = s.step;
  g.ppe_iterations = s.last_solve.iterations;
  g.ppe_residual = s.last_solve.relative_residual;
  g.ppe_structure_reused = s.last_solve.reused_structure;
  double ke = 0.0, front = -std::numeric_limits<double>::infinity(), vmax = 0.0;
  bool finite = true;
  const auto& P = s.particles;
  for (std::size_t n = 0; n < P.x.size(); ++n) {
    const double v2 = P.u[n] * P.u[n] + P.w[n] * P.w[n];
    ke += 0.5 * s.particle_mass * v2;
    front = std::max(front, P.x[n]);
    vmax = std::max(vmax, std::sqrt(v2));
    finite = finite && std::isfinite(v2) && std::isfinite(P.x[n]) && std::isfinite(P.z[n]);
  }
  double ke_solids = 0.0;
  if (s.dem)
    for (const auto& st : s.dem->owned()) {
      ke_solids += 0.5 * st.mass * core::norm2(st.v) + 0.5 * st.inertia * st.omega * st.omega;
      finite = finite && std::isfinite(st.x.x) && std::isfinite(st.x.z) && std::isfinite(st.v.x);
    }
  if (s.comm.any(!finite)) {
    std::ostringstream m;
    m << "step " << s.step << " at t = " << s.t
      << " s: a particle or solid has a non-finite position or velocity: the run has blown up";
    throw core::SolverError(m.str());
  }
  g.kinetic_energy = s.comm.sum(ke);
  g.solid_kinetic_energy = s.comm.sum(ke_solids);
  g.front_x = s.has_fluid ? s.comm.max(front) - s.spec.origin.x : 0.0;
  g.max_speed = s.comm.max(vmax);
  g.particles = s.comm.sum(static_cast<long long>(P.x.size()));
  if (s.has_fluid) {
    particle_occupancy(s.particles, *s.decomp, *s.halo,
                       s.particle_cfg.per_cell_1d * s.particle_cfg.per_cell_1d, s.fluid.occupancy);
    if (s.has_bodies) open_share_correction(s.fluid.occupancy, s.cut, *s.decomp);
    g.fluid_volume =
        occupied_area(s.fluid.occupancy, *s.decomp, s.comm, s.has_bodies ? &s.cut : nullptr);
  }
  g.levels.clear();
  for (double x : s.params.reals("output/level_probes"))
    g.levels.push_back(s.has_fluid ? s.fluid.surface_height(x) : std::nan(""));
  const auto box = s.params.reals("output/solid_count_box");
  long long inside = 0;
  if (s.dem && box.size() == 4)
    for (const auto& st : s.dem->owned())
      inside += st.x.x >= box[0] && st.x.x <= box[1] && st.x.z >= box[2] && st.x.z <= box[3];
  g.solids_in_box = s.comm.sum(inside);
}

}  // namespace

void Simulation::step() {
  SimulationState& s = *s_;
  const double dt = choose_time_step(s);
  if (s.has_fluid) {
    place_solids(s);         // geometry
    mark_cells(s);           // transfer (cells)
    if (correct_density(s))  // density (positions only)
      mark_cells(s);
    particles_to_grid(s);     // transfer
    add_forces(s, dt);        // forces
    predict_contacts(s, dt);  // contact
    solve_pressure(s, dt);    // pressure
    project(s, dt);           // project
    advance_solids(s, dt);    // solids
    grid_to_particles(s);     // transfer
    advect_particles(s, dt);  // advect
  } else {
    advance_solids(s, dt);  // dry: solids only
  }
  s.t += dt;
  ++s.step;
  record_diagnostics(s, dt);
}

const fluid::FluidState& Simulation::fluid() const {
  if (!s_->has_fluid) throw std::logic_error("Simulation::fluid(): the case has no water");
  return s_->fluid;
}

const particles::ParticleSet& Simulation::particles() const {
  return s_->particles;
}

const dem::DemSolver* Simulation::dem() const {
  return s_->dem.get();
}

std::vector<core::SolidLoads> Simulation::fluid_loads() const {
  const SimulationState& s = *s_;
  std::vector<double> mine;
  for (const auto& l : s.fluid_loads)
    mine.insert(mine.end(), {static_cast<double>(l.id), l.force.x, l.force.z, l.torque});
  const auto all = s.comm.all_gather(mine);
  std::vector<core::SolidLoads> out;
  for (std::size_t n = 0; n + 4 <= all.size(); n += 4)
    out.push_back({static_cast<std::int64_t>(all[n]), {all[n + 1], all[n + 2]}, all[n + 3]});
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  return out;
}

void Simulation::run(long long max_steps) {
  SimulationState& s = *s_;
  core::Progress progress(s.comm, s.t, s.t_end, s.params.real("output/progress_seconds"));
  if (s.output && !s.restarted)
    s.output->frame(s.t, s.step, s.diag, s.particles, s.fluid.p, s.fluid.cells, s.dem.get(),
                    s.obstacles, true);
  const CheckpointConfig& ck = s.checkpoint;
  double wall_last_checkpoint = core::wall_seconds();
  long long last_checkpoint_step = s.restarted ? s.step : -1;
  auto checkpoint = [&] {
    Simulation::write_checkpoint(ck.directory + "/" + checkpoint_file_name(s.step));
    prune_checkpoints(s.comm, ck.directory, ck.keep);
    wall_last_checkpoint = core::wall_seconds();
    last_checkpoint_step = s.step;
  };
  s.stopped_by_signal = false;
  while (s.t < s.t_end * (1.0 - 1e-12) && (max_steps <= 0 || s.step < max_steps)) {
    step();
    check_step(s.diag, s.spec.h, s.has_fluid, s.dem.get(), s.comm);
    if (s.output) {
      s.output->record(s.diag);
      s.output->frame(s.t, s.step, s.diag, s.particles, s.fluid.p, s.fluid.cells, s.dem.get(),
                      s.obstacles, false);
    }
    progress.report(s.t, s.step, s.diag.dt, s.diag.ppe_iterations);
    const bool stop = s.comm.any(stop_signal_received());
    if (!ck.directory.empty()) {
      const bool by_steps = ck.every_steps > 0 && s.step % ck.every_steps == 0;
      const bool by_time =
          ck.every_seconds > 0.0 &&
          s.comm.max(core::wall_seconds() - wall_last_checkpoint) >= ck.every_seconds;
      if (stop || by_steps || by_time) checkpoint();
    }
    if (stop) {
      core::log(s.comm,
                "picdem: stop signal at step " + std::to_string(s.step) +
                    (ck.directory.empty() ? ", no checkpoint directory" : ": checkpoint written") +
                    ", stopping");
      s.stopped_by_signal = true;
      return;
    }
  }
  progress.report(s.t, s.step, s.diag.dt, s.diag.ppe_iterations, true);
  if (!ck.directory.empty() && ck.at_end && last_checkpoint_step != s.step) checkpoint();
  if (s.output)
    s.output->finish(s.t, s.step, s.diag, s.particles, s.fluid.p, s.fluid.cells, s.dem.get(),
                     s.obstacles);
}

namespace {
CheckpointParts checkpoint_parts(SimulationState& s) {
  return {s.comm, s.params, *s.decomp, s.particles, s.has_fluid ? &s.fluid : nullptr, s.dem.get()};
}
}  // namespace

void Simulation::enable_checkpoints(const std::string& directory) {
  SimulationState& s = *s_;
  s.checkpoint = checkpoint_config_from(s.params, "");
  s.checkpoint.directory = directory;
  if (!directory.empty()) open_checkpoint_directory(s.comm, directory, !s.restarted);
}

void Simulation::restart_from(const std::string& checkpoint, const std::string& output_dir) {
  SimulationState& s = *s_;
  const CheckpointHeader head = read_checkpoint(checkpoint_parts(s), checkpoint);
  s.t = head.t, s.step = head.step, s.diag = head.diag;
  const Output::Mark& mark = head.mark;
  s.restarted = true;
  s.output.reset();
  if (!output_dir.empty())
    s.output = std::make_unique<Output>(s.comm, s.params, *s.decomp, output_dir, &mark, s.t);
  core::log(s.comm, "picdem: restarted from " + checkpoint + " at step " + std::to_string(s.step) +
                        ", t = " + std::to_string(s.t) + " s");
}

void Simulation::write_checkpoint(const std::string& path) const {
  SimulationState& s = *s_;  // the parts are only read
  const CheckpointHeader head{s.t, s.step, s.diag, s.output ? s.output->mark() : Output::Mark{}};
  coupling::write_checkpoint(checkpoint_parts(s), head, path);
}

bool Simulation::stopped_by_signal() const {
  return s_->stopped_by_signal;
}

}  // namespace picdem::coupling
