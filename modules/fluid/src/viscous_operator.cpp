// The cut-boundary viscous operator (viscous.hpp, doc/viscous.md).
//
// Discretisation, per velocity component u (nodes on the faces of the MAC grid, spacing h):
// a node is an unknown when it lies in the fluid (outside every body, inside the tank). From an
// unknown u_P the four grid lines towards its neighbours are its legs. A leg whose neighbour u_N is
// an unknown is interior; a leg that meets a body, obstacle or wall before the neighbour, at the
// distance theta h (0 < theta <= 1, found on the body's true boundary, theta >= kViscousThetaMin),
// is a boundary leg with the boundary value u_B = V + omega x (x_B - x_c) of that body at the
// crossing point x_B. With the linear ghost value u_G = (u_B + (theta - 1) u_P) / theta at the
// neighbour's place (Gibou et al. 2002, J. Comput. Phys. 176), the 5-point Laplacian becomes
//
//   h^2 (L u)_P = sum_{interior legs} (u_N - u_P) + sum_{boundary legs} (u_B - u_P) / theta,
//
// symmetric in the unknowns (interior legs couple P and N with the same weight 1), so the implicit
// matrix is symmetric positive definite. The solution is second-order accurate although the
// truncation error at the boundary is O(1) (measured in doc/viscous.md). Tank walls: the wall-
// normal component is 0 (or prescribed) on the wall, reached at theta = 1; the tangential
// component meets a no-slip wall at theta = 1/2 with u_B = 0; free-slip drops the leg (zero
// gradient). Read as a finite-volume balance of the node's h x h box, the fluid gains per unit
// time and depth mu (u_B - u_P) / theta through a boundary leg and mu (u_N - u_P) through an
// interior leg; interior legs cancel in pairs, so the momentum the fluid gains equals minus the
// sum of the loads given to the bodies and walls (viscous_loads) to round-off.
// Free surface: nodes outside the caller's fluid mask are not unknowns and legs to them are
// dropped (zero gradient at the midpoint). Not seen by this version: a body thinner than h
// between two fluid nodes (the leg does not test the segment between them).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "picdem/core/error.hpp"
#include "picdem/fluid/viscous.hpp"
#include "picdem/grid/tent.hpp"

namespace picdem::fluid {

using core::Vec2;

namespace {

constexpr int kDi[4] = {1, -1, 0, 0};
constexpr int kDk[4] = {0, 0, 1, -1};

double component_of(const Vec2& v, int c) {
  return c == 0 ? v.x : v.z;
}

/// The first crossing of the segment p -> t (p outside every body) with a body that contains t:
/// the body's index and the fraction s in (0, 1] of the segment, by bisection on the inside test
/// (60 halvings: s to round-off). body = -1 when no body contains t.
struct Crossing {
  int body = -1;
  double s = 1.0;
};
Crossing first_crossing(const Vec2& p, const Vec2& t, const std::vector<ViscousBody>& bodies) {
  Crossing best;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (!bodies[b].inside(t)) continue;
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (bodies[b].inside(p + mid * (t - p)))
        hi = mid;
      else
        lo = mid;
    }
    const double s = 0.5 * (lo + hi);
    if (best.body < 0 || s < best.s) best = {static_cast<int>(b), s};
  }
  return best;
}

bool any_inside(const Vec2& x, const std::vector<ViscousBody>& bodies) {
  for (const auto& b : bodies)
    if (b.in_box(x) && b.inside(x)) return true;
  return false;
}

/// The tank wall a leg in direction d (kDi, kDk) meets.
TankWall wall_towards(int d) {
  if (kDi[d] != 0) return kDi[d] < 0 ? TankWall::Left : TankWall::Right;
  return kDk[d] < 0 ? TankWall::Bottom : TankWall::Top;
}

/// Adds the boundary leg of unknown r towards target t (at the fraction `reach` of h from the
/// node: 1 for a neighbour node, 1/2 for a wall between nodes), or the wall's leg when no body is
/// met first; `on_wall` says that t is on the tank wall, the one in direction d.
void add_boundary_leg(ViscousStencil& s, int r, const Vec2& p, const Vec2& t, double reach,
                      bool on_wall, int d, const std::vector<ViscousBody>& bodies,
                      const ViscousWalls& walls) {
  const Crossing c = first_crossing(p, t, bodies);
  ViscousLeg leg;
  leg.unknown = r;
  if (c.body >= 0) {
    // free-slip body: no leg for the component across the leg's direction (zero gradient)
    const bool across = (kDi[d] != 0) != (s.component == 0);
    if (across && bodies[static_cast<std::size_t>(c.body)].free_slip) return;
    leg.body = c.body;
    leg.point = p + c.s * (t - p);
    leg.value =
        component_of(bodies[static_cast<std::size_t>(c.body)].velocity_at(leg.point), s.component);
    leg.weight = 1.0 / std::max(c.s * reach, kViscousThetaMin);
  } else {
    if (!on_wall) return;  // a neighbour that is not an unknown and not in a body: none here
    const bool tangential = reach < 1.0;
    WallKind kind = walls.kind_at(wall_towards(d));
    std::optional<OpenWallPoint> open;
    if (walls.open) open = walls.open(wall_towards(d), t);
    if (open) kind = open->kind;
    if (kind == WallKind::Open) return;                    // outflow, do-nothing: no leg
    if (tangential && kind == WallKind::FreeSlip) return;  // zero gradient: no leg
    leg.body = -1;
    leg.point = t;
    if (kind == WallKind::Prescribed)
      leg.value = component_of(open ? open->velocity : walls.velocity(t), s.component);
    else
      leg.value = 0.0;
    leg.weight = 1.0 / reach;
  }
  s.diag[static_cast<std::size_t>(r)] += leg.weight;
  s.legs.push_back(leg);
}

}  // namespace

Vec2 ViscousStencil::position(int node, const ViscousGrid& g) const {
  const int i = node % ni, k = node / ni;
  const double x = component == 0 ? i * h : (i + 0.5) * h;
  const double z = component == 0 ? (k + 0.5) * h : k * h;
  return g.origin + Vec2{x, z};
}

ViscousStencil build_viscous_stencil(int component, const ViscousGrid& g,
                                     const std::vector<ViscousBody>& bodies,
                                     const ViscousWalls& walls,
                                     const std::vector<unsigned char>* fluid_nodes) {
  if (!(g.h > 0.0) || g.nx < 1 || g.nz < 1)
    throw core::InputError("viscous stencil: the grid needs h > 0 and at least one cell");
  for (TankWall wall : {TankWall::Left, TankWall::Right, TankWall::Bottom, TankWall::Top})
    if (walls.kind_at(wall) == WallKind::Prescribed && !walls.velocity)
      throw core::InputError("viscous stencil: prescribed walls need a velocity function");
  const std::size_t nodes = component == 0 ? std::size_t(g.nx + 1) * std::size_t(g.nz)
                                           : std::size_t(g.nx) * std::size_t(g.nz + 1);
  if (fluid_nodes && fluid_nodes->size() != nodes)
    throw core::InputError("viscous stencil: the fluid-node mask needs one value per node");
  ViscousStencil s;
  s.component = component;
  s.h = g.h;
  s.ni = component == 0 ? g.nx + 1 : g.nx;
  s.nk = component == 0 ? g.nz : g.nz + 1;
  s.unknown_of.assign(static_cast<std::size_t>(s.ni) * static_cast<std::size_t>(s.nk), -1);
  for (int k = 0; k < s.nk; ++k)
    for (int i = 0; i < s.ni; ++i) {
      const bool on_wall = component == 0 ? (i == 0 || i == g.nx) : (k == 0 || k == g.nz);
      const int n = i + s.ni * k;
      if (on_wall || (fluid_nodes && !(*fluid_nodes)[static_cast<std::size_t>(n)]) ||
          any_inside(s.position(n, g), bodies))
        continue;
      s.unknown_of[static_cast<std::size_t>(n)] = static_cast<int>(s.node_of.size());
      s.node_of.push_back(n);
    }
  const std::size_t nu = s.node_of.size();
  s.diag.assign(nu, 0.0);
  s.neighbours.assign(nu, {-1, -1, -1, -1});
  for (std::size_t r = 0; r < nu; ++r) {
    const int n = s.node_of[r], i = n % s.ni, k = n / s.ni;
    const Vec2 p = s.position(n, g);
    for (int d = 0; d < 4; ++d) {
      const int in = i + kDi[d], kn = k + kDk[d];
      const int ri = static_cast<int>(r);
      if (in < 0 || kn < 0 || in >= s.ni || kn >= s.nk) {
        // Past the last node: the tangential component's wall, half a cell away.
        const Vec2 t = p + Vec2{0.5 * g.h * kDi[d], 0.5 * g.h * kDk[d]};
        add_boundary_leg(s, ri, p, t, 0.5, true, d, bodies, walls);
        continue;
      }
      const int m = in + s.ni * kn;
      const int rn = s.unknown_of[static_cast<std::size_t>(m)];
      if (rn >= 0) {
        s.neighbours[r][static_cast<std::size_t>(d)] = rn;
        s.diag[r] += 1.0;
        continue;
      }
      const bool wall_node = component == 0 ? (in == 0 || in == g.nx) : (kn == 0 || kn == g.nz);
      add_boundary_leg(s, ri, p, s.position(m, g), 1.0, wall_node, d, bodies, walls);
    }
  }
  return s;
}

void set_cut_node_masses(ViscousStencil& s, const ViscousGrid& g,
                         const std::vector<ViscousBody>& bodies) {
  // Midpoint rule on a lattice of spacing h / kPerCell shared by the tents of neighbouring nodes
  // (sample (X + 1/2) h / kPerCell from the component's first node), each sample tested once.
  constexpr int kPerCell = 16;
  const double step = 1.0 / kPerCell;
  std::unordered_map<long long, bool> fluid_at;
  const Vec2 first = s.position(0, g);
  auto fluid_sample = [&](long long X, long long Z) {
    const long long key = X * 4294967296LL + Z;
    const auto it = fluid_at.find(key);
    if (it != fluid_at.end()) return it->second;
    const Vec2 x = first + Vec2{(X + 0.5) * step * g.h, (Z + 0.5) * step * g.h};
    return fluid_at[key] = !any_inside(x, bodies);
  };
  // The tent's share (per axis) of each sample's stretch [a step - 1, (a + 1) step - 1].
  std::array<double, 2 * kPerCell> share;
  for (int a = 0; a < 2 * kPerCell; ++a)
    share[static_cast<std::size_t>(a)] = grid::tent_share(a * step - 1.0, (a + 1) * step - 1.0);
  s.mass.assign(s.node_of.size(), 1.0);
  for (std::size_t r = 0; r < s.node_of.size(); ++r) {
    const int n = s.node_of[r], i = n % s.ni, k = n / s.ni;
    const Vec2 p = s.position(n, g);
    // Only a node whose tent meets a body: one of the 8 nodes about it (its tent's corners and
    // sides) is no unknown and inside a body (a body between them reaches in by under h^2 / 8R).
    bool near = false;
    for (int a = -1; a <= 1 && !near; ++a)
      for (int c = -1; c <= 1 && !near; ++c) {
        const int in = i + a, kn = k + c;
        if ((a == 0 && c == 0) || in < 0 || kn < 0 || in >= s.ni || kn >= s.nk) continue;
        near = s.unknown_of[static_cast<std::size_t>(in + s.ni * kn)] < 0 &&
               any_inside(p + Vec2{a * g.h, c * g.h}, bodies);
      }
    if (!near) continue;
    // m = integral of the tent (1 - |x| / h)(1 - |z| / h) over the fluid, / h^2
    double m = 0.0;
    for (int a = 0; a < 2 * kPerCell; ++a)
      for (int c = 0; c < 2 * kPerCell; ++c)
        if (fluid_sample(static_cast<long long>(i - 1) * kPerCell + a,
                         static_cast<long long>(k - 1) * kPerCell + c))
          m += share[static_cast<std::size_t>(a)] * share[static_cast<std::size_t>(c)];
    s.mass[r] = m;
  }
}

std::vector<double> apply_viscous_operator(const ViscousStencil& s, const std::vector<double>& u) {
  std::vector<double> lap(u.size(), 0.0);
  std::vector<double> acc(s.node_of.size(), 0.0);
  for (std::size_t r = 0; r < s.node_of.size(); ++r) {
    const double up = u[static_cast<std::size_t>(s.node_of[r])];
    double sum = 0.0;
    for (int rn : s.neighbours[r])
      if (rn >= 0) sum += u[static_cast<std::size_t>(s.node_of[static_cast<std::size_t>(rn)])] - up;
    acc[r] = sum;
  }
  for (const ViscousLeg& leg : s.legs) {
    const auto r = static_cast<std::size_t>(leg.unknown);
    acc[r] += leg.weight * (leg.value - u[static_cast<std::size_t>(s.node_of[r])]);
  }
  for (std::size_t r = 0; r < s.node_of.size(); ++r)
    lap[static_cast<std::size_t>(s.node_of[r])] = acc[r] / (s.h * s.h);
  return lap;
}

ViscousLoads viscous_loads(const ViscousStencil& su, const ViscousStencil& sw,
                           const std::vector<double>& u, const std::vector<double>& w, double mu,
                           const std::vector<ViscousBody>& bodies) {
  ViscousLoads loads;
  loads.force.assign(bodies.size(), Vec2{});
  loads.torque.assign(bodies.size(), 0.0);
  for (const ViscousStencil* s : {&su, &sw}) {
    const std::vector<double>& field = s->component == 0 ? u : w;
    for (const ViscousLeg& leg : s->legs) {
      const double up =
          field[static_cast<std::size_t>(s->node_of[static_cast<std::size_t>(leg.unknown)])];
      // The fluid gains mu weight (u_B - u_P); the body gets the opposite.
      const double f = -mu * leg.weight * (leg.value - up);
      const Vec2 F = s->component == 0 ? Vec2{f, 0.0} : Vec2{0.0, f};
      if (leg.body < 0) {
        loads.wall_force += F;
        continue;
      }
      const auto b = static_cast<std::size_t>(leg.body);
      loads.force[b] += F;
      const Vec2 r = leg.point - bodies[b].centre;
      loads.torque[b] += r.x * F.z - r.z * F.x;
    }
  }
  // The symmetric part of the stress: mu (grad u)^T n = mu omega (n_z, -n_x) on the surface,
  // whose torque over the closed surface is -mu omega integral r.n dl = -2 mu omega area.
  for (std::size_t b = 0; b < bodies.size(); ++b)
    loads.torque[b] -= 2.0 * mu * bodies[b].omega * bodies[b].area;
  return loads;
}

double viscous_time_step(double h, double nu) {
  if (nu <= 0.0) return std::numeric_limits<double>::infinity();
  // Explicit diffusion on the 5-point stencil: dt nu 8 / h^2 <= 2.
  return h * h / (4.0 * nu);
}

double viscous_time_limit(const FluidConfig& cfg) {
  if (cfg.implicit_viscosity) return std::numeric_limits<double>::infinity();
  return viscous_time_step(cfg.h, cfg.nu);
}

}  // namespace picdem::fluid
