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

  // the clock and what the last step reported
  double t = 0.0;
  long long step = 0;
  double last_dt = 0.0;  // the last step's dt (time/dt_growth); 0 before the first
  Diagnostics diag;
  std::vector<core::SolidLoads> fluid_loads;     // J p + F_q of the last step, by id (all ranks)
  fluid::ViscousExchange viscous;                // the last step's viscous loads (implicit scheme)
  std::vector<core::SolidLoads> obstacle_loads;  // J p + F_q of the last step, every obstacle

  Layout layout() const { return {*decomp, *halo, comm}; }
  bool weighted() const { return params.string("grid/decomposition") == "weighted"; }
};

namespace {

// Water is seeded where neither solids nor obstacles are. Cells are seeded by their centre;
// particles that fall inside a body are then removed, so that cut cells whose centre is covered
// still get particles in their fluid part. The seeding's jitter keeps the lattice's occupancy over
// the particles whose lattice position is wet (particles::seed): a level surface on a cell face
// is seeded flat.
particles::ParticleSet seed_water(const Simulation::Impl& m) {
  const particles::WaterRegions water(m.params);
  const SolidScene scene0 = scene_of(m.dem.get(), m.obstacles);
  const SolidLocator locator(scene0);
  const auto wet = [&](Vec2 p) { return water.contains(p) && !locator.inside(p); };
  auto ps = particles::seed(
      *m.decomp, m.set.particles,
      [&](Vec2 c) {
        const double r = 0.5 * m.set.spec.h;
        return water.contains(c) || water.contains(c + Vec2{r, r}) ||
               water.contains(c + Vec2{-r, r}) || water.contains(c + Vec2{r, -r}) ||
               water.contains(c + Vec2{-r, -r});
      },
      wet);
  std::vector<char> keep(ps.size());
  for (std::size_t n = 0; n < keep.size(); ++n) keep[n] = wet({ps.x[n], ps.z[n]});
  ps.keep_if(keep);
  return ps;
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

// grid/decomposition = weighted: cut lines balancing the particles' work (particles::cell_work,
// grid::balanced_cuts), taken
// when they lighten the heaviest block by grid/rebalance_gain or more. A function of the particles
// and the present cuts only, both of which a checkpoint keeps.
void rebalance_cuts(Simulation::Impl& m) {
  if (!m.weighted() || m.comm.size() == 1 || !m.set.has_fluid) return;
  const auto work = particles::cell_work(*m.decomp, m.particles);
  const auto cuts =
      grid::balanced_cuts(*m.decomp, work, static_cast<int>(m.params.integer("grid/ranks_x")),
                          static_cast<int>(m.params.integer("grid/ranks_z")));
  if (cuts.xs == m.decomp->x_cuts() && cuts.zs == m.decomp->z_cuts()) return;
  const long long before = grid::heaviest_block(*m.decomp, work);
  const double gain = m.params.real("grid/rebalance_gain");
  if (static_cast<double>(cuts.heaviest) > (1.0 - gain) * static_cast<double>(before)) return;
  adopt_cuts(m, cuts);
  auto list = [](const std::vector<int>& v) {
    std::string out;
    for (int c : v) out += (out.empty() ? "" : " ") + std::to_string(c);
    return out;
  };
  core::log(m.comm, "picdem: step " + std::to_string(m.step) + ": cut lines x {" + list(cuts.xs) +
                        "}, z {" + list(cuts.zs) + "}, heaviest block " + std::to_string(before) +
                        " -> " + std::to_string(cuts.heaviest) + " of " +
                        std::to_string(cuts.total));
}

}  // namespace

Simulation::Simulation(core::Comm comm, core::Params params) : m_(std::make_unique<Impl>()) {
  Impl& m = *m_;
  m.comm = comm;
  m.params = params;
  m.set = step_settings_from(params);
  const auto& spec = m.set.spec;
  const int halo = std::max(3, particles::required_halo(m.set.particles));
  m.decomp = std::make_unique<grid::Decomposition>(
      spec, comm, halo, static_cast<int>(params.integer("grid/ranks_x")),
      static_cast<int>(params.integer("grid/ranks_z")));
  m.halo = std::make_unique<grid::Halo>(*m.decomp);
  const auto& d = *m.decomp;

  m.obstacles = geometry::obstacles_from(params);
  const auto solids = dem::solids_from(params);
  if (!solids.empty() || !m.set.has_fluid) {
    const core::Box2 tank{spec.origin, spec.origin + Vec2{spec.length(), spec.height()}};
    std::vector<std::vector<Vec2>> polys;
    for (const auto& o : m.obstacles)
      for (const auto& poly : o.polygons) polys.push_back(poly);
    m.dem = std::make_unique<dem::DemSolver>(comm, dem::config_from(params, spec.h),
                                             grid::owned_regions(d), tank, polys);
    m.dem->add_solids(solids);
  }
  m.set.has_solids = m.dem != nullptr;
  m.set.has_bodies = m.dem || !m.obstacles.empty();

  if (m.set.has_fluid) {
    m.pressure = std::make_unique<fluid::PressureSolver>(d, params);
    if (m.set.density_relaxation > 0.0)
      m.density_solver = std::make_unique<fluid::PressureSolver>(
          d, params, fluid::PressureSolver::Equation::DensityCorrection);
    m.fluid = fluid::FluidState(d);
    m.particles = seed_water(m);
    rebalance_cuts(m);
    if (m.set.fluid.open.any()) m.diag.open_volumes = {0.0, 0.0};  // in, out since t = 0
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
  const long long every = m.params.integer("grid/rebalance_interval");
  if (every > 0 && m.step > 0 && m.step % every == 0) rebalance_cuts(m);
  const Layout L = m.layout();
  fluid::FluidState* fluid = set.has_fluid ? &m.fluid : nullptr;
  const auto motion = cfl_extra_motion(L, set, m.particles, m.occupancy, m.dem.get());  // dt
  const double dt =
      fluid::choose_time_step(set.time, set.fluid, m.t, m.step, fluid, motion, m.last_dt, m.comm);
  m.set.fluid.open.t0 = m.t, m.set.fluid.open.t1 = m.t + dt;  // the inflows over this step
  fluid::OpenFluxes open_flux;
  SolidsAtStart solids;  // at X^n
  fluid::SolveStats solve;
  double advected = 0.0;
  if (fluid) {
    solids = place_solids(L, set, m.dem.get(), m.obstacles, m.fluid.apertures);  // geometry
    mark_cells(L, set, solids.cut, m.particles, m.occupancy, m.fluid);           // transfer
    if (correct_density(L, set, m.step, solids, m.fluid, m.density_solver.get(), m.particles))
      mark_cells(L, set, solids.cut, m.particles, m.occupancy, m.fluid);   // density: cells again
    particles_to_grid(L, set, solids, m.particles, m.occupancy, m.fluid);  // transfer
    m.viscous = add_forces(L, set.fluid, set.viscous_rigid_rows, m.dem.get(), m.obstacles, dt,
                           set.ghost_fluid ? &m.fluid.surface : nullptr, m.fluid);  // forces
    auto collision = predict_contacts(m.dem.get(), dt);                             // contact
    // eq. 6: the viscous loads join the p-independent loads of V* (doc/viscous.md)
    if (m.dem && !m.viscous.solids.empty())
      collision = fluid::plus_viscous(collision, m.viscous, m.dem->owned());
    solve = solve_pressure(L, set, solids, collision, dt, *m.pressure, m.fluid);  // pressure
    project(L, set, dt, m.fluid);                                                 // project
    if (set.fluid.open.any())  // volumes through the open sides (doc/open_boundaries.md)
      open_flux = fluid::open_fluxes(m.fluid.u, m.fluid.w, set.fluid.open, L.d, m.comm);
    if (!m.obstacles.empty())  // for forces.csv
      m.obstacle_loads = fluid::obstacle_pressure_loads(solids.cut, m.fluid.cells, L.d, m.fluid.p,
                                                        set.quadrature, m.obstacles.size());
    if (m.dem) m.fluid_loads = advance_solids(m.pressure.get(), fluid, dt, m.viscous, *m.dem);
    const SolidScene after = scene_of(m.dem.get(), m.obstacles);  // solids at X^{n+1}
    grid_to_particles(L, set, solids, after, m.dem.get(), m.fluid, m.particles);  // transfer
    advected = advect_particles(L, set, m.step, solids.cut, after, dt, m.fluid, m.particles);
  } else if (m.dem) {
    m.fluid_loads = advance_solids(nullptr, nullptr, dt, {}, *m.dem);  // dry: solids only
  }
  m.t += dt;
  ++m.step;
  m.last_dt = dt;
  std::vector<double> volumes = m.diag.open_volumes;
  if (volumes.size() == 2)
    volumes[0] += dt * open_flux.inflow, volumes[1] += dt * open_flux.outflow;
  m.diag = record_diagnostics(L, set, m.t, m.step, dt, advected, solve, m.particles, m.dem.get(),
                              fluid ? &solids : nullptr, m.occupancy, fluid);
  m.diag.open_volumes = volumes;
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
  if (!s.weighted() || s.comm.size() == 1 || !s.set.has_fluid) return false;
  const auto cuts = grid::cuts_of_boxes(s.set.spec, boxes);
  const long long rx = s.params.integer("grid/ranks_x"), rz = s.params.integer("grid/ranks_z");
  const bool fit = boxes.size() == static_cast<std::size_t>(s.comm.size()) && !cuts.xs.empty() &&
                   (rx == 0 || rx + 1 == static_cast<long long>(cuts.xs.size())) &&
                   (rz == 0 || rz + 1 == static_cast<long long>(cuts.zs.size()));
  if (fit) adopt_cuts(s, cuts);
  return fit;
}

void Simulation::rebalance() {
  rebalance_cuts(*m_);
}

}  // namespace picdem::coupling
