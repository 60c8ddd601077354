// The fluid part of the pressure rows (eqs. 3, 5) and conversions to the plain-array form.
#include "pressure_rows.hpp"

#include <algorithm>

#include "picdem/core/timer.hpp"

namespace picdem::fluid::detail {

namespace {

constexpr signed char kFluid = static_cast<signed char>(grid::CellState::Fluid);
constexpr signed char kSolid = static_cast<signed char>(grid::CellState::Solid);

}  // namespace

void fluid_rows(const CellStates& cells, const Apertures& E, const grid::FaceField& u,
                const grid::FaceField& w, double dt, const FluidConfig& cfg,
                const SurfaceFractions* surface, const grid::CellField* source,
                const grid::Decomposition& d, RowContributions& rows,
                grid::GridArray<int>& row_of) {
  const grid::GridSpec& g = d.spec();
  const core::IndexBox own = d.owned_cells();
  rows.cells.clear(), rows.row.clear(), rows.col.clear(), rows.val.clear(), rows.rhs.clear();
  rows.with_solids = rows.low_rank = false;
  rows.u_row.clear(), rows.u_col.clear(), rows.u_val.clear(), rows.weight.clear();
  rows.u_diag.clear();
  row_of.fill(-1);
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i)
      if (cells(i, k) == kFluid) {
        row_of(i, k) = static_cast<int>(rows.cells.size());
        rows.cells.push_back(g.cell_gid(i, k));
      }
  rows.rhs.assign(rows.cells.size(), 0.0);
  grid::CellField D(d, grid::Stagger::Cell, 0.0);
  divergence(u, w, E, cells, D);
  const double s = dt / (cfg.rho * g.h);
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) {
      const int r = row_of(i, k);
      if (r < 0) continue;
      double diag = 0.0;
      const struct {
        double E, theta;
        int i, k;
      } faces[4] = {{E.E_x(i, k), surface ? surface->theta_x(i, k) : 1.0, i - 1, k},
                    {E.E_x(i + 1, k), surface ? surface->theta_x(i + 1, k) : 1.0, i + 1, k},
                    {E.E_z(i, k), surface ? surface->theta_z(i, k) : 1.0, i, k - 1},
                    {E.E_z(i, k + 1), surface ? surface->theta_z(i, k + 1) : 1.0, i, k + 1}};
      for (const auto& f : faces) {
        if (f.E <= 0.0) continue;
        if (f.i < 0 || f.k < 0 || f.i >= g.nx || f.k >= g.nz) {
          // an open side (open_boundary.hpp): outflow p = 0 at theta h (the face: theta = 1/2
          // with the ghost fluid), inflow a prescribed velocity (no term)
          if (outflow_beyond(cfg.open, g, i, k, f.i, f.k)) diag += f.E * s / f.theta;
          continue;
        }
        const signed char nb = cells(f.i, f.k);
        if (nb == kSolid) continue;
        // -L_E: diagonal sum_f E_f dt/(rho h); fluid neighbour -E_f dt/(rho h); air: p = 0
        // at theta h (theta = 1: the air cell's centre), diagonal E_f dt/(rho h theta)
        if (nb == kFluid) {
          diag += f.E * s;
          rows.add(r, g.cell_gid(f.i, f.k), -f.E * s);
        } else {
          diag += f.E * s / f.theta;
        }
      }
      rows.add(r, g.cell_gid(i, k), diag);
      // b = -D(u~)  (eq. 5 with the sign of -L_E)
      rows.rhs[static_cast<std::size_t>(r)] = -D(i, k) + (source ? (*source)(i, k) : 0.0);
    }
}

AssembledSystem assembled(const RowContributions& rows) {
  AssembledSystem sys;
  sys.rows = rows.cells;
  sys.rhs = rows.rhs;
  sys.with_solids = rows.with_solids;
  sys.entries.resize(rows.cells.size());
  for (std::size_t c = 0; c < rows.row.size(); ++c)
    sys.entries[static_cast<std::size_t>(rows.row[c])].emplace_back(rows.col[c], rows.val[c]);
  // Sorted by column, duplicates summed in contribution order.
  for (auto& row : sys.entries) {
    std::stable_sort(row.begin(), row.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    std::size_t m = 0;
    for (std::size_t n = 0; n < row.size(); ++n) {
      if (m > 0 && row[m - 1].first == row[n].first)
        row[m - 1].second += row[n].second;
      else
        row[m++] = row[n];
    }
    row.resize(m);
  }
  return sys;
}

RowContributions contributions(const AssembledSystem& sys) {
  RowContributions rows;
  rows.cells = sys.rows;
  rows.rhs = sys.rhs;
  rows.with_solids = sys.with_solids;
  for (std::size_t r = 0; r < sys.entries.size(); ++r)
    for (const auto& [c, v] : sys.entries[r]) rows.add(static_cast<int>(r), c, v);
  return rows;
}

}  // namespace picdem::fluid::detail
