// The fluid part of the pressure rows (eqs. 3, 5) and conversions to the plain-array form.
#include "pressure_rows.hpp"

#include <algorithm>
#include <string>

#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"

namespace picdem::fluid::detail {

namespace {

constexpr signed char kFluid = static_cast<signed char>(grid::CellState::Fluid);
constexpr signed char kSolid = static_cast<signed char>(grid::CellState::Solid);

}  // namespace

namespace {

/// The rows (cells, row_of, active) of the owned fluid cells, or of the band's owned cells.
void number_rows(const CellStates& cells, const grid::Decomposition& d,
                 const grid::GridArray<signed char>* band, RowContributions& rows,
                 grid::GridArray<int>& row_of) {
  const grid::GridSpec& g = d.spec();
  const core::IndexBox own = d.owned_cells();
  row_of.fill(-1);
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) {
      const bool fluid = cells(i, k) == kFluid;
      if (band && fluid && (*band)(i, k) == 0)
        throw core::SolverError("pressure rows: fluid cell " + std::to_string(g.cell_gid(i, k)) +
                                " outside the kept band");
      if (!(band ? (*band)(i, k) != 0 : fluid)) continue;
      const auto r = static_cast<int>(rows.cells.size());
      if (fluid) row_of(i, k) = r;
      if (fluid && band) rows.active.push_back(r);
      rows.cells.push_back(g.cell_gid(i, k));
    }
}

/// Along one line: out[n] = 1 where in[n - m .. n + m] holds a non-zero (prefix counts).
void dilate_line(const std::vector<int>& in, int m, std::vector<int>& out) {
  const auto n = static_cast<int>(in.size());
  std::vector<int> pre(in.size() + 1, 0);
  for (int a = 0; a < n; ++a)
    pre[static_cast<std::size_t>(a) + 1] =
        pre[static_cast<std::size_t>(a)] + (in[static_cast<std::size_t>(a)] != 0);
  out.assign(in.size(), 0);
  for (int a = 0; a < n; ++a) {
    const int lo = std::max(0, a - m), hi = std::min(n, a + m + 1);
    out[static_cast<std::size_t>(a)] =
        pre[static_cast<std::size_t>(hi)] - pre[static_cast<std::size_t>(lo)] > 0;
  }
}

}  // namespace

void choose_band(const CellStates& cells, int margin, grid::GridArray<signed char>& band) {
  const core::IndexBox sb = cells.storage(), own = cells.owned();
  const auto nxs = static_cast<std::size_t>(sb.i1 - sb.i0);
  const auto nzs = static_cast<std::size_t>(sb.k1 - sb.k0);
  // The box dilation in two passes: along i on every stored line, then along k.
  std::vector<int> line(nxs), out, xdil(nxs * nzs);
  for (int k = sb.k0; k < sb.k1; ++k) {
    for (int i = sb.i0; i < sb.i1; ++i)
      line[static_cast<std::size_t>(i - sb.i0)] = cells(i, k) == kFluid;
    dilate_line(line, margin, out);
    std::copy(out.begin(), out.end(),
              xdil.begin() + static_cast<std::ptrdiff_t>((k - sb.k0) * nxs));
  }
  band.fill(0);
  line.assign(nzs, 0);
  for (int i = own.i0; i < own.i1; ++i) {
    for (std::size_t k = 0; k < nzs; ++k)
      line[k] = xdil[k * nxs + static_cast<std::size_t>(i - sb.i0)];
    dilate_line(line, margin, out);
    for (int k = own.k0; k < own.k1; ++k)
      band(i, k) = static_cast<signed char>(out[static_cast<std::size_t>(k - sb.k0)]);
  }
}

void fluid_rows(const CellStates& cells, const Apertures& E, const grid::FaceField& u,
                const grid::FaceField& w, double dt, const FluidConfig& cfg,
                const SurfaceFractions* surface, const grid::CellField* source,
                const grid::Decomposition& d, RowContributions& rows, grid::GridArray<int>& row_of,
                const grid::GridArray<signed char>* band) {
  const bool fixed = band != nullptr;
  const grid::GridSpec& g = d.spec();
  rows.cells.clear(), rows.row.clear(), rows.col.clear(), rows.val.clear(), rows.rhs.clear();
  rows.with_solids = rows.low_rank = false;
  rows.fixed = fixed;
  rows.active.clear();
  rows.u_row.clear(), rows.u_col.clear(), rows.u_val.clear(), rows.weight.clear();
  rows.u_diag.clear();
  number_rows(cells, d, band, rows, row_of);
  rows.rhs.assign(rows.cells.size(), 0.0);
  grid::CellField D(d, grid::Stagger::Cell, 0.0);
  divergence(u, w, E, cells, D);
  const double s = dt / (cfg.rho * g.h);
  // The rows in number_rows' order (the owned cells k-major), visited without the other cells.
  for (int r = 0; r < static_cast<int>(rows.cells.size()); ++r) {
    const long long cell = rows.cells[static_cast<std::size_t>(r)];
    const int i = static_cast<int>(cell % g.nx), k = static_cast<int>(cell / g.nx);
    const bool fluid = row_of(i, k) >= 0;
    double diag = 0.0;
    const struct {
      double E, theta;
      int i, k;
    } faces[4] = {{E.E_x(i, k), surface ? surface->theta_x(i, k) : 1.0, i - 1, k},
                  {E.E_x(i + 1, k), surface ? surface->theta_x(i + 1, k) : 1.0, i + 1, k},
                  {E.E_z(i, k), surface ? surface->theta_z(i, k) : 1.0, i, k - 1},
                  {E.E_z(i, k + 1), surface ? surface->theta_z(i, k + 1) : 1.0, i, k + 1}};
    for (const auto& f : faces) {
      const bool in_grid = f.i >= 0 && f.k >= 0 && f.i < g.nx && f.k < g.nz;
      // fixed: the same columns at every solve, 0 where the cells are not coupled
      const bool coupled = fluid && f.E > 0.0 && in_grid && cells(f.i, f.k) == kFluid;
      if (fixed && in_grid && !coupled && (*band)(f.i, f.k) != 0)
        rows.add(r, g.cell_gid(f.i, f.k), 0.0);
      if (!fluid || f.E <= 0.0) continue;
      if (!in_grid) {
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
    // identity row of a non-fluid cell (fixed): x = 0 with rhs 0
    rows.add(r, g.cell_gid(i, k), fluid ? diag : 1.0);
    // b = -D(u~)  (eq. 5 with the sign of -L_E)
    if (fluid) rows.rhs[static_cast<std::size_t>(r)] = -D(i, k) + (source ? (*source)(i, k) : 0.0);
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
