#include "picdem/coupling/simulation.hpp"

#include "step_phases.hpp"

#include <algorithm>
#include <stdexcept>

#include "picdem/core/error.hpp"
#include "picdem/core/log.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/coupling/solids_in_fluid.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/dem/parameters.hpp"
#include "picdem/fluid/bodies.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/fluid/open_flow.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/geometry/obstacles.hpp"
#include "picdem/grid/balance.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/particles/occupancy_pass.hpp"
#include "picdem/particles/particles.hpp"
#include "picdem/particles/water.hpp"

namespace picdem::coupling {

using core::Vec2;

// The modules and the run's records; the step's phases (step_phases.hpp) get what each needs.
struct Simulation::Impl {
  core::Comm comm;
  core::Params params;
  StepSettings set;
  std::unique_ptr<grid::Decomposition> decomp;
  std::unique_ptr<grid::Halo> halo;

  // the modules' state
  fluid::FluidState fluid;  // empty without water
  std::unique_ptr<fluid::PressureSolver> pressure, density_solver;
  particles::ParticleSet particles;
  std::unique_ptr<dem::DemSolver> dem;  // null without solids (with water)
  std::vector<geometry::Obstacle> obstacles;
  particles::OccupancyPass occupancy;  // the particles' S, from the last diagnostics to the cells
  CutCellsAhead cut_ahead;             // the cut cells at the last step's X^{n+1}

  // the clock and what the last step reported
  double t = 0.0;
  long long step = 0;
  double last_dt = 0.0;  // the last step's dt (time/dt_growth); 0 before the first
  Diagnostics diag;
  std::vector<core::SolidLoads> fluid_loads;     // J p + F_q of the last step, by id (all ranks)
  fluid::ViscousExchange viscous;                // the last step's viscous loads (implicit scheme)
  std::vector<core::SolidLoads> obstacle_loads;  // J p + F_q of the last step, every obstacle

  Layout layout() const { return {*decomp, *halo, comm}; }
};

namespace {

// The water, out of the solids and obstacles at t = 0.
particles::ParticleSet seed_water(const Simulation::Impl& m) {
  const dem::SolidScene scene0 = dem::scene_of(m.dem.get(), m.obstacles);
  const dem::SolidLocator locator(scene0);
  return particles::seed_water(*m.decomp, m.set.particles, particles::WaterRegions(m.params),
                               [&](Vec2 p) { return locator.inside(p); });
}

// Collective: sets the cut lines and moves the state to the new owners (the fluid's saved fields
// with their ghosts, the particles, the solids), then rebuilds what holds maps of the old blocks.
void adopt_cuts(Simulation::Impl& m, const grid::Cuts& cuts) {
  {
    core::ScopedTimer timer("rebalance: move");
    const grid::Decomposition from = *m.decomp;
    m.decomp->set_cuts(cuts.xs, cuts.zs);
    m.halo = std::make_unique<grid::Halo>(*m.decomp);
    if (m.set.has_fluid) m.fluid = fluid::redistributed(m.fluid, from, *m.decomp);
    particles::migrate(m.particles, *m.decomp);
    if (m.dem) m.dem->set_regions(grid::owned_regions(*m.decomp));
  }
  m.occupancy = particles::OccupancyPass{};  // on the old blocks: scattered again by the next step
  if (m.pressure) m.pressure = std::make_unique<fluid::PressureSolver>(*m.decomp, m.params);
  if (m.density_solver)
    m.density_solver = std::make_unique<fluid::PressureSolver>(
        *m.decomp, m.params, fluid::PressureSolver::Equation::DensityCorrection);
}

// A dry run's work per owned cell: the solids, kWorkSolid at the cell of each centre, over every
// cell's kWorkCell (a dry run has no grid work; the DEM's subcycles are the whole step).
constexpr long long kWorkSolid = 1000;
std::vector<long long> solid_work(const grid::Decomposition& d, const dem::DemSolver& dem) {
  const auto& spec = d.spec();
  const core::IndexBox own = d.owned_cells();
  std::vector<long long> work(static_cast<std::size_t>(own.size()), particles::kWorkCell);
  for (const auto& s : dem.owned()) {
    int i, k;
    spec.cell_of(s.x, i, k);
    if (own.contains(i, k))
      work[static_cast<std::size_t>(k - own.k0) * static_cast<std::size_t>(own.nx()) +
           static_cast<std::size_t>(i - own.i0)] += kWorkSolid;
  }
  return work;
}

// grid/decomposition = weighted: cut lines balancing the particles' work (particles::cell_work)
// or, in a dry run, the solids' (solid_work), by grid::worthwhile_cuts. A function of the
// particles or solids and the present cuts only, all of which a checkpoint keeps.
void rebalance_cuts(Simulation::Impl& m) {
  if (!m.set.balance.weighted || m.comm.size() == 1) return;
  if (!m.set.has_fluid && !m.dem) return;
  const auto cuts =
      grid::worthwhile_cuts(*m.decomp,
                            m.set.has_fluid ? particles::cell_work(*m.decomp, m.particles)
                                            : solid_work(*m.decomp, *m.dem),
                            m.set.balance);
  if (!cuts) return;
  adopt_cuts(m, *cuts);
  core::log(m.comm, "picdem: step " + std::to_string(m.step) + ": " + grid::describe(*cuts));
}

}  // namespace

Simulation::Simulation(core::Comm comm, core::Params params) : m_(std::make_unique<Impl>()) {
  Impl& m = *m_;
  m.comm = comm;
  m.params = params;
  m.set = step_settings_from(params);
  const auto& spec = m.set.spec;
  const int halo = std::max(3, particles::required_halo(m.set.particles));
  m.decomp = std::make_unique<grid::Decomposition>(spec, comm, halo, m.set.balance.ranks_x,
                                                   m.set.balance.ranks_z);
  m.halo = std::make_unique<grid::Halo>(*m.decomp);
  const auto& d = *m.decomp;

  m.obstacles = geometry::obstacles_from(params);
  const auto solids = dem::solids_from(params);
  const core::Box2 tank{spec.origin, spec.origin + Vec2{spec.length(), spec.height()}};
  if (!solids.empty() || !m.set.has_fluid)
    m.dem =
        dem::solver_from(params, comm, spec.h, tank, grid::owned_regions(d), m.obstacles, solids);
  m.set.has_solids = m.dem != nullptr;
  m.set.has_bodies = m.dem || !m.obstacles.empty();

  if (m.set.has_fluid) {
    m.pressure = std::make_unique<fluid::PressureSolver>(d, params);
    if (m.set.surface.density_relaxation > 0.0)
      m.density_solver = std::make_unique<fluid::PressureSolver>(
          d, params, fluid::PressureSolver::Equation::DensityCorrection);
    m.fluid = fluid::FluidState(d);
    m.particles = seed_water(m);
    rebalance_cuts(m);
    if (m.set.fluid.open.any()) m.diag.open_volumes = {0.0, 0.0};  // in, out since t = 0
  } else {
    rebalance_cuts(m);  // a dry run: cut lines that share out the solids
  }
}

Simulation::~Simulation() = default;

Simulation::GridSplit Simulation::grid_split() const {
  return {m_->decomp->x_cuts(), m_->decomp->z_cuts()};
}

const Diagnostics& Simulation::diagnostics() const {
  return m_->diag;
}
double Simulation::time() const {
  return m_->t;
}
long long Simulation::step_count() const {
  return m_->step;
}
const core::Params& Simulation::params() const {
  return m_->params;
}

// The step in the order of the paper's Fig. 4: each phase's inputs and outputs are named here.
void Simulation::step() {
  Impl& m = *m_;
  const StepSettings& set = m.set;
  if (set.balance.due(m.step)) rebalance_cuts(m);
  const Layout L = m.layout();
  fluid::FluidState* fluid = set.has_fluid ? &m.fluid : nullptr;
  const auto motion = cfl_extra_motion(L, set, m.particles, m.occupancy, m.dem.get());  // dt
  const double dt =
      fluid::choose_time_step(set.time, set.fluid, m.t, m.step, fluid, motion, m.last_dt, m.comm);
  m.set.fluid.open.t0 = m.t, m.set.fluid.open.t1 = m.t + dt;  // the inflows over this step
  fluid::OpenFluxes open_flux;
  SolidsAtStart solids;          // at X^n
  geometry::CutCells cut_after;  // moving solids: at X^{n+1}, for the diagnostics' fluid volume
  fluid::SolveStats solve;
  double advected = 0.0;
  if (fluid) {
    solids = place_solids(L, set, m.dem.get(), m.obstacles, m.fluid.apertures,
                          m.cut_ahead);                                 // geometry
    mark_cells(L, set, solids.cut, m.particles, m.occupancy, m.fluid);  // transfer
    if (correct_density(L, set, m.step, solids, m.fluid, m.density_solver.get(), m.particles))
      mark_cells(L, set, solids.cut, m.particles, m.occupancy, m.fluid);   // density: cells again
    particles_to_grid(L, set, solids, m.particles, m.occupancy, m.fluid);  // transfer
    m.viscous =
        add_forces(L, set.fluid, set.viscous_rigid_rows, m.dem.get(), m.obstacles, dt,
                   set.surface.ghost_fluid ? &m.fluid.surface : nullptr, m.fluid);  // forces
    auto collision = predict_contacts(m.dem.get(), dt);                             // contact
    // eq. 6: the viscous loads join the p-independent loads of V* (doc/viscous.md)
    if (m.dem && !m.viscous.solids.empty())
      collision = fluid::plus_viscous(collision, m.viscous, m.dem->owned());
    solve = solve_pressure(L, set, solids, collision, dt, *m.pressure, m.fluid);  // pressure
    if (solve.preconditioner_retries > 0)
      core::log(m.comm, "picdem: step " + std::to_string(m.step + 1) +
                            ": CG broke down on an indefinite preconditioner; solved again with "
                            "solver/MueLu_solids merged (doc/fluid.md)");
    project(L, set, dt, m.fluid);  // project
    if (set.fluid.open.any())      // volumes through the open sides (doc/open_boundaries.md)
      open_flux = fluid::open_fluxes(m.fluid.u, m.fluid.w, m.fluid.cells,
                                     set.surface.ghost_fluid ? &m.fluid.surface : nullptr,
                                     set.fluid.open, L.d, m.comm);
    if (!m.obstacles.empty())  // for forces.csv
      m.obstacle_loads = fluid::obstacle_pressure_loads(solids.cut, m.fluid.cells, L.d, m.fluid.p,
                                                        set.quadrature, m.obstacles.size());
    if (m.dem) m.fluid_loads = advance_solids(m.pressure.get(), fluid, dt, m.viscous, *m.dem);
    const dem::SolidScene after = dem::scene_of(m.dem.get(), m.obstacles);  // solids at X^{n+1}
    grid_to_particles(L, set, solids, after, m.dem.get(), m.fluid, m.particles);  // transfer
    advected = advect_particles(L, set, m.step, solids.cut, after, dt, m.fluid, m.particles);
    if (m.dem) {  // the water where the particles are now, less the solids where they are now
      core::ScopedTimer timer("geometry: cut cells at X^n+1");
      fluid::Apertures E;
      cut_after = fluid::cut_cells(after.placements, after.obstacles, set.tiny_fraction, L.d, E);
      m.cut_ahead = {true, after.placements, after.obstacles, L.d.storage(grid::Stagger::Cell),
                     {},   std::move(E)};  // the next step's, with cut_after once recorded
    }
  } else if (m.dem) {
    m.fluid_loads = advance_solids(nullptr, nullptr, dt, {}, *m.dem);  // dry: solids only
  }
  m.t += dt;
  ++m.step;
  m.last_dt = dt;
  std::vector<double> volumes = m.diag.open_volumes;
  if (volumes.size() == 2)
    volumes[0] += dt * open_flux.inflow, volumes[1] += dt * open_flux.outflow;
  const geometry::CutCells* cut = !fluid || !set.has_bodies ? nullptr
                                  : m.dem                   ? &cut_after
                                                            : &solids.cut;  // obstacles stay
  m.diag = record_diagnostics(L, set, m.t, m.step, dt, advected, solve, m.particles, m.dem.get(),
                              cut, m.occupancy, fluid);
  m.diag.open_volumes = volumes;
  if (fluid && m.dem) m.cut_ahead.cut = std::move(cut_after);
}

const fluid::FluidState& Simulation::fluid() const {
  if (!m_->set.has_fluid) throw std::logic_error("Simulation::fluid(): the case has no water");
  return m_->fluid;
}

const particles::ParticleSet& Simulation::particles() const {
  return m_->particles;
}

const dem::DemSolver* Simulation::dem() const {
  return m_->dem.get();
}

StepLoads Simulation::last_loads() const {
  return {m_->fluid_loads, m_->obstacle_loads, m_->viscous.solids, m_->viscous.obstacles};
}

const std::vector<geometry::Obstacle>& Simulation::obstacles() const {
  return m_->obstacles;
}

bool Simulation::has_fluid() const {
  return m_->set.has_fluid;
}

Simulation::Modules Simulation::modules() {
  Impl& s = *m_;
  return {s.comm,     s.params, *s.decomp, s.particles, s.set.has_fluid ? &s.fluid : nullptr,
          s.dem.get()};
}

void Simulation::choose_pressure_rows_again() {
  if (m_->pressure) m_->pressure->choose_rows_again();
  if (m_->density_solver) m_->density_solver->choose_rows_again();
}

void Simulation::resume(double t, long long step, double last_dt, const Diagnostics& diag) {
  m_->t = t, m_->step = step, m_->last_dt = last_dt, m_->diag = diag;
}

double Simulation::last_time_step() const {
  return m_->last_dt;
}

// weighted: the file's cut lines on the same rank count (they came from the state of the last
// rebalance, which the file does not hold); otherwise the caller rebalances after the restore
bool Simulation::take_cuts_of(const std::vector<core::IndexBox>& boxes) {
  Impl& s = *m_;
  if (!s.set.balance.weighted || s.comm.size() == 1 || (!s.set.has_fluid && !s.dem)) return false;
  const auto cuts = grid::fitting_cuts_of_boxes(s.set.spec, boxes, s.comm.size(), s.set.balance);
  if (!cuts.xs.empty()) adopt_cuts(s, cuts);
  return !cuts.xs.empty();
}

void Simulation::rebalance() {
  rebalance_cuts(*m_);
}

}  // namespace picdem::coupling
