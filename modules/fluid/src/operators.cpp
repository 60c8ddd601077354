// Grid operators of the fluid step: parameters, apertures, body forces, walls, viscosity,
// divergence, projection, velocity extension and the CFL time step.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/open_flow.hpp"
#include "picdem/grid/axis.hpp"

namespace picdem::fluid {

using grid::Axis;
using grid::CellState;
using grid::FaceField;
using grid::Stagger;

namespace {

constexpr signed char kAir = static_cast<signed char>(CellState::Air);
constexpr signed char kFluid = static_cast<signed char>(CellState::Fluid);
constexpr signed char kSolid = static_cast<signed char>(CellState::Solid);

/// State of cell (i, k); cells outside the tank or outside storage count as solid (walls).
signed char state(const CellStates& cells, int i, int k, int nx, int nz) {
  if (i < 0 || k < 0 || i >= nx || k >= nz || !cells.in_storage(i, k)) return kSolid;
  return cells(i, k);
}

/// The columns [lo, hi) of each storage row of `cells` between its first and last fluid cell
/// (lo = hi: none). A face is next to a fluid cell only inside its row's span grown by one
/// (x faces) or inside the union of its two rows' spans (z faces): loops over the faces that
/// need a fluid neighbour visit these columns only (the water's band, not the whole window).
class FluidSpans {
 public:
  explicit FluidSpans(const CellStates& cells) : box_(cells.storage()) {
    spans_.assign(static_cast<std::size_t>(box_.nz()), {0, 0});
    for (int k = box_.k0; k < box_.k1; ++k) {
      int lo = box_.i1, hi = box_.i0;
      for (int i = box_.i0; i < box_.i1; ++i)
        if (cells(i, k) == kFluid) lo = std::min(lo, i), hi = i + 1;
      if (lo < hi) spans_[static_cast<std::size_t>(k - box_.k0)] = {lo, hi};
    }
  }
  /// Faces (i, k) of an x-face box whose cells (i - 1, k), (i, k) may hold fluid: [i0, i1).
  std::pair<int, int> x_faces(int k, const core::IndexBox& faces) const {
    const auto [lo, hi] = row(k);
    if (lo >= hi) return {faces.i0, faces.i0};
    return {std::max(faces.i0, lo), std::max(std::max(faces.i0, lo), std::min(faces.i1, hi + 1))};
  }
  /// Faces (i, k) of a z-face box whose cells (i, k - 1), (i, k) may hold fluid.
  std::pair<int, int> z_faces(int k, const core::IndexBox& faces) const {
    const auto [la, ha] = row(k - 1);
    const auto [lb, hb] = row(k);
    const int lo = la < ha ? (lb < hb ? std::min(la, lb) : la) : lb;
    const int hi = la < ha ? (lb < hb ? std::max(ha, hb) : ha) : hb;
    if (!(la < ha) && !(lb < hb)) return {faces.i0, faces.i0};
    return {std::max(faces.i0, lo), std::max(std::max(faces.i0, lo), std::min(faces.i1, hi))};
  }

  /// x_faces for Axis::X, z_faces for Axis::Z.
  template <Axis A>
  std::pair<int, int> faces(int k, const core::IndexBox& box) const {
    return A == Axis::X ? x_faces(k, box) : z_faces(k, box);
  }

 private:
  std::pair<int, int> row(int k) const {
    if (k < box_.k0 || k >= box_.k1) return {0, 0};
    return spans_[static_cast<std::size_t>(k - box_.k0)];
  }
  core::IndexBox box_;
  std::vector<std::pair<int, int>> spans_;
};

/// The aperture of the axis-A face (i, k): E_x or E_z.
template <Axis A>
double aperture(const Apertures& E, int i, int k) {
  return A == Axis::X ? E.E_x(i, k) : E.E_z(i, k);
}

/// The wall values and ghosts of the axis-A velocity f, in (n, t) = (index along A, index
/// across): zero on the walls across A (n = 0, n_cells), odd ghosts beyond them; beyond the walls
/// along A (halfway between t = -1 and t = 0, and t_cells - 1 and t_cells), t_lo / t_hi times the
/// mirrored inside value (free slip +1, no slip -1).
template <Axis A>
void wall_ghosts(FaceField& f, int n_cells, int t_cells, double t_lo, double t_hi) {
  auto at = [&](int n, int t) -> double& { return A == Axis::X ? f(n, t) : f(t, n); };
  auto inside = [&](int n, int t) {
    return A == Axis::X ? f.in_storage(n, t) : f.in_storage(t, n);
  };
  const auto& b = f.storage();
  const int n0 = A == Axis::X ? b.i0 : b.k0, n1 = A == Axis::X ? b.i1 : b.k1;
  const int t0 = A == Axis::X ? b.k0 : b.i0, t1 = A == Axis::X ? b.k1 : b.i1;
  for (int t = t0; t < t1; ++t) {
    for (int n : {0, n_cells})
      if (inside(n, t)) at(n, t) = 0.0;
    // Normal component odd about the walls: f(-j) = -f(j), f(N + j) = -f(N - j).
    for (int n = n0; n < 0; ++n)
      if (inside(-n, t)) at(n, t) = -at(-n, t);
    for (int n = n_cells + 1; n < n1; ++n)
      if (inside(2 * n_cells - n, t)) at(n, t) = -at(2 * n_cells - n, t);
  }
  // Tangential component about the walls along A.
  for (int n = n0; n < n1; ++n) {
    for (int t = t0; t < 0; ++t)
      if (inside(n, -t - 1)) at(n, t) = t_lo * at(n, -t - 1);
    for (int t = t_cells; t < t1; ++t)
      if (inside(n, 2 * t_cells - 1 - t)) at(n, t) = t_hi * at(n, 2 * t_cells - 1 - t);
  }
}

/// The body force on the axis-A velocity f of the faces with a fluid cell on either side
/// (interior faces only: the grid's outer faces have no cell on their outer side).
template <Axis A>
void gravity_along(FaceField& f, const CellStates& cells, double dt, double g) {
  constexpr int di = grid::step_i(A), dk = grid::step_k(A);
  const auto& b = f.owned();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) {
      if (!cells.in_storage(i - di, k - dk) || !cells.in_storage(i, k)) continue;
      if (cells(i - di, k - dk) != kFluid && cells(i, k) != kFluid) continue;
      // u~ = u + dt g_x, w~ = w + dt g_z  (eq. 2, body force)
      f(i, k) += dt * g;
    }
}

/// Explicit viscosity on the axis-A velocity f (f0: its values before) of the interior faces
/// between two fluid cells; fluid(i, k) tells a fluid cell.
template <Axis A, class IsFluid>
void viscosity_along(FaceField& f, const FaceField& f0, double c, int nx, int nz, IsFluid fluid) {
  constexpr int di = grid::step_i(A), dk = grid::step_k(A);
  // A neighbour face is used when it lies on or beyond a wall (wall value or ghost) or touches
  // fluid; otherwise (free surface) the centre value stands in: zero normal gradient.
  auto nb = [&](int i, int k, double centre) {
    const int n = A == Axis::X ? i : k, t = A == Axis::X ? k : i;
    const int n_end = A == Axis::X ? nx : nz, t_end = A == Axis::X ? nz : nx;
    if (n <= 0 || n >= n_end || t < 0 || t >= t_end) return f0(i, k);
    return fluid(i - di, k - dk) || fluid(i, k) ? f0(i, k) : centre;
  };
  const auto& b = f.owned();
  const int k0 = dk ? std::max(b.k0, 1) : b.k0, k1 = dk ? std::min(b.k1, nz) : b.k1;
  const int i0 = di ? std::max(b.i0, 1) : b.i0, i1 = di ? std::min(b.i1, nx) : b.i1;
  for (int k = k0; k < k1; ++k)
    for (int i = i0; i < i1; ++i) {
      if (!fluid(i - di, k - dk) || !fluid(i, k)) continue;
      const double fc = f0(i, k);
      // u += dt nu (u_E + u_W + u_N + u_S - 4 u_P) / h^2, the same for w  (eq. 2, viscous term)
      f(i, k) += c * (nb(i + 1, k, fc) + nb(i - 1, k, fc) + nb(i, k + 1, fc) + nb(i, k - 1, fc) -
                      4.0 * fc);
    }
}

/// The axis-A pressure gradient on the open faces of f (neither side solid, one side fluid);
/// theta: the free-surface fractions of those faces, or null.
template <Axis A>
void project_along(FaceField& f, const grid::CellField& p, const CellStates& cells,
                   const Apertures& E, double s, const FluidSpans& spans, const FaceField* theta) {
  constexpr int di = grid::step_i(A), dk = grid::step_k(A);
  auto p_of = [&](int i, int k) { return cells(i, k) == kFluid ? p(i, k) : 0.0; };
  // Ghost pressure of the air cell across a face of fraction theta: p = 0 at theta h from the
  // fluid centre, so p_ghost = p_fluid (theta - 1) / theta.
  auto ghost = [](double p_fluid, double th) { return p_fluid * (th - 1.0) / th; };
  auto open = [](signed char a, signed char b) {
    return a != kSolid && b != kSolid && (a == kFluid || b == kFluid);
  };
  const auto& b = f.owned();
  for (int k = b.k0; k < b.k1; ++k) {
    const auto [i0, i1] = spans.faces<A>(k, b);
    for (int i = i0; i < i1; ++i) {
      if (aperture<A>(E, i, k) <= 0.0 || !open(cells(i - di, k - dk), cells(i, k))) continue;
      double lo = p_of(i - di, k - dk), hi = p_of(i, k);
      if (theta && (*theta)(i, k) < 1.0) {
        if (cells(i - di, k - dk) == kAir) lo = ghost(hi, (*theta)(i, k));
        if (cells(i, k) == kAir) hi = ghost(lo, (*theta)(i, k));
      }
      // u = u~ - dt/rho (p_{i} - p_{i-1}) / h, w = w~ - dt/rho (p_{k} - p_{k-1}) / h
      f(i, k) -= s * (hi - lo);
    }
  }
}

/// 1 on the axis-A faces with an aperture and a fluid cell on a side, 0 elsewhere in the band.
template <Axis A>
void valid_along(grid::GridArray<signed char>& valid, const CellStates& cells, const Apertures& E,
                 const FluidSpans& spans) {
  constexpr int di = grid::step_i(A), dk = grid::step_k(A);
  auto fluid = [&](int i, int k) { return cells.in_storage(i, k) && cells(i, k) == kFluid; };
  const auto& b = valid.storage();
  for (int k = b.k0; k < b.k1; ++k) {
    const auto [i0, i1] = spans.faces<A>(k, b);
    for (int i = i0; i < i1; ++i)
      valid(i, k) = aperture<A>(E, i, k) > 0.0 && (fluid(i - di, k - dk) || fluid(i, k)) ? 1 : 0;
  }
}

}  // namespace

void declare_parameters(core::ParamSchema& schema) {
  schema.section("fluid", "The fluid: density, viscosity, gravity and the tank-wall condition.");
  schema.real("fluid/density", 1000.0, "fluid density rho [kg/m^3]").positive();
  schema.real("fluid/viscosity", 1e-6, "kinematic viscosity nu [m^2/s] (0: inviscid)")
      .non_negative();
  schema.reals("fluid/gravity", {0.0, -9.81}, "gravity (g_x, g_z) [m/s^2]").size(2, 2);
  schema.string("fluid/walls", "free_slip", {"free_slip", "no_slip"},
                "tank-wall condition on the tangential velocity");
  for (const char* side : {"left", "right", "bottom", "top"})
    schema.string(std::string("fluid/wall_") + side, "default", {"default", "free_slip", "no_slip"},
                  std::string("condition of the ") + side +
                      " tank wall on the tangential velocity; default: as fluid/walls "
                      "(doc/viscous.md)");
  schema.string("fluid/viscosity_scheme", "explicit", {"explicit", "implicit", "crank_nicolson"},
                "explicit: 5-point viscosity on faces between fluid cells, the time step held "
                "below h^2 / (4 nu); implicit: backward Euler with no-slip at the true boundary of "
                "solids and obstacles, whose viscous loads enter the solids' update; "
                "crank_nicolson: the same operator with the trapezoidal rule (second order in "
                "time, hardly damps stiff modes; not with coupling/viscous_rigid_rows) "
                "(doc/viscous.md)");
  schema.boolean(
      "fluid/viscous_pressure_predictor", false,
      "implicit scheme without coupling/viscous_rigid_rows: solve the viscosity for u + "
      "dt (g - grad p^n / rho) and take it off after, so that steady flows keep "
      "no-slip without the splitting's O(dt) wall slip (doc/viscous.md, \"Pressure "
      "predictor\"; off by default: with it the viscous momentum balance's split case exceeds "
      "its 2%)");
  schema.boolean("fluid/viscous_cut_mass", false,
                 "implicit scheme: weigh each velocity node next to a solid or obstacle by the "
                 "share of its P2G tent outside the bodies (its particles' mass), so that the "
                 "viscous loads equal the momentum the particles lose (doc/viscous.md, "
                 "\"Cut-node masses\")");
  schema.boolean("fluid/viscous_rotation_rows", false,
                 "implicit scheme without coupling/viscous_rigid_rows: each solid's angular "
                 "velocity is an unknown of the viscous solve (its translation stays split, with "
                 "the pressure predictor if set): light disks whose spin the split makes unstable "
                 "(doc/viscous.md, \"Rotation rows\")");
  schema.section("solver", "The pressure solve: Belos CG preconditioned by MueLu.");
  schema.real("solver/tolerance", 1e-8, "relative true residual ||b - A p|| / ||b|| to reach")
      .positive()
      .less_than(1.0);
  schema.integer("solver/max_iterations", 500, "CG iterations allowed per solve").at_least(1);
  schema.boolean("solver/rebalance", true,
                 "split the pressure unknowns evenly over the ranks for the solve (the grid "
                 "blocks hold unequal numbers of fluid cells)");
  schema.string("solver/coupling_operator", "low_rank", {"assembled", "low_rank"},
                "assembled: the solids' dense blocks dt A_s M_s^-1 A_s^T in the pressure matrix "
                "(solver/MueLu_solids applies); low_rank: kept beside it and applied as a low-rank "
                "term in CG, MueLu built on the fluid rows plus the blocks' diagonal "
                "(doc/performance.md)");
  schema.string("solver/pressure_structure", "active", {"active", "fixed"},
                "active: the pressure rows are the owned fluid cells, and the Tpetra structure "
                "(maps, graph, Exports) is rebuilt whenever they change; fixed: the rows are a "
                "kept band of cells (the fluid and every cell within solver/structure_margin of "
                "it, chosen again when a fluid cell leaves it or a checkpoint is written), air "
                "and solid cells identity rows (p = 0), so the structure is rebuilt only then and "
                "otherwise values are refilled; solver/rebalance does not apply "
                "(doc/performance.md)");
  schema
      .integer("solver/structure_margin", 4,
               "solver/pressure_structure fixed: cells (along x and z) around the fluid that "
               "are rows too; a margin as large as the grid makes every cell a row")
      .at_least(0);
  schema.passthrough("solver/Belos",
                     "\"Implicit Residual Scaling\": \"Norm of RHS\"\n"
                     "Verbosity: 0\n",
                     "settings handed to Belos::PseudoBlockCGSolMgr (tolerance and iteration "
                     "limit come from solver/tolerance and solver/max_iterations)");
  schema.passthrough("solver/MueLu",
                     "verbosity: none\n"
                     "\"multigrid algorithm\": sa\n"
                     "\"problem: symmetric\": true\n"
                     "\"aggregation: type\": uncoupled\n"
                     "\"smoother: type\": CHEBYSHEV\n"
                     "\"smoother: params\":\n"
                     "  \"chebyshev: degree\": 3\n"
                     "\"coarse: max size\": 800\n"
                     "\"repartition: enable\": true\n"
                     "\"repartition: start level\": 1\n"
                     "\"repartition: min rows per proc\": 800\n",
                     "settings handed to MueLu::CreateTpetraPreconditioner; cell-centre "
                     "coordinates are added as \"Coordinates\" in \"user data\"");
  schema.passthrough("solver/MueLu_solids",
                     "\"aggregation: drop tol\": 0.02\n"
                     "\"smoother: params\":\n"
                     "  \"chebyshev: eigenvalue max iterations\": 30\n",
                     "merged over solver/MueLu for systems with solids: their dense blocks join "
                     "every cut cell of a body to every other, and aggregated as strong "
                     "connections they double the iterations (drop tol); they also add large "
                     "eigenvalues that Chebyshev's 10-step estimate can miss, which made the "
                     "preconditioner indefinite (doc/performance.md)");
  schema.passthrough("solver/MueLu_one_level",
                     "\"coarse: type\": RELAXATION\n"
                     "\"coarse: params\":\n"
                     "  \"relaxation: type\": \"Symmetric Gauss-Seidel\"\n"
                     "  \"relaxation: sweeps\": 2\n",
                     "merged over the list when a system no larger than \"coarse: max size\" is "
                     "solved on several ranks: it is then its own coarsest level, which no "
                     "repartitioning gathers on one rank, and MueLu's distributed direct coarse "
                     "solve is wrong there (TOOLCHAIN.md)");
  schema
      .real("solver/density_tolerance", 1e-4,
            "relative true residual ||b - A q|| / ||b|| of the density correction's solve "
            "(free_surface/density_correction; doc/coupling.md)")
      .positive()
      .less_than(1.0);
  schema.passthrough("solver/MueLu_density", "\"multigrid algorithm\": sa\n",
                     "merged over solver/MueLu for the density correction's solve "
                     "(doc/coupling.md)");
  declare_viscous_solver_parameters(schema);
  declare_open_parameters(schema);
}

FluidConfig config_from(const core::Params& params) {
  FluidConfig c;
  c.rho = params.real("fluid/density");
  c.nu = params.real("fluid/viscosity");
  const auto g = params.reals("fluid/gravity");
  c.g = {g[0], g[1]};
  c.no_slip = params.string("fluid/walls") == "no_slip";
  const char* sides[4] = {"left", "right", "bottom", "top"};
  for (std::size_t s = 0; s < 4; ++s) {
    const std::string v = params.string(std::string("fluid/wall_") + sides[s]);
    if (v != "default") c.wall_no_slip[s] = v == "no_slip";
  }
  const std::string scheme = params.string("fluid/viscosity_scheme");
  c.implicit_viscosity = scheme != "explicit";
  c.viscous_beta = scheme == "crank_nicolson" ? 0.5 : 1.0;
  c.viscous_pressure_predictor = params.boolean("fluid/viscous_pressure_predictor");
  c.viscous_cut_mass = params.boolean("fluid/viscous_cut_mass");
  c.viscous_rotation_rows = params.boolean("fluid/viscous_rotation_rows");
  c.viscous_solver = viscous_solver_settings_from(params);
  c.h = params.real("grid/cell_size");
  c.open = open_boundaries_from(params, grid::spec_from(params));
  if (params.has("obstacles"))
    for (const auto& name : params.sublist_names("obstacles"))
      c.obstacle_free_slip.push_back(params.string("obstacles/" + name + "/wall") == "free_slip");
  return c;
}

Apertures open_apertures(const grid::Decomposition& d) {
  const int nx = d.spec().nx, nz = d.spec().nz;
  const double h = d.spec().h;
  Apertures E{FaceField(d, Stagger::FaceX, 0.0), FaceField(d, Stagger::FaceZ, 0.0)};
  const auto& bx = E.E_x.storage();
  for (int k = std::max(bx.k0, 0); k < std::min(bx.k1, nz); ++k)
    for (int i = std::max(bx.i0, 1); i < std::min(bx.i1, nx); ++i) E.E_x(i, k) = h;
  const auto& bz = E.E_z.storage();
  for (int k = std::max(bz.k0, 1); k < std::min(bz.k1, nz); ++k)
    for (int i = std::max(bz.i0, 0); i < std::min(bz.i1, nx); ++i) E.E_z(i, k) = h;
  return E;
}

void enforce_walls(FaceField& u, FaceField& w, const FluidConfig& cfg,
                   const grid::Decomposition& d) {
  const bool open = cfg.open.any();
  const OutflowFaces kept = open ? keep_outflow_faces(u, w, cfg.open, d) : OutflowFaces{};
  const int nx = d.spec().nx, nz = d.spec().nz;
  // Tangential ghost = t * mirrored inside value: free-slip t = +1, no-slip t = -1 (per wall).
  auto t_of = [&](TankWall wall) { return no_slip_at(cfg, wall) ? -1.0 : 1.0; };
  const double t_left = t_of(TankWall::Left), t_right = t_of(TankWall::Right);
  const double t_bottom = t_of(TankWall::Bottom), t_top = t_of(TankWall::Top);
  wall_ghosts<Axis::X>(u, nx, nz, t_bottom, t_top);
  wall_ghosts<Axis::Z>(w, nz, nx, t_left, t_right);
  if (open) enforce_open_sides(u, w, cfg.open, d, kept);
}

void apply_gravity(FaceField& u, FaceField& w, const CellStates& cells, double dt,
                   const FluidConfig& cfg) {
  core::ScopedTimer timer("fluid: forces");
  gravity_along<Axis::X>(u, cells, dt, cfg.g.x);
  gravity_along<Axis::Z>(w, cells, dt, cfg.g.z);
}

void apply_viscosity(FaceField& u, FaceField& w, const CellStates& cells, double dt,
                     const FluidConfig& cfg, const grid::Decomposition& d, const grid::Halo& halo) {
  core::ScopedTimer timer("fluid: forces");
  if (cfg.nu == 0.0) return;
  const int nx = d.spec().nx, nz = d.spec().nz;
  const double h = d.spec().h;
  halo.forward_all({&u, &w});
  enforce_walls(u, w, cfg, d);
  const FaceField u0 = u, w0 = w;
  auto fluid = [&](int i, int k) { return state(cells, i, k, nx, nz) == kFluid; };
  const double c = dt * cfg.nu / (h * h);
  viscosity_along<Axis::X>(u, u0, c, nx, nz, fluid);
  viscosity_along<Axis::Z>(w, w0, c, nx, nz, fluid);
}

void divergence(const FaceField& u, const FaceField& w, const Apertures& E, const CellStates& cells,
                grid::CellField& D) {
  const auto& b = D.owned();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) {
      if (cells(i, k) != kFluid) {
        D(i, k) = 0.0;
        continue;
      }
      // D = E_{i+1/2} u_{i+1/2} - E_{i-1/2} u_{i-1/2} + E_{k+1/2} w_{k+1/2} - E_{k-1/2} w_{k-1/2}
      // (eq. 5, right-hand side without the solid term)
      D(i, k) = E.E_x(i + 1, k) * u(i + 1, k) - E.E_x(i, k) * u(i, k) +
                E.E_z(i, k + 1) * w(i, k + 1) - E.E_z(i, k) * w(i, k);
    }
}

SurfaceFractions surface_fractions(const grid::CellField& phi, const CellStates& cells,
                                   const grid::Decomposition& d, double theta_min) {
  SurfaceFractions t{FaceField(d, Stagger::FaceX, 1.0), FaceField(d, Stagger::FaceZ, 1.0)};
  auto theta = [&](int ia, int ka, int ib, int kb) {
    if (!cells.in_storage(ia, ka) || !cells.in_storage(ib, kb)) return 1.0;
    const signed char a = cells(ia, ka), b = cells(ib, kb);
    double pf, pa;
    if (a == kFluid && b == kAir)
      pf = phi(ia, ka), pa = phi(ib, kb);
    else if (a == kAir && b == kFluid)
      pf = phi(ib, kb), pa = phi(ia, ka);
    else
      return 1.0;
    if (!(pa > pf)) return 1.0;
    // theta = phi_fluid / (phi_fluid - phi_air): where phi crosses 0 between the two centres
    return std::min(1.0, std::max(theta_min, pf / (pf - pa)));
  };
  // theta is 1 unless one of the face's cells is fluid: only the water's band is visited.
  const FluidSpans spans(cells);
  const auto& bx = t.theta_x.storage();
  for (int k = bx.k0; k < bx.k1; ++k) {
    const auto [i0, i1] = spans.x_faces(k, bx);
    for (int i = i0; i < i1; ++i) t.theta_x(i, k) = theta(i - 1, k, i, k);
  }
  const auto& bz = t.theta_z.storage();
  for (int k = bz.k0; k < bz.k1; ++k) {
    const auto [i0, i1] = spans.z_faces(k, bz);
    for (int i = i0; i < i1; ++i) t.theta_z(i, k) = theta(i, k - 1, i, k);
  }
  return t;
}

void project(FaceField& u, FaceField& w, const grid::CellField& p, const CellStates& cells,
             const Apertures& E, double dt, const FluidConfig& cfg,
             const SurfaceFractions* surface) {
  core::ScopedTimer timer("fluid: project");
  if (cfg.h <= 0.0) throw core::InputError("fluid::project: FluidConfig::h must be the cell size");
  const double s = dt / (cfg.rho * cfg.h);
  const FluidSpans spans(cells);  // open faces have a fluid cell: the water's band only
  project_along<Axis::X>(u, p, cells, E, s, spans, surface ? &surface->theta_x : nullptr);
  project_along<Axis::Z>(w, p, cells, E, s, spans, surface ? &surface->theta_z : nullptr);
}

void fluid_faces(const CellStates& cells, const Apertures& E, grid::GridArray<signed char>& u_valid,
                 grid::GridArray<signed char>& w_valid) {
  // 0 away from fluid cells: only the water's band is visited
  const FluidSpans spans(cells);
  u_valid.fill(0);
  w_valid.fill(0);
  valid_along<Axis::X>(u_valid, cells, E, spans);
  valid_along<Axis::Z>(w_valid, cells, E, spans);
}

namespace {

// Off-grid storage faces (beyond the walls) are never extended; their validity is tagged in bit
// 1 of the working copy so that one forward tells them from on-grid halo faces (whose owners
// overwrite the tag). Bit 0 is "valid"; bit 2 marks a face queued for the current layer.
constexpr signed char kValid = 1, kOffGrid = 2, kQueued = 4;

/// The width of the halo around the owned samples (the smallest over the four sides).
int halo_width(const FaceField& f) {
  const auto& o = f.owned();
  const auto& s = f.storage();
  return std::min({o.i0 - s.i0, s.i1 - o.i1, o.k0 - s.k0, s.k1 - o.k1});
}

/// `rounds` layers of extension computed locally on the storage box: layer l on the box shrunk by
/// l, where every value it reads is that of the layer-by-layer scheme with a forward after each
/// layer (the neighbours lie in the box shrunk by l - 1). The owned faces are exact when
/// rounds <= halo width. Only faces next to a face made valid by the previous layer can change,
/// so every layer after the first visits that band only.
void extend_locally(FaceField& f, grid::GridArray<signed char>& v, int rounds,
                    std::vector<std::size_t>& band,
                    std::vector<std::pair<std::size_t, double>>& updates) {
  const core::IndexBox s = f.storage();
  const auto row = static_cast<std::ptrdiff_t>(s.nx());
  const std::ptrdiff_t step[4] = {1, -1, row, -row};  // (i+1), (i-1), (k+1), (k-1)
  double* x = f.data().data();
  signed char* m = v.data().data();
  // first layer: every invalid on-grid face of the box shrunk by 1 with a valid neighbour
  band.clear();
  for (int k = s.k0 + 1; k < s.k1 - 1; ++k)
    for (int i = s.i0 + 1; i < s.i1 - 1; ++i) {
      const std::size_t n = f.index(i, k);
      if (m[n] != 0) continue;
      for (std::ptrdiff_t d : step)
        if (m[static_cast<std::ptrdiff_t>(n) + d] & kValid) {
          band.push_back(n);
          break;
        }
    }
  for (int layer = 1; layer <= rounds; ++layer) {
    updates.clear();
    for (std::size_t n : band) {
      double sum = 0.0;
      int count = 0;
      for (std::ptrdiff_t d : step) {
        const auto a = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(n) + d);
        if (m[a] & kValid) sum += x[a], ++count;
      }
      // u_f = mean of the valid neighbours (one layer of extension)
      if (count > 0) updates.emplace_back(n, sum / count);
    }
    for (const auto& [n, value] : updates) x[n] = value, m[n] = kValid;
    if (layer == rounds) break;
    // next band: invalid on-grid neighbours of the faces just made valid, inside the box shrunk
    // by layer + 1
    band.clear();
    const core::IndexBox next{s.i0 + layer + 1, s.i1 - layer - 1, s.k0 + layer + 1,
                              s.k1 - layer - 1};
    for (const auto& [n, value] : updates) {
      const auto i = s.i0 + static_cast<int>(n % static_cast<std::size_t>(row));
      const auto k = s.k0 + static_cast<int>(n / static_cast<std::size_t>(row));
      const int di[4] = {1, -1, 0, 0}, dk[4] = {0, 0, 1, -1};
      for (int q = 0; q < 4; ++q) {
        const auto a = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(n) + step[q]);
        if (m[a] != 0 || !next.contains(i + di[q], k + dk[q])) continue;
        m[a] = kQueued;
        band.push_back(a);
      }
    }
    for (std::size_t n : band) m[n] = 0;
  }
}

// Marks the halo faces off the grid (beyond the walls): the forward() of v replaces the tag on
// every on-grid halo face with its owner's flag.
void tag_off_grid(const FaceField& f, grid::GridArray<signed char>& v) {
  const core::IndexBox o = f.owned(), s = f.storage();
  for (int k = s.k0; k < s.k1; ++k)
    for (int i = s.i0; i < s.i1; ++i)
      if (!o.contains(i, k)) v(i, k) = static_cast<signed char>((v(i, k) ? kValid : 0) | kOffGrid);
}

}  // namespace

void extend_velocity(FaceField& u, FaceField& w, const grid::GridArray<signed char>& u_valid,
                     const grid::GridArray<signed char>& w_valid, int layers,
                     const grid::Halo& halo) {
  core::ScopedTimer timer("fluid: extend velocity");
  if (layers <= 0) return;
  auto uv = u_valid;
  auto wv = w_valid;
  const int width = std::min(halo_width(u), halo_width(w));
  if (width < 1)
    throw core::SolverError("extend_velocity: the fields need a halo of at least one face");
  // Both components in each exchange: the same values as one component after the other, in
  // half the rounds of messages.
  tag_off_grid(u, uv), tag_off_grid(w, wv);
  halo.forward_all({&uv, &wv});
  halo.forward_all({&u, &w});
  std::vector<std::size_t> band;
  std::vector<std::pair<std::size_t, double>> updates;
  for (int done = 0; done < layers;) {
    const int rounds = std::min(width, layers - done);
    extend_locally(u, uv, rounds, band, updates);
    extend_locally(w, wv, rounds, band, updates);
    done += rounds;
    halo.forward_all({&u, &w});
    if (done < layers) halo.forward_all({&uv, &wv});
  }
}

double max_face_speed(const FaceField& u, const FaceField& w, const core::Comm& comm) {
  double vmax = 0.0;
  for (const FaceField* f : {&u, &w}) {
    const auto& b = f->owned();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) vmax = std::max(vmax, std::abs((*f)(i, k)));
  }
  return comm.max(vmax);
}

double cfl_time_step(const FaceField& u, const FaceField& w, double h, double cfl, double dt_max,
                     const core::Comm& comm) {
  const double vmax = max_face_speed(u, w, comm);
  // dt = min(dt_max, CFL h / max|u|)
  return vmax > 0.0 ? std::min(dt_max, cfl * h / vmax) : dt_max;
}

}  // namespace picdem::fluid
