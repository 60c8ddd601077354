#pragma once
// Viscous operator on the staggered grid that sees solids, obstacles and walls at their true
// (cut) position, its implicit (backward Euler) solve, and the viscous loads on each body from
// the same discrete stresses (doc/viscous.md; equations at the top of viscous_operator.cpp).
//
// Each velocity component is treated on its own (the vector Laplacian of a constant-viscosity
// incompressible fluid is component-wise). The stencil is built over the whole grid on every rank
// (replicated): this first version is for runs and tests on one rank; distributing the rows over
// the decomposition is left for the hook into the step (doc/viscous.md).
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "picdem/core/vec2.hpp"
#include "picdem/fluid/fluid.hpp"

namespace picdem::fluid {

/// A rigid body as the viscous operator sees it: a point-inside test (true inside or on the
/// boundary) and the rigid velocity V + omega x (x - centre) that is the no-slip boundary value.
/// Fixed obstacles: velocity 0, omega 0. `area` (the body's area) is needed for the torque of a
/// rotating body (viscous_loads). mass > 0 (per unit depth, with `inertia` about the centre): a
/// free body whose rigid velocity is an unknown of the implicit step (rigid rows, doc/viscous.md);
/// 0: its velocity is prescribed.
struct ViscousBody {
  std::function<bool(const core::Vec2&)> inside;
  core::Vec2 velocity;
  double omega = 0.0;
  core::Vec2 centre;
  double area = 0.0;
  double mass = 0.0, inertia = 0.0;
  /// Free-slip boundary (obstacles/<name>/wall): the legs of the tangential component (the
  /// component across the leg's direction) are dropped, zero gradient; the component along the
  /// leg keeps the body's velocity. Exact on grid-aligned edges only (doc/viscous.md).
  bool free_slip = false;
  /// With mass > 0: omega alone is an unknown of the implicit step, the translation keeps the
  /// split's start-of-step velocity (fluid/viscous_rotation_rows, doc/viscous.md).
  bool rotation_only = false;
  /// A box holding the body (inside and boundary): a point outside it is outside the body, so
  /// `inside` is not asked (the cut-node masses' samples, the stencil's nodes). Unbounded unless
  /// given (viscous_bodies gives it: the solid's centre +- its bounding radius, an obstacle's
  /// vertices' extent, each padded).
  core::Vec2 box_lo{-std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity()};
  core::Vec2 box_hi{std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
  bool in_box(const core::Vec2& x) const {
    return x.x >= box_lo.x && x.x <= box_hi.x && x.z >= box_lo.z && x.z <= box_hi.z;
  }
  core::Vec2 velocity_at(const core::Vec2& x) const {
    return {velocity.x - omega * (x.z - centre.z), velocity.z + omega * (x.x - centre.x)};
  }
};

/// The tank walls: no-slip (0), free-slip (normal 0, zero tangential gradient) or a prescribed
/// velocity (a function of the wall point; used for exact-solution boundaries). `kind` holds for
/// every wall without its own entry in `side` (left, right, bottom, top; TankWall order).
/// Open: an outflow (do-nothing: no leg for either component, open_boundary.hpp).
enum class WallKind { NoSlip, FreeSlip, Prescribed, Open };
/// A point of an open tank side: Prescribed (inflow, with its velocity) or Open (outflow).
struct OpenWallPoint {
  WallKind kind = WallKind::Open;
  core::Vec2 velocity;
};
struct ViscousWalls {
  WallKind kind = WallKind::NoSlip;
  std::function<core::Vec2(const core::Vec2&)> velocity;  ///< for Prescribed
  std::array<std::optional<WallKind>, 4> side{};
  /// Open sides: the kind (and inflow velocity) at a wall point, overriding the wall's kind;
  /// empty or nullopt: the wall's.
  std::function<std::optional<OpenWallPoint>(TankWall, const core::Vec2&)> open{};
  WallKind kind_at(TankWall wall) const {
    const auto& own = side[static_cast<std::size_t>(wall)];
    return own ? *own : kind;
  }
};
/// The walls of the step's fluid configuration (fluid/walls, fluid/wall_<side> and the open
/// sides of cfg.open, their inflow velocity over the step's interval).
ViscousWalls viscous_walls_of(const FluidConfig& cfg);

/// The tank: cells of size h, nx x nz, lower-left corner at origin.
struct ViscousGrid {
  core::Vec2 origin;
  double h = 0.0;
  int nx = 0, nz = 0;
};

/// A boundary leg: the grid line from an unknown towards a neighbour crosses a body or wall at
/// the fraction theta of h; the flux through it is weight (value - u) with weight = 1 / theta.
struct ViscousLeg {
  int unknown = 0;
  int body = -1;  ///< index into the bodies, -1 for the tank walls
  double weight = 0.0;
  double value = 0.0;  ///< the boundary velocity component at the crossing point
  core::Vec2 point;    ///< the crossing point
};

/// The stencil of one velocity component. Nodes: component 0 (u) at x-faces (i in [0, nx],
/// k in [0, nz)), component 1 (w) at z-faces (i in [0, nx), k in [0, nz]); node id i + ni k.
/// h^2 (L u)_r = sum_{neighbours n} u_n - diag_r u_r + sum_{legs of r} weight value.
struct ViscousStencil {
  int component = 0;
  int ni = 0, nk = 0;
  double h = 0.0;
  std::vector<int> unknown_of;  ///< per node: unknown number, -1 for nodes that are not unknowns
  std::vector<int> node_of;     ///< per unknown: node id
  std::vector<double> diag;     ///< per unknown: sum of the weights of its legs (1 interior)
  std::vector<std::array<int, 4>> neighbours;  ///< per unknown: unknown numbers, -1 none
  std::vector<ViscousLeg> legs;
  /// Per unknown: the share of the node's P2G tent (bilinear, 2h x 2h) outside every body, the
  /// node's fluid mass in units of rho h^2 (set_cut_node_masses); empty: 1 for every unknown.
  std::vector<double> mass;
  /// Position of node id n.
  core::Vec2 position(int node, const ViscousGrid& g) const;
};

/// Below this fraction of h a crossing is moved to theta_min h (bounds the weight 1/theta).
constexpr double kViscousThetaMin = 1e-3;

/// Builds the stencil of `component` (0: u, 1: w). A node is an unknown when it is strictly
/// inside the tank (for the wall-normal component), outside every body and, with `fluid_nodes`
/// (one value per node id), marked 1 there: the free surface. A leg to a node that is not an
/// unknown, not in a body and not on the tank wall is dropped (zero gradient, as at the free
/// surface of apply_viscosity).
ViscousStencil build_viscous_stencil(int component, const ViscousGrid& g,
                                     const std::vector<ViscousBody>& bodies,
                                     const ViscousWalls& walls,
                                     const std::vector<unsigned char>* fluid_nodes = nullptr);

/// Sets s.mass: each unknown's share of its P2G tent (bilinear over [-h, h]^2 about the node)
/// outside every body, by the midpoint rule on samples h / 16 apart (each sample's inside test
/// shared by the tents that hold it), on the nodes whose tent meets a body (1 for the others; the
/// tank walls are not counted). The particles fill the fluid only, so this is the
/// node's P2G mass over rho h^2; with it the implicit step's momentum, sum rho h^2 mass (u_new -
/// u_old), is what the particles gain, and it still equals minus the loads (doc/viscous.md,
/// "Cut-node masses").
void set_cut_node_masses(ViscousStencil& s, const ViscousGrid& g,
                         const std::vector<ViscousBody>& bodies);

/// (L u) per node (0 on nodes that are not unknowns): the explicit operator, u per node.
std::vector<double> apply_viscous_operator(const ViscousStencil& s, const std::vector<double>& u);

/// One implicit step for one component: m (u_new - u_old)/dt = nu L (beta u_new + (1 - beta)
/// u_old) + m f, m = s.mass (1 when empty), with f per node [m/s^2]; beta = 1 backward Euler, 1/2
/// Crank-Nicolson; dt = infinity gives the steady problem -nu L u = f. u holds u_old on entry (and
/// the initial guess), u_new on return; nodes that are not unknowns are left unchanged. Solved with
/// Belos CG preconditioned with MueLu (the matrix is symmetric positive definite) to the relative
/// true residual `tolerance`; throws core::SolverError if it is not reached. Returns iterations.
/// The loads of the step are viscous_loads of beta u_new + (1 - beta) u_old (they are linear in u).
/// Belos and MueLu get the declared defaults of viscous_solver/Belos and viscous_solver/MueLu.
int solve_viscous_implicit(const ViscousStencil& s, double nu, double dt,
                           const std::vector<double>& f, std::vector<double>& u,
                           double tolerance = kViscousTolerance, double beta = 1.0);
/// The same with the case's viscous_solver/ settings (tolerance, iteration limit, Belos and MueLu
/// lists; viscous_settings.hpp).
int solve_viscous_implicit(const ViscousStencil& s, double nu, double dt,
                           const std::vector<double>& f, std::vector<double>& u,
                           const ViscousSolverSettings& solver, double beta = 1.0);

/// Viscous force [N/m] and torque [N m/m] on each body (about its centre) and the force on the
/// tank walls, from the boundary legs: the fluid at a leg gains mu weight (value - u) per unit
/// time and depth, the body loses it. These fluxes are those of the Laplacian form mu grad u; the
/// true stress mu (grad u + grad u^T) differs by mu (grad u)^T n, which on a rigid body's surface
/// (divergence-free fluid) is its rigid motion's, omega (n_z, -n_x): no net force, and the torque
/// -2 mu omega area, added to each body's torque (doc/viscous.md).
struct ViscousLoads {
  std::vector<core::Vec2> force;
  std::vector<double> torque;
  core::Vec2 wall_force;
};
ViscousLoads viscous_loads(const ViscousStencil& su, const ViscousStencil& sw,
                           const std::vector<double>& u, const std::vector<double>& w, double mu,
                           const std::vector<ViscousBody>& bodies);

/// Implicit viscosity on the step's fields, in place of apply_viscosity: gathers u, w and the
/// cell states of all ranks, builds the stencils (unknowns: nodes next to a Fluid cell and outside
/// every body; walls no-slip or free-slip from cfg), solves both components with
/// solve_viscous_implicit (f = 0: the step applies gravity after it), writes the owned values back,
/// forwards the halo and enforces the walls. Returns the CG iterations (both components) and the
/// viscous loads of the step (from beta u_new + (1 - beta) u_old). Every rank solves the whole
/// grid (replicated): meant for one rank or small grids until the rows are distributed.
struct ViscousStepResult {
  int iterations = 0;
  ViscousLoads loads;
  std::vector<core::Vec2> velocity;  ///< per body: its rigid velocity in the step (solved if free)
  std::vector<double> omega;
};
ViscousStepResult apply_viscosity_implicit(grid::FaceField& u, grid::FaceField& w,
                                           const CellStates& cells, double dt,
                                           const FluidConfig& cfg, const grid::Decomposition& d,
                                           const grid::Halo& halo,
                                           const std::vector<ViscousBody>& bodies,
                                           double beta = 1.0);

/// The rest of the step after the viscous solve, predicted from the last step's pressure p^n
/// (fluid/viscous_pressure_predictor, doc/viscous.md "Pressure predictor"): du = dt (g - grad p^n /
/// rho) on the interior faces that fluid::apply_gravity and fluid::project change, 0 on the tank's
/// outer faces and elsewhere (apply_gravity and project on zero fields; halo forwarded). The step
/// solves the viscosity for u + du and takes du off again, so that a steady state satisfies the
/// boundary conditions and nu L u = grad p / rho - g without the splitting's O(dt) wall slip.
void viscous_pressure_predictor(grid::FaceField& du, grid::FaceField& dw, const grid::CellField& p,
                                const CellStates& cells, const Apertures& E, double dt,
                                const FluidConfig& cfg, const SurfaceFractions* surface,
                                const grid::Decomposition& d, const grid::Halo& halo);

/// Backward Euler for u and w (u, w: u_old on entry, u_new on return, per node) with the rigid
/// velocities of the free bodies (mass > 0) as unknowns: M_b (s_b - s_b^n) / dt = F_b, F_b the
/// viscous load of body b from the same legs (viscous_loads). Solved by superposition: the fluid
/// solve with the bodies at s^n plus, per free body, its answers to unit rigid velocities (2 more
/// solves per component and body), then a dense 3 x 3 per body system. The bodies' velocities are
/// set to s on return; returns the loads at (u_new, s) and adds the CG iterations. Each solve
/// with `solver` (viscous_solver/ keys).
ViscousLoads solve_viscous_rigid_rows(const ViscousStencil& su, const ViscousStencil& sw, double nu,
                                      double rho, double dt, std::vector<double>& u,
                                      std::vector<double>& w, std::vector<ViscousBody>& bodies,
                                      int& iterations, const ViscousSolverSettings& solver = {});

/// Stability limit of explicit viscosity on a uniform grid: dt <= h^2 / (4 nu) (infinity for
/// nu = 0).
double viscous_time_step(double h, double nu);

/// The time-step limit the viscosity scheme of `cfg` needs: viscous_time_step(cfg.h, cfg.nu) for
/// the explicit scheme, infinity for the implicit one (the step takes the minimum with the CFL).
double viscous_time_limit(const FluidConfig& cfg);

}  // namespace picdem::fluid
