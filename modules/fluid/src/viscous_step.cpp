// Implicit viscosity on the step's distributed fields (viscous.hpp): gather, the stencils of
// viscous_operator.cpp, the solve of viscous_solver.cpp, scatter.
#include <algorithm>
#include <cmath>
#include <memory>

#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/fluid/viscous.hpp"

namespace picdem::fluid {

namespace {

constexpr signed char kFluid = static_cast<signed char>(grid::CellState::Fluid);
constexpr signed char kSolid = static_cast<signed char>(grid::CellState::Solid);

/// The whole grid's values of a staggered field (node id i + ni k over spec.extent), summed
/// from every rank's owned samples.
std::vector<double> gather(const grid::GridArray<double>& f, const grid::Decomposition& d) {
  const core::IndexBox ext = d.spec().extent(f.stagger());
  const int ni = ext.i1 - ext.i0;
  std::vector<double> all(static_cast<std::size_t>(ni) * static_cast<std::size_t>(ext.k1 - ext.k0),
                          0.0);
  const auto& b = f.owned();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) all[static_cast<std::size_t>(i + ni * k)] = f(i, k);
  d.comm().sum_in_place(all);
  return all;
}

void scatter(const std::vector<double>& all, grid::GridArray<double>& f,
             const grid::Decomposition& d) {
  const core::IndexBox ext = d.spec().extent(f.stagger());
  const int ni = ext.i1 - ext.i0;
  const auto& b = f.owned();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) f(i, k) = all[static_cast<std::size_t>(i + ni * k)];
}

/// 1 on nodes of `component` next to a Fluid cell (whole grid, node ids as in the stencil).
std::vector<unsigned char> fluid_node_mask(int component, const std::vector<double>& cell_state,
                                           const grid::GridSpec& g) {
  const int ni = component == 0 ? g.nx + 1 : g.nx, nk = component == 0 ? g.nz : g.nz + 1;
  auto fluid = [&](int i, int k) {
    return i >= 0 && k >= 0 && i < g.nx && k < g.nz &&
           cell_state[static_cast<std::size_t>(i + g.nx * k)] ==
               static_cast<double>(grid::CellState::Fluid);
  };
  std::vector<unsigned char> mask(static_cast<std::size_t>(ni) * static_cast<std::size_t>(nk), 0);
  for (int k = 0; k < nk; ++k)
    for (int i = 0; i < ni; ++i) {
      const bool next =
          component == 0 ? fluid(i - 1, k) || fluid(i, k) : fluid(i, k - 1) || fluid(i, k);
      mask[static_cast<std::size_t>(i + ni * k)] = next ? 1 : 0;
    }
  return mask;
}

}  // namespace

ViscousWalls viscous_walls_of(const FluidConfig& cfg) {
  auto kind = [](bool no_slip) { return no_slip ? WallKind::NoSlip : WallKind::FreeSlip; };
  ViscousWalls walls{kind(cfg.no_slip), {}, {}};
  for (std::size_t s = 0; s < 4; ++s)
    if (cfg.wall_no_slip[s]) walls.side[s] = kind(*cfg.wall_no_slip[s]);
  if (!cfg.open.any()) return walls;
  // Open sides: inflow (the inward face speed, tangential 0) or outflow (do-nothing).
  walls.open = [open = cfg.open](TankWall wall,
                                 const core::Vec2& t) -> std::optional<OpenWallPoint> {
    const auto n = static_cast<std::size_t>(wall);
    const OpenSide& side = open.side[n];
    const double along = n < 2 ? t.z : t.x;
    if (!side.open_at(along)) return std::nullopt;
    if (side.kind == OpenKind::Outflow) return OpenWallPoint{WallKind::Open, {}};
    const double v = (n == 0 || n == 2 ? 1.0 : -1.0) * open.face_speed(n, along);
    return OpenWallPoint{WallKind::Prescribed, n < 2 ? core::Vec2{v, 0.0} : core::Vec2{0.0, v}};
  };
  return walls;
}

ViscousStepResult apply_viscosity_implicit(grid::FaceField& u, grid::FaceField& w,
                                           const CellStates& cells, double dt,
                                           const FluidConfig& cfg, const grid::Decomposition& d,
                                           const grid::Halo& halo,
                                           const std::vector<ViscousBody>& bodies, double beta) {
  core::ScopedTimer timer("fluid: implicit viscosity");
  ViscousStepResult result;
  if (cfg.nu == 0.0) return result;
  const grid::GridSpec& g = d.spec();
  std::vector<double> states(static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.nz), 0.0);
  const core::IndexBox own = d.owned_cells();
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i)
      states[static_cast<std::size_t>(i + g.nx * k)] = static_cast<double>(cells(i, k));
  d.comm().sum_in_place(states);
  const ViscousGrid vg{g.origin, g.h, g.nx, g.nz};
  const ViscousWalls walls = viscous_walls_of(cfg);
  const std::vector<unsigned char> mask_u = fluid_node_mask(0, states, g);
  const std::vector<unsigned char> mask_w = fluid_node_mask(1, states, g);
  auto stencil_timer = std::make_unique<core::ScopedTimer>("fluid: implicit viscosity: stencil");
  ViscousStencil su = build_viscous_stencil(0, vg, bodies, walls, &mask_u);
  ViscousStencil sw = build_viscous_stencil(1, vg, bodies, walls, &mask_w);
  if (cfg.viscous_cut_mass) {  // each node's P2G mass next to the bodies (doc/viscous.md)
    set_cut_node_masses(su, vg, bodies);
    set_cut_node_masses(sw, vg, bodies);
  }
  stencil_timer.reset();
  core::ScopedTimer solve_timer("fluid: implicit viscosity: solve");
  std::vector<double> ug = gather(u, d), wg = gather(w, d);
  const bool rigid_rows =
      std::any_of(bodies.begin(), bodies.end(), [](const ViscousBody& b) { return b.mass > 0.0; });
  std::vector<ViscousBody> solved = bodies;
  if (rigid_rows) {
    if (beta != 1.0) throw core::InputError("viscous rigid rows need backward Euler (beta = 1)");
    result.loads = solve_viscous_rigid_rows(su, sw, cfg.nu, cfg.rho, dt, ug, wg, solved,
                                            result.iterations, cfg.viscous_solver);
  } else {
    const std::vector<double> u_old = ug, w_old = wg;
    result.iterations += solve_viscous_implicit(su, cfg.nu, dt, std::vector<double>(ug.size(), 0.0),
                                                ug, cfg.viscous_solver, beta);
    result.iterations += solve_viscous_implicit(sw, cfg.nu, dt, std::vector<double>(wg.size(), 0.0),
                                                wg, cfg.viscous_solver, beta);
    std::vector<double> ub(ug.size()), wb(wg.size());
    for (std::size_t n = 0; n < ug.size(); ++n) ub[n] = beta * ug[n] + (1.0 - beta) * u_old[n];
    for (std::size_t n = 0; n < wg.size(); ++n) wb[n] = beta * wg[n] + (1.0 - beta) * w_old[n];
    result.loads = viscous_loads(su, sw, ub, wb, cfg.rho * cfg.nu, bodies);
  }
  for (const ViscousBody& b : solved) result.velocity.push_back(b.velocity);
  for (const ViscousBody& b : solved) result.omega.push_back(b.omega);
  scatter(ug, u, d);
  scatter(wg, w, d);
  halo.forward(u);
  halo.forward(w);
  enforce_walls(u, w, cfg, d);
  return result;
}

void viscous_pressure_predictor(grid::FaceField& du, grid::FaceField& dw, const grid::CellField& p,
                                const CellStates& cells, const Apertures& E, double dt,
                                const FluidConfig& cfg, const SurfaceFractions* surface,
                                const grid::Decomposition& d, const grid::Halo& halo) {
  du.fill(0.0);
  dw.fill(0.0);
  // No pressure yet (the first step): no prediction.
  double largest = 0.0;
  const core::IndexBox own = d.owned_cells();
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) largest = std::max(largest, std::abs(p(i, k)));
  if (d.comm().max(largest) == 0.0) return;
  // du = dt (g - grad p^n / rho) on the faces the projection changes (open, with a fluid cell and
  // E > 0; fluid::project), 0 elsewhere: where the projection does not act, gravity is not
  // balanced by a pressure and must not enter the viscous solve. Not on the tank's outer faces:
  // they are no unknowns of the solve, and the walls and open sides set them (enforce_walls)
  // between the shift and its removal.
  const grid::GridSpec& g = d.spec();
  auto open = [&](signed char a, signed char b) {
    return a != kSolid && b != kSolid && (a == kFluid || b == kFluid);
  };
  const auto& bu = du.owned();
  for (int k = bu.k0; k < bu.k1; ++k)
    for (int i = std::max(bu.i0, 1); i < std::min(bu.i1, g.nx); ++i)
      if (E.E_x(i, k) > 0.0 && open(cells(i - 1, k), cells(i, k))) du(i, k) = dt * cfg.g.x;
  const auto& bw = dw.owned();
  for (int k = std::max(bw.k0, 1); k < std::min(bw.k1, g.nz); ++k)
    for (int i = bw.i0; i < bw.i1; ++i)
      if (E.E_z(i, k) > 0.0 && open(cells(i, k - 1), cells(i, k))) dw(i, k) = dt * cfg.g.z;
  project(du, dw, p, cells, E, dt, cfg, surface);  // - dt grad p^n / rho on the same faces
  for (int k = bu.k0; k < bu.k1; ++k)
    for (int i = bu.i0; i < bu.i1; ++i)
      if (i <= 0 || i >= g.nx) du(i, k) = 0.0;
  for (int k = bw.k0; k < bw.k1; ++k)
    for (int i = bw.i0; i < bw.i1; ++i)
      if (k <= 0 || k >= g.nz) dw(i, k) = 0.0;
  halo.forward(du);
  halo.forward(dw);
}

}  // namespace picdem::fluid
