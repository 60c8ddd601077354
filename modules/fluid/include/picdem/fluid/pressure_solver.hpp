#pragma once
// The augmented pressure Poisson equation (paper eqs. 5-6, METHOD.md section 4):
//
//   [ -L_E + dt sum_s A_s M_s^-1 A_s^T ] p = sum_s A_s V*_s - D(u~)
//
// -L_E: row c holds sum_f E_f dt/(rho h) on the diagonal and -E_f dt/(rho h) for each fluid
// neighbour (air neighbours: p = 0; solid neighbours and closed faces: E = 0). A_s has one row
// a_{s,c} per cut cell c of solid s; M_s = diag(m, m, I); V* = V^n + dt M^-1 (F_g + F_coll).
// Unknowns are the owned fluid cells, numbered by their global cell id k nx + i. The matrix is a
// Tpetra::CrsMatrix whose structure (maps, graph, Export) is kept while the fluid mask and the
// couplings' cells are unchanged (values refilled), or with solver/pressure_structure fixed while
// the fluid stays inside a kept band of rows (air and solid cells in it identity rows); the
// solids' term is a separate piece (src/coupling_term.hpp), assembled into the matrix
// (solver/coupling_operator: assembled) or applied beside it as dt U M^-1 U^T with MueLu built
// on the fluid rows (low_rank). Belos CG
// preconditioned by MueLu (a new hierarchy every solve) solves it starting from the previous
// pressure. Tpetra, Belos and MueLu stay inside src/.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/core/solid_state.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::fluid {

/// One solid whose boundary cuts fluid cells. A rank may pass only part of a solid's cut cells:
/// the lists of all ranks with the same id are joined. Each (solid, cell) pair must be listed on
/// exactly one rank; cells that are not fluid on their owner are ignored.
struct SolidCoupling {
  std::int64_t id = 0;                    ///< the solid's global id (joins partial lists)
  std::vector<long long> cells;           ///< global cell ids k nx + i of its cut cells
  std::vector<std::array<double, 3>> a;   ///< a_{s,c} = (int n_x dl, int n_z dl, int r x n dl)
  double mass = 0.0, inertia = 0.0;       ///< M_s = diag(m, m, I), per unit depth
  std::array<double, 3> v_star{0, 0, 0};  ///< V* = V^n + dt M^-1 (F_g + F_coll)
  /// A load that does not depend on p, added to J_s p in the loads (the hydrostatic quadrature
  /// load F_q of the listed pieces); the lists with the same id add theirs.
  std::array<double, 3> load{0, 0, 0};
};

struct SolveStats {
  int iterations = 0;
  double relative_residual = 0.0;  ///< ||b - A x|| / ||b||, computed after the solve
  double setup_seconds = 0.0;      ///< assembly + MueLu setup
  double solve_seconds = 0.0;      ///< Belos iterations
  long long unknowns = 0;          ///< global number of fluid cells
  bool reused_structure = false;   ///< the Tpetra structure of the last solve was reused
  long long matrix_entries = 0;    ///< global entries of the matrix MueLu was built on
  long long low_rank_entries = 0;  ///< global entries of U (solver/coupling_operator low_rank)
  int preconditioner_retries = 0;  ///< solves again after CG broke down (solver/MueLu_solids)
};

/// The assembled system in plain arrays (for tests and diagnostics): rows are this rank's owned
/// fluid cells by global cell id; every row lists (column cell id, value) sorted by column.
struct AssembledSystem {
  std::vector<long long> rows;
  std::vector<std::vector<std::pair<long long, double>>> entries;
  std::vector<double> rhs;
  bool with_solids = false;  ///< solid couplings entered (the solver/solid_* settings apply)
};

class PressureSolver {
 public:
  /// What the solver solves: the pressure equation, or the density correction's Poisson
  /// equation (same operator; solver/density_tolerance instead of solver/tolerance and
  /// solver/MueLu_density merged over solver/MueLu).
  enum class Equation { Pressure, DensityCorrection };

  /// Reads solver/tolerance, solver/max_iterations, solver/Belos and solver/MueLu.
  PressureSolver(const grid::Decomposition& d, const core::Params& params,
                 Equation eq = Equation::Pressure);
  ~PressureSolver();
  PressureSolver(const PressureSolver&) = delete;
  PressureSolver& operator=(const PressureSolver&) = delete;

  /// Assembles and solves; p holds the initial guess on entry (previous pressure) and the
  /// solution on exit: owned fluid cells solved, owned non-fluid cells 0, halo forwarded.
  /// `cells` must have a current halo. Throws core::SolverError naming the residual reached
  /// when the relative true residual stays above solver/tolerance. With `surface`, an air
  /// neighbour across a face of fraction theta adds E dt/(rho h theta) to the diagonal (p = 0
  /// at the sub-cell surface); pass the same surface to project(). With `source`, its value on
  /// each owned fluid cell is added to that row's right-hand side (units of D: m^2/s).
  SolveStats solve(const CellStates& cells, const Apertures& E, const grid::FaceField& u,
                   const grid::FaceField& w, const std::vector<SolidCoupling>& couplings, double dt,
                   const FluidConfig& cfg, grid::CellField& p,
                   const SurfaceFractions* surface = nullptr,
                   const grid::CellField* source = nullptr);

  /// The same assembly as solve(), returned as plain arrays instead of solved; the solids'
  /// blocks are in the matrix whatever solver/coupling_operator says.
  AssembledSystem assemble(const CellStates& cells, const Apertures& E, const grid::FaceField& u,
                           const grid::FaceField& w, const std::vector<SolidCoupling>& couplings,
                           double dt, const FluidConfig& cfg,
                           const SurfaceFractions* surface = nullptr,
                           const grid::CellField* source = nullptr) const;

  /// The operator of the last solve() applied to x (one value per row of that system, in the
  /// order of AssembledSystem::rows): the assembled matrix, or with solver/coupling_operator
  /// low_rank the fluid rows plus the solids' low-rank term (for tests). Collective.
  std::vector<double> apply(const std::vector<double>& x) const;

  /// solver/pressure_structure fixed: the band of rows is chosen again from the fluid cells at
  /// the next solve, as a new solver would (called where a checkpoint is written, so that a run
  /// restarted from it chooses the same rows as the run that wrote it: bitwise restarts).
  void choose_rows_again();

  /// The loads J_s p + F_s on every solid of the couplings of the last solve() or assemble(),
  /// from the same rows a_{s,c} the matrix was assembled from (eq. 6; F_s: SolidCoupling::load);
  /// the same vector (ordered by id) on every rank. p: the solved pressure (owned cells read).
  std::vector<core::SolidLoads> solid_loads(const grid::CellField& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Checks solver/Belos, solver/MueLu and its merged lists with Trilinos' validators, and the
/// smoother names with Ifpack2's factory, as the first PressureSolver would; throws
/// core::InputError naming the list. For checks before the run.
void check_solver_settings(const core::Params& params);

/// Initialises MPI (if needed), Kokkos and Tpetra for the life of main(); create one before any
/// PressureSolver::solve (Tpetra::ScopeGuard underneath).
class LinearAlgebraScope {
 public:
  LinearAlgebraScope(int* argc, char*** argv);
  ~LinearAlgebraScope();
  LinearAlgebraScope(const LinearAlgebraScope&) = delete;
  LinearAlgebraScope& operator=(const LinearAlgebraScope&) = delete;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Solves A x = b for an assembled system with the settings of `params` (solver/ keys), starting
/// from x (owned rows of `system`, same order); returns the statistics. Used by the benchmark
/// and the tests of the linear solver alone.
SolveStats solve_system(const grid::Decomposition& d, const core::Params& params,
                        const AssembledSystem& system, std::vector<double>& x);

}  // namespace picdem::fluid
