#pragma once
// The pressure system of one rank as the assembly produces it, before it goes to Tpetra (private
// to the fluid module): the fluid part -L_E, D (eqs. 3, 5) and the plain-array form for tests.
#include <vector>

#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/grid/field.hpp"

namespace picdem::fluid::detail {

/// Rows are this rank's owned fluid cells; every matrix entry is a contribution (row, column cell
/// id, value) in a fixed order, so that duplicates are always summed in the same order, whether
/// the Tpetra structure is rebuilt or reused (bitwise restarts).
struct RowContributions {
  std::vector<long long> cells;  ///< row r: the owned fluid cell k nx + i (k-major order)
  std::vector<int> row;          ///< per contribution: its row
  std::vector<long long> col;    ///< per contribution: the cell id of its column
  std::vector<double> val;       ///< per contribution: its value
  std::vector<double> rhs;       ///< per row
  bool with_solids = false;      ///< solid couplings entered (solver/MueLu_solids applies)
  // The solids' term kept out of the matrix (solver/coupling_operator low_rank): U W U^T with U's
  // entries (row, unknown j = 3 x the solid's index + component, value a_{s,c} component), W the
  // diagonal dt M_s^-1 (3 per solid, the same on every rank); the contributions above then hold
  // its diagonal only, also kept per row in u_diag (the operator subtracts it again).
  bool low_rank = false;
  // solver/pressure_structure fixed: the rows are the owned cells of a kept set (the band:
  // every cell within solver/structure_margin of the fluid when it was chosen), k-major, with
  // the same columns at every solve (itself and its neighbours in the band, explicit zeros where
  // there is no coupling); the rows of non-fluid cells are identity rows (x = 0, rhs 0).
  // `active`: the rows of the fluid cells, in order (fixed only).
  bool fixed = false;
  std::vector<int> active;
  std::vector<int> u_row, u_col;
  std::vector<double> u_val, weight, u_diag;

  void add(int r, long long c, double v) { row.push_back(r), col.push_back(c), val.push_back(v); }
  void add_u(int r, int j, double v) { u_row.push_back(r), u_col.push_back(j), u_val.push_back(v); }
};

/// -L_E and b = -D(u~) (+ source) of the owned fluid cells into `rows` (cleared first): per row
/// its fluid neighbours in face order, then the diagonal (eqs. 3, 5). row_of: the row of every
/// owned fluid cell, -1 elsewhere. With a `band` (RowContributions::fixed; non-zero on its
/// cells, halo current, every fluid cell in it), every owned cell of the band is a row: its
/// neighbours in the band in face order (0 where not a fluid coupling), then the diagonal (1 on
/// the identity rows of non-fluid cells).
void fluid_rows(const CellStates& cells, const Apertures& E, const grid::FaceField& u,
                const grid::FaceField& w, double dt, const FluidConfig& cfg,
                const SurfaceFractions* surface, const grid::CellField* source,
                const grid::Decomposition& d, RowContributions& rows, grid::GridArray<int>& row_of,
                const grid::GridArray<signed char>* band = nullptr);

/// The band of the fixed rows: every owned cell within `margin` cells (along i and k) of a fluid
/// cell of this rank's storage window (cells' halo current), 1 there and 0 elsewhere; the halo is
/// left to the caller.
void choose_band(const CellStates& cells, int margin, grid::GridArray<signed char>& band);

/// The plain-array form: per row (column, value) sorted by column, duplicates summed.
AssembledSystem assembled(const RowContributions& rows);
/// Contributions of a system in plain-array form (solve_system).
RowContributions contributions(const AssembledSystem& sys);

}  // namespace picdem::fluid::detail
