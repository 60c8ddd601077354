// Obstacle pressure loads and the rows of forces.csv (body_forces.hpp).
#include "body_forces.hpp"

namespace picdem::coupling {

using core::Vec2;

std::vector<core::SolidLoads> obstacle_pressure_loads(const geometry::CutCells& cut,
                                                      const fluid::CellStates& cells,
                                                      const grid::Decomposition& d,
                                                      const grid::CellField& p,
                                                      const QuadratureOptions& quadrature,
                                                      std::size_t count, const core::Comm& comm) {
  std::vector<double> table(3 * count, 0.0);  // F_x, F_z, T per obstacle
  const auto own = d.owned_cells();
  const auto& spec = d.spec();
  const Vec2 rg = quadrature.rho * quadrature.g;
  for (const auto& piece : cut.pieces) {
    if (piece.body >= 0 || !own.contains(piece.i, piece.k) ||
        cells(piece.i, piece.k) != static_cast<signed char>(grid::CellState::Fluid))
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
      // F_q = -int rho g.(x - x_c) n dl (solids_in_fluid.cpp), its moment taken at x_c
      const Vec2 fq{-(rg.x * piece.dx_n_dl.x + rg.z * piece.dz_n_dl.x),
                    -(rg.x * piece.dx_n_dl.z + rg.z * piece.dz_n_dl.z)};
      f += fq;
      torque += xc.x * fq.z - xc.z * fq.x;
    }
    table[3 * o] += f.x, table[3 * o + 1] += f.z, table[3 * o + 2] += torque;
  }
  comm.sum_in_place(table);
  std::vector<core::SolidLoads> out;
  for (std::size_t o = 0; o < count; ++o)
    out.push_back(
        {static_cast<std::int64_t>(o), {table[3 * o], table[3 * o + 1]}, table[3 * o + 2]});
  return out;
}

std::vector<BodyForces> body_forces(const std::vector<core::SolidLoads>& pressure,
                                    const std::vector<core::SolidLoads>& obstacles,
                                    const ViscousExchange& viscous) {
  std::vector<BodyForces> rows;
  auto viscous_of = [](const std::vector<core::SolidLoads>& v, std::int64_t id) {
    return id >= 0 && static_cast<std::size_t>(id) < v.size() ? v[static_cast<std::size_t>(id)]
                                                              : core::SolidLoads{id, {}, 0.0};
  };
  for (const auto& l : pressure) {
    const auto v = viscous_of(viscous.solids, l.id);
    rows.push_back({l.id, false, l.force, v.force, l.torque, v.torque});
  }
  for (const auto& l : obstacles) {
    const auto v = viscous_of(viscous.obstacles, l.id);
    rows.push_back({l.id, true, l.force, v.force, l.torque, v.torque});
  }
  return rows;
}

}  // namespace picdem::coupling
