// The solids' part of the augmented pressure equation (eqs. 5-6): dt A_s M_s^-1 A_s^T and A_s V*_s
// over the fluid cut cells of every solid, and the loads J_s p + F_s from the same rows. The
// block goes into the matrix, or (rows.low_rank) is kept as U W U^T beside it with only its
// diagonal in the matrix.
#include <array>

#include "coupling_term.hpp"
#include "solid_couplings.hpp"

namespace picdem::fluid::detail {

void RigidBodyTerm::add(const std::vector<SolidCoupling>& couplings, double dt,
                        const CellStates& cells, const grid::GridArray<int>& row_of,
                        const grid::Decomposition& d, RowContributions& rows) {
  const grid::GridSpec& g = d.spec();
  const core::IndexBox own = d.owned_cells();
  constexpr auto kFluid = static_cast<signed char>(grid::CellState::Fluid);
  const auto joined = gather_couplings(couplings, d.comm());
  rows.with_solids = !joined.empty();
  rows_.clear();
  if (joined.empty()) {
    rows.low_rank = false;  // nothing to keep out of the matrix
    return;
  }
  // Which coupling cells are fluid: each owner answers for its cells, summed over ranks.
  std::vector<double> fluid_flag;
  for (const auto& [id, sc] : joined)
    for (long long c : sc.cells) {
      const int i = static_cast<int>(c % g.nx), k = static_cast<int>(c / g.nx);
      const bool inside = c >= 0 && k < g.nz;
      fluid_flag.push_back(inside && own.contains(i, k) && cells(i, k) == kFluid ? 1.0 : 0.0);
    }
  d.comm().sum_in_place(fluid_flag);
  std::size_t flag = 0;
  for (const auto& [id, sc] : joined) {
    SolidCoupling& kept = rows_[id];
    kept = sc;
    kept.cells.clear(), kept.a.clear();
    for (std::size_t a = 0; a < sc.cells.size(); ++a, ++flag)
      if (fluid_flag[flag] != 0.0) kept.cells.push_back(sc.cells[a]), kept.a.push_back(sc.a[a]);
  }
  const bool low_rank = rows.low_rank;
  if (low_rank) rows.u_diag.assign(rows.cells.size(), 0.0);
  int j0 = 0;  // the solid's first unknown of the low-rank term
  for (const auto& [id, sc] : rows_) {
    const std::array<double, 3> Minv{1.0 / sc.mass, 1.0 / sc.mass, 1.0 / sc.inertia};
    if (low_rank)
      for (int m = 0; m < 3; ++m) rows.weight.push_back(dt * Minv[static_cast<std::size_t>(m)]);
    for (std::size_t a = 0; a < sc.cells.size(); ++a) {
      const long long c1 = sc.cells[a];
      const int i = static_cast<int>(c1 % g.nx), k = static_cast<int>(c1 / g.nx);
      if (!own.contains(i, k)) continue;
      const int r = row_of(i, k);
      const auto& a1 = sc.a[a];
      // b_c += a_{s,c} . V*_s
      rows.rhs[static_cast<std::size_t>(r)] +=
          a1[0] * sc.v_star[0] + a1[1] * sc.v_star[1] + a1[2] * sc.v_star[2];
      // dt A_s M_s^-1 A_s^T, entry (c1, c2) = dt a_{c1} . M^-1 a_{c2}
      auto entry = [&](const std::array<double, 3>& a2) {
        return dt * (a1[0] * Minv[0] * a2[0] + a1[1] * Minv[1] * a2[1] + a1[2] * Minv[2] * a2[2]);
      };
      if (!low_rank) {
        for (std::size_t b = 0; b < sc.cells.size(); ++b) rows.add(r, sc.cells[b], entry(sc.a[b]));
        continue;
      }
      // Low rank: row c of U is a_{s,c}; the block's diagonal joins the matrix MueLu sees.
      for (int m = 0; m < 3; ++m) rows.add_u(r, j0 + m, a1[static_cast<std::size_t>(m)]);
      rows.add(r, c1, entry(a1));
      rows.u_diag[static_cast<std::size_t>(r)] += entry(a1);
    }
    j0 += 3;
  }
}

std::vector<core::SolidLoads> RigidBodyTerm::loads(const grid::CellField& p,
                                                   const grid::Decomposition& d) const {
  return coupling_loads(rows_, p, d);
}

}  // namespace picdem::fluid::detail
