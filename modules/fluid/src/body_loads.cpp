// The solids' rows of the pressure equation and the obstacles' pressure loads from the cut cells
// (body_loads.hpp).
#include "picdem/fluid/body_loads.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <utility>

namespace picdem::fluid {

using core::Vec2;

namespace {

// A table of `width` doubles per solid id, summed over ranks (ids are 0 .. n-1).
struct IdTable {
  int width;
  std::vector<double> v;
  IdTable(std::int64_t n, int w) : width(w), v(static_cast<std::size_t>(n * w), 0.0) {}
  double* row(std::int64_t id) { return &v[static_cast<std::size_t>(id * width)]; }
};

std::int64_t solid_count(const std::vector<core::SolidState>& bodies, const core::Comm& comm) {
  long long n = 0;
  for (const auto& st : bodies) n = std::max(n, static_cast<long long>(st.id) + 1);
  return comm.max(n);
}

bool fluid_cell(const CellStates& cells, int i, int k) {
  return cells(i, k) == static_cast<signed char>(grid::CellState::Fluid);
}

// Hydrostatic quadrature load of one piece: -int rho g.(x - x_c) (n, r x n) dl, exact along the
// piece (arcs included) from its first moments about x_c; 0 without the quadrature.
std::array<double, 3> quadrature_load(const geometry::WettedPiece& piece,
                                      const QuadratureOptions& q) {
  if (!q.hydrostatic) return {0.0, 0.0, 0.0};
  const Vec2 rg = q.rho * q.g;
  return {-(rg.x * piece.dx_n_dl.x + rg.z * piece.dz_n_dl.x),
          -(rg.x * piece.dx_n_dl.z + rg.z * piece.dz_n_dl.z),
          -(rg.x * piece.d_r_cross_n_dl.x + rg.z * piece.d_r_cross_n_dl.z)};
}

}  // namespace

std::vector<SolidCoupling> solid_couplings(const std::vector<core::SolidState>& bodies,
                                           const geometry::CutCells& cut, const CellStates& cells,
                                           const grid::Decomposition& d,
                                           const std::vector<core::SolidLoads>& collision,
                                           const QuadratureOptions& quadrature, double dt) {
  const core::Comm& comm = d.comm();
  const Vec2 gravity = quadrature.g;
  const auto n = solid_count(bodies, comm);
  if (n == 0) return {};
  const auto own = d.owned_cells();
  const auto& spec = d.spec();
  // Predicted collision loads of every solid, from their owners, plus the quadrature loads.
  IdTable coll(n, 3);
  for (const auto& l : collision) {
    double* r = coll.row(l.id);
    r[0] = l.force.x, r[1] = l.force.z, r[2] = l.torque;
  }
  // Each owned fluid cell's pieces: their rows a_{s,c} and quadrature loads, the latter added
  // to the solid's own load and to the table every rank sums for V*.
  std::map<int, SolidCoupling> by_body;  // body index -> coupling, in body order
  std::map<std::pair<int, long long>, std::size_t> slot;
  for (const auto& piece : cut.pieces) {
    if (piece.body < 0 || !own.contains(piece.i, piece.k) || !fluid_cell(cells, piece.i, piece.k))
      continue;
    auto& c = by_body[piece.body];
    const long long gid = spec.cell_gid(piece.i, piece.k);
    auto [it, fresh] = slot.try_emplace({piece.body, gid}, c.cells.size());
    if (fresh) {
      c.cells.push_back(gid);
      c.a.push_back({0.0, 0.0, 0.0});
    }
    auto& a = c.a[it->second];
    a[0] += piece.n_dl.x, a[1] += piece.n_dl.z, a[2] += piece.r_cross_n_dl;
    const auto q = quadrature_load(piece, quadrature);
    double* r = coll.row(bodies[static_cast<std::size_t>(piece.body)].id);
    for (int m = 0; m < 3; ++m) r[m] += q[m], c.load[static_cast<std::size_t>(m)] += q[m];
  }
  comm.sum_in_place(coll.v);

  std::vector<SolidCoupling> out;
  for (auto& [body, c] : by_body) {
    const auto& st = bodies[static_cast<std::size_t>(body)];
    c.id = st.id;
    c.mass = st.mass;
    c.inertia = st.inertia;
    const double* f = coll.row(st.id);
    // V* = V^n + dt M^-1 (F_g + F_coll)   (eq. 6 without the pressure term)
    c.v_star = {st.v.x + dt * (gravity.x + f[0] / st.mass),
                st.v.z + dt * (gravity.z + f[1] / st.mass), st.omega + dt * f[2] / st.inertia};
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<core::SolidLoads> obstacle_pressure_loads(
    const geometry::CutCells& cut, const CellStates& cells, const grid::Decomposition& d,
    const grid::CellField& p, const QuadratureOptions& quadrature, std::size_t count) {
  std::vector<double> table(3 * count, 0.0);  // F_x, F_z, T per obstacle
  const auto own = d.owned_cells();
  const auto& spec = d.spec();
  for (const auto& piece : cut.pieces) {
    if (piece.body >= 0 || !own.contains(piece.i, piece.k) || !fluid_cell(cells, piece.i, piece.k))
      continue;
    const auto o = static_cast<std::size_t>(-1 - piece.body);
    if (o >= count) continue;
    const Vec2 xc = spec.origin + spec.h * Vec2{piece.i + 0.5, piece.k + 0.5};
    const double pc = p(piece.i, piece.k);
    // J p of the piece: -p_c int n dl; torque about (0, 0): -p_c int x x n dl
    Vec2 f = -pc * piece.n_dl;
    double torque =
        -pc * (xc.x * piece.n_dl.z - xc.z * piece.n_dl.x + piece.dx_n_dl.z - piece.dz_n_dl.x);
    if (quadrature.hydrostatic) {
      // F_q = -int rho g.(x - x_c) n dl, its moment taken at x_c (r x n is 0 for obstacles)
      const auto q = quadrature_load(piece, quadrature);
      const Vec2 fq{q[0], q[1]};
      f += fq;
      torque += xc.x * fq.z - xc.z * fq.x;
    }
    table[3 * o] += f.x, table[3 * o + 1] += f.z, table[3 * o + 2] += torque;
  }
  d.comm().sum_in_place(table);
  std::vector<core::SolidLoads> out;
  for (std::size_t o = 0; o < count; ++o)
    out.push_back(
        {static_cast<std::int64_t>(o), {table[3 * o], table[3 * o + 1]}, table[3 * o + 2]});
  return out;
}

}  // namespace picdem::fluid
