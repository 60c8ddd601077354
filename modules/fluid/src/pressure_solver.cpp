// The augmented pressure equation (eqs. 5-6) solved by Belos CG preconditioned with MueLu
// smoothed aggregation: the rows (pressure_rows.cpp) and the coupling term (coupling_term.hpp)
// are assembled, handed to the Tpetra system kept between solves (tpetra_system.cpp), and
// solved with the declared solver settings. One of the few files that include Belos and MueLu.
#include "picdem/fluid/pressure_solver.hpp"

#include <BelosLinearProblem.hpp>
#include <BelosPseudoBlockCGSolMgr.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Ifpack2_Factory.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <MueLu_HierarchyUtils.hpp>
#include <MueLu_MasterList.hpp>
#include <MueLu_ParameterListInterpreter.hpp>
#include <Tpetra_Core.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

#include "coupling_term.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"
#include "pressure_rows.hpp"
#include "solver_sublists.hpp"
#include "tpetra_system.hpp"

namespace picdem::fluid {

namespace {

using MV = Tpetra::MultiVector<>;
using OP = Tpetra::Operator<>;
using Teuchos::RCP;
using Teuchos::rcp;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The linear-solver settings read once from the case: the declared lists of solver/Belos and
/// solver/MueLu, and the lists merged over MueLu's for systems with solids and for systems
/// solved on one level on several ranks (fluid::declare_parameters declares all four).
struct SolverSettings {
  double tolerance = 1e-8;  // solver/tolerance, or solver/density_tolerance
  int max_iterations = 500;
  bool rebalance = true;
  bool low_rank = false;  // solver/coupling_operator: low_rank
  bool fixed = false;     // solver/pressure_structure: fixed
  int margin = 0;         // solver/structure_margin
  bool density = false;   // the density correction's solve (its own timers)
  Teuchos::ParameterList belos, muelu, muelu_solids, muelu_one_level;
};

/// `over`'s keys merged over `base`. A "smoother: params" sublist belongs to its smoother: the
/// "chebyshev: ..." keys of the default list are dropped when the merged smoother is not
/// Chebyshev (Ifpack2 rejects keys of another smoother).
Teuchos::ParameterList merged(const Teuchos::ParameterList& base,
                              const Teuchos::ParameterList* over) {
  Teuchos::ParameterList m = base;
  if (over) m.setParameters(*over);
  if (m.isSublist("smoother: params") &&
      m.get<std::string>("smoother: type", "RELAXATION") != "CHEBYSHEV") {
    Teuchos::ParameterList& sp = m.sublist("smoother: params");
    std::vector<std::string> cheb;
    for (auto it = sp.begin(); it != sp.end(); ++it)
      if (sp.name(it).rfind("chebyshev: ", 0) == 0) cheb.push_back(sp.name(it));
    for (const auto& k : cheb) sp.remove(k);
  }
  return m;
}

/// MueLu's list for a system: solver/MueLu, then solver/MueLu_solids if it couples solids, then
/// solver/MueLu_one_level if it has no coarser level and several ranks.
Teuchos::ParameterList muelu_list(const SolverSettings& s, bool with_solids, long long unknowns,
                                  int ranks, bool* one_level = nullptr) {
  Teuchos::ParameterList m = merged(s.muelu, with_solids ? &s.muelu_solids : nullptr);
  const bool one = ranks > 1 && unknowns <= m.get<int>("coarse: max size", 2000);
  if (one) m = merged(m, &s.muelu_one_level);
  if (one_level) *one_level = one;
  return m;
}

/// Trilinos' own lists of valid parameters check the case's lists before the first solve:
/// Belos' valid parameters of PseudoBlockCG, MueLu's master list (top level) and the smoother and
/// coarse sublists by the Ifpack2 smoother or MueLu direct solver they configure.
void validate(const SolverSettings& s) {
  const std::vector<std::pair<const char*, Teuchos::ParameterList>> lists = {
      {"solver/MueLu", merged(s.muelu, nullptr)},
      {"solver/MueLu_solids", merged(s.muelu, &s.muelu_solids)},
      {"solver/MueLu_one_level", merged(s.muelu, &s.muelu_one_level)},
      {"solver/MueLu_density", s.muelu}};
  for (const auto& [key, list] : lists) detail::check_muelu_list(key, list);
  try {
    Belos::PseudoBlockCGSolMgr<double, MV, OP> cg;
    s.belos.validateParameters(*cg.getValidParameters(), 0);
  } catch (const std::exception& e) {
    throw core::InputError(std::string("solver/Belos: Belos rejected the settings: ") + e.what());
  }
}

/// The settings of the pressure solve, or of the density correction's solve: its own tolerance
/// and solver/MueLu_density merged over solver/MueLu.
SolverSettings settings_from(const core::Params& params,
                             PressureSolver::Equation eq = PressureSolver::Equation::Pressure) {
  const bool density = eq == PressureSolver::Equation::DensityCorrection;
  SolverSettings s;
  s.tolerance = params.real(density ? "solver/density_tolerance" : "solver/tolerance");
  s.max_iterations = static_cast<int>(params.integer("solver/max_iterations"));
  s.rebalance = params.boolean("solver/rebalance");
  s.density = density;
  s.low_rank = params.string("solver/coupling_operator") == "low_rank";
  s.fixed = params.string("solver/pressure_structure") == "fixed";
  s.margin = static_cast<int>(params.integer("solver/structure_margin"));
  s.belos = params.teuchos("solver/Belos");
  s.muelu = params.teuchos("solver/MueLu");
  s.muelu_solids = params.teuchos("solver/MueLu_solids");
  s.muelu_one_level = params.teuchos("solver/MueLu_one_level");
  if (density) {
    const Teuchos::ParameterList over = params.teuchos("solver/MueLu_density");
    s.muelu = merged(s.muelu, &over);
  }
  validate(s);
  return s;
}

/// MueLu's interpreters of the solver's lists, made once: turning a parameter list into
/// factories took a fifth of every setup (doc/performance.md). Each hierarchy is still built
/// from scratch, so it is a function of the matrix alone (bitwise restarts). One per list: with
/// or without solids, with or without the one-level override.
struct Interpreters {
  using Manager = MueLu::HierarchyManager<double, OP::local_ordinal_type, OP::global_ordinal_type,
                                          OP::node_type>;
  std::array<RCP<Manager>, 4> made;
};

/// MueLu's hierarchy for the system's matrix: the list for this system (muelu_list) with the
/// cell-centre coordinates on level 0, set up by the kept interpreter of that list. With the
/// solids' term kept out of the matrix, the matrix has no dense blocks: solver/MueLu alone.
RCP<OP> preconditioner(const detail::TpetraSystem& ts, const SolverSettings& settings,
                       bool with_solids, long long unknowns, int ranks, Interpreters& kept) {
  using SC = double;
  using LO = OP::local_ordinal_type;
  using GO = OP::global_ordinal_type;
  using NO = OP::node_type;
  core::ScopedTimer timer(settings.density ? "fluid: density preconditioner"
                                           : "fluid: pressure preconditioner");
  bool one_level = false;
  Teuchos::ParameterList muelu = muelu_list(settings, with_solids, unknowns, ranks, &one_level);
  RCP<Interpreters::Manager>& made = kept.made[(with_solids ? 2 : 0) + (one_level ? 1 : 0)];
  try {
    const auto comm = ts.matrix()->getDomainMap()->getComm();
    if (made.is_null())
      made = rcp(new MueLu::ParameterListInterpreter<SC, LO, GO, NO>(muelu, comm));
    auto A = MueLu::TpetraCrs_To_XpetraMatrix<SC, LO, GO, NO>(ts.matrix());
    Teuchos::ParameterList user;
    user.sublist("user data")
        .set("Coordinates",
             MueLu::TpetraMultiVector_To_XpetraMultiVector<SC, LO, GO, NO>(ts.coordinates()));
    RCP<MueLu::Hierarchy<SC, LO, GO, NO>> H = made->CreateHierarchy();
    H->setlib(A->getDomainMap()->lib());
    MueLu::HierarchyUtils<SC, LO, GO, NO>::AddNonSerializableDataToHierarchy(*made, *H, user);
    H->GetLevel(0)->Set("A", A);
    H->SetProcRankVerbose(comm->getRank());
    {
      core::ScopedTimer hierarchy(settings.density ? "fluid: density preconditioner: hierarchy"
                                                   : "fluid: pressure preconditioner: hierarchy");
      made->SetupHierarchy(*H);
    }
    return rcp(new MueLu::TpetraOperator<SC, LO, GO, NO>(H));
  } catch (const Teuchos::Exceptions::InvalidParameter& e) {
    throw core::InputError(std::string("solver/MueLu: MueLu rejected the settings: ") + e.what());
  }
}

/// Why Belos' CG stops short on the pressure equation, with what the case can change.
std::string singular_hint() {
  return "the matrix may be singular, nearly so, or not positive definite. A body of water with "
         "no free surface and no outflow boundary has no pressure level, and water entering it "
         "through an inflow (open/<side>) has nowhere to go: give it an outflow or room above it";
}

/// The message of a Belos CG breakdown (p^T A p <= 0; Belos' last line of `what`).
std::string breakdown_message(bool density, const std::string& what) {
  std::string last = what;
  while (!last.empty() && (last.back() == '\n' || last.back() == ' ')) last.pop_back();
  const std::size_t cut = last.find_last_of('\n');
  if (cut != std::string::npos) last = last.substr(cut + 1);
  return std::string(density ? "density correction" : "pressure") +
         " solve broke down (Belos: " + last + "): " + singular_hint();
}

/// Belos CG from the system's x; the implicit residual may drift from the true one, so after the
/// solve ||b - A x|| / ||b|| is computed and the solve restarts once from the reached x if it is
/// above the tolerance. Adds the iterations and sets the true residual in `stats`. False, with
/// the message in `breakdown`, when CG broke down (p^T A p <= 0).
bool run_cg(const detail::TpetraSystem& ts, const RCP<OP>& prec, const SolverSettings& settings,
            double b_norm, SolveStats& stats, std::string& breakdown) {
  core::ScopedTimer timer(settings.density ? "fluid: density solve" : "fluid: pressure solve");
  const auto& A = ts.op();
  auto true_residual = [&]() {
    MV R(A->getRangeMap(), 1);
    A->apply(*ts.x(), R);
    R.update(1.0, *ts.b(), -1.0);
    Teuchos::Array<double> norm(1);
    R.norm2(norm());
    return norm[0] / b_norm;
  };
  auto problem = rcp(new Belos::LinearProblem<double, MV, OP>(A, ts.x(), ts.b()));
  // Given as the right preconditioner: Belos' CG applies it to the residual either way (the same
  // iterates, bit for bit), but LinearProblem::setProblem applies a left one to the initial
  // residual for nothing, one V-cycle per solve (doc/performance.md).
  problem->setRightPrec(prec);
  problem->setProblem();
  auto belos = rcp(new Teuchos::ParameterList(settings.belos));
  belos->set("Convergence Tolerance", settings.tolerance);
  belos->set("Maximum Iterations", settings.max_iterations);
  Belos::PseudoBlockCGSolMgr<double, MV, OP> solver(problem, belos);
  for (int attempt = 0; attempt < 2; ++attempt) {
    try {
      core::ScopedTimer iterations(settings.density ? "fluid: density solve: iterations"
                                                    : "fluid: pressure solve: iterations");
      solver.solve();
    } catch (const Belos::BelosError& e) {
      // p^T A p <= 0 is a global reduction: every rank throws here alike
      breakdown = breakdown_message(settings.density, e.what());
      return false;
    }
    stats.iterations += solver.getNumIters();
    stats.relative_residual = true_residual();
    if (stats.relative_residual <= settings.tolerance) break;
    problem->setProblem();
    solver.reset(Belos::Problem);
  }
  return true;
}

/// Solves the rows with the kept Tpetra system `ts`, starting from x (one value per row), which
/// holds the solution on return. Throws SolverError when the tolerance is not reached.
SolveStats solve_rows(detail::TpetraSystem& ts, const grid::Decomposition& d,
                      const SolverSettings& settings, const detail::RowContributions& rows,
                      std::vector<double>& x, Interpreters& interpreters) {
  const auto t0 = std::chrono::steady_clock::now();
  SolveStats stats;
  if (!Tpetra::isInitialized())
    throw core::SolverError(
        "the pressure solver needs Tpetra initialised: create a fluid::LinearAlgebraScope in "
        "main()");
  const core::Comm& comm = d.comm();
  stats.unknowns =
      comm.sum(static_cast<long long>(rows.fixed ? rows.active.size() : rows.cells.size()));
  x.resize(rows.cells.size(), 0.0);
  double b2 = 0.0;
  for (double v : rows.rhs) b2 += v * v;
  const double b_norm = std::sqrt(comm.sum(b2));
  if (stats.unknowns == 0 || b_norm == 0.0) {
    std::fill(x.begin(), x.end(), 0.0);
    return stats;
  }
  // Fixed rows are solved where they are assembled: they move with the decomposition only.
  stats.reused_structure = ts.load(rows, x, d, settings.rebalance && !rows.fixed);
  const bool blocks = rows.with_solids && !rows.low_rank;  // dense blocks in the matrix
  const auto matrix_rows = static_cast<long long>(ts.matrix()->getGlobalNumRows());
  const RCP<OP> prec = preconditioner(ts, settings, blocks, matrix_rows, comm.size(), interpreters);
  stats.matrix_entries = ts.matrix_entries();
  stats.low_rank_entries = ts.low_rank_entries();
  stats.setup_seconds = seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  const MV x0(*ts.x(), Teuchos::Copy);  // the start, for a second attempt
  std::string breakdown;
  if (!run_cg(ts, prec, settings, b_norm, stats, breakdown)) {
    // CG's p^T A p <= 0 with a positive definite operator: the preconditioner is indefinite.
    // Chebyshev's largest-eigenvalue estimate missed the large eigenvalues of a light solid's
    // cut cells (doc/performance.md). With the low-rank operator (the assembled one has
    // solver/MueLu_solids already): once more from the same start, with it merged in.
    if (!rows.with_solids || blocks) throw core::SolverError(breakdown);
    ts.x()->assign(x0);
    const RCP<OP> safe = preconditioner(ts, settings, true, matrix_rows, comm.size(), interpreters);
    ++stats.preconditioner_retries;
    if (!run_cg(ts, safe, settings, b_norm, stats, breakdown)) throw core::SolverError(breakdown);
  }
  stats.solve_seconds = seconds_since(t1);
  x = ts.solution();
  if (!(stats.relative_residual <= settings.tolerance)) {
    std::ostringstream msg;
    msg << "pressure solve did not converge: relative true residual " << stats.relative_residual
        << " after " << stats.iterations << " iterations, solver/tolerance = " << settings.tolerance
        << " (solver/max_iterations = " << settings.max_iterations << ")";
    // stopped before the iteration limit: CG broke down or its residual drifted from the true one
    if (stats.iterations < settings.max_iterations)
      msg << "; CG stopped short of the iteration limit: " << singular_hint();
    throw core::SolverError(msg.str());
  }
  return stats;
}

}  // namespace

void check_solver_settings(const core::Params& params) {
  settings_from(params);
  settings_from(params, PressureSolver::Equation::DensityCorrection);
}

struct PressureSolver::Impl {
  const grid::Decomposition& d;
  grid::Halo halo;
  SolverSettings settings;
  std::unique_ptr<detail::CouplingTerm> term = detail::make_coupling_term();
  detail::RowContributions rows;  // buffers kept between solves
  grid::GridArray<int> row_of;
  detail::TpetraSystem system;
  Interpreters interpreters;
  // The rows of the last solve() with fixed rows (apply() takes and gives the fluid rows only).
  bool solved_fixed = false;
  std::size_t solved_rows = 0;
  std::vector<int> solved_active;
  // Fixed rows: the band of cells that are rows, chosen again when a fluid cell leaves it.
  grid::GridArray<signed char> band;
  bool band_chosen = false;
  Impl(const grid::Decomposition& dec, const core::Params& params, Equation eq)
      : d(dec),
        halo(dec),
        settings(settings_from(params, eq)),
        row_of(dec, grid::Stagger::Cell, -1),
        band(dec, grid::Stagger::Cell, 0) {}

  /// The band chosen again (every fluid cell and the cells within solver/structure_margin of
  /// one) when it is not chosen yet or a fluid cell has left it on any rank. Collective.
  void keep_band(const CellStates& cells) {
    bool out = !band_chosen;
    const core::IndexBox own = d.owned_cells();
    constexpr auto kFluid = static_cast<signed char>(grid::CellState::Fluid);
    for (int k = own.k0; k < own.k1 && !out; ++k)
      for (int i = own.i0; i < own.i1 && !out; ++i) out = cells(i, k) == kFluid && band(i, k) == 0;
    if (!d.comm().any(out)) return;
    core::ScopedTimer timer("fluid: pressure band");
    detail::choose_band(cells, settings.margin, band);
    halo.forward(band);
    band_chosen = true;
  }

  /// The fluid rows (-L_E, -D + source), then the coupling term's part, in the matrix or
  /// (low_rank) beside it.
  void assemble(const CellStates& cells, const Apertures& E, const grid::FaceField& u,
                const grid::FaceField& w, const std::vector<SolidCoupling>& couplings, double dt,
                const FluidConfig& cfg, const SurfaceFractions* surface,
                const grid::CellField* source, bool low_rank, bool fixed) {
    core::ScopedTimer timer("fluid: pressure assembly");
    if (fixed) keep_band(cells);
    detail::fluid_rows(cells, E, u, w, dt, cfg, surface, source, d, rows, row_of,
                       fixed ? &band : nullptr);
    rows.low_rank = low_rank;
    term->add(couplings, dt, cells, row_of, d, rows);
  }
};

PressureSolver::PressureSolver(const grid::Decomposition& d, const core::Params& params,
                               Equation eq)
    : impl_(std::make_unique<Impl>(d, params, eq)) {}
PressureSolver::~PressureSolver() = default;

AssembledSystem PressureSolver::assemble(const CellStates& cells, const Apertures& E,
                                         const grid::FaceField& u, const grid::FaceField& w,
                                         const std::vector<SolidCoupling>& couplings, double dt,
                                         const FluidConfig& cfg, const SurfaceFractions* surface,
                                         const grid::CellField* source) const {
  impl_->assemble(cells, E, u, w, couplings, dt, cfg, surface, source, false, false);
  return detail::assembled(impl_->rows);
}

SolveStats PressureSolver::solve(const CellStates& cells, const Apertures& E,
                                 const grid::FaceField& u, const grid::FaceField& w,
                                 const std::vector<SolidCoupling>& couplings, double dt,
                                 const FluidConfig& cfg, grid::CellField& p,
                                 const SurfaceFractions* surface, const grid::CellField* source) {
  const auto t0 = std::chrono::steady_clock::now();
  impl_->assemble(cells, E, u, w, couplings, dt, cfg, surface, source, impl_->settings.low_rank,
                  impl_->settings.fixed);
  const double assembly = seconds_since(t0);
  const auto& rows = impl_->rows;
  const grid::GridSpec& g = impl_->d.spec();
  auto cell_of = [&](std::size_t r) -> double& {
    return p(static_cast<int>(rows.cells[r] % g.nx), static_cast<int>(rows.cells[r] / g.nx));
  };
  // The initial guess: the previous pressure on the fluid rows, 0 on the identity rows (fixed).
  std::vector<double> x(rows.cells.size(), 0.0);
  if (rows.fixed)
    for (int r : rows.active) x[static_cast<std::size_t>(r)] = cell_of(static_cast<std::size_t>(r));
  else
    for (std::size_t r = 0; r < rows.cells.size(); ++r) x[r] = cell_of(r);
  SolveStats stats =
      solve_rows(impl_->system, impl_->d, impl_->settings, rows, x, impl_->interpreters);
  stats.setup_seconds += assembly;
  const core::IndexBox own = impl_->d.owned_cells();
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) p(i, k) = 0.0;
  impl_->solved_fixed = rows.fixed, impl_->solved_rows = rows.cells.size();
  if (rows.fixed) impl_->solved_active = rows.active;
  if (rows.fixed)
    for (int r : rows.active) cell_of(static_cast<std::size_t>(r)) = x[static_cast<std::size_t>(r)];
  else
    for (std::size_t r = 0; r < rows.cells.size(); ++r) cell_of(r) = x[r];
  impl_->halo.forward(p);
  return stats;
}

void PressureSolver::choose_rows_again() {
  impl_->band_chosen = false;
}

std::vector<double> PressureSolver::apply(const std::vector<double>& x) const {
  if (impl_->system.op().is_null())
    throw core::SolverError("PressureSolver::apply needs a solve() first");
  if (!impl_->solved_fixed) return impl_->system.apply(x);
  // Fixed rows: x and the result on the fluid rows only (the identity rows hold 0).
  const std::vector<int>& active = impl_->solved_active;
  std::vector<double> all(impl_->solved_rows, 0.0), y(active.size());
  for (std::size_t n = 0; n < active.size(); ++n)
    all[static_cast<std::size_t>(active[n])] = x.at(n);
  const std::vector<double> y_all = impl_->system.apply(all);
  for (std::size_t n = 0; n < active.size(); ++n) y[n] = y_all[static_cast<std::size_t>(active[n])];
  return y;
}

std::vector<core::SolidLoads> PressureSolver::solid_loads(const grid::CellField& p) const {
  return impl_->term->loads(p, impl_->d);
}

SolveStats solve_system(const grid::Decomposition& d, const core::Params& params,
                        const AssembledSystem& system, std::vector<double>& x) {
  detail::TpetraSystem ts;
  Interpreters interpreters;
  return solve_rows(ts, d, settings_from(params), detail::contributions(system), x, interpreters);
}

struct LinearAlgebraScope::Impl {
  Tpetra::ScopeGuard guard;
  Impl(int* argc, char*** argv) : guard(argc, argv) {}
};
LinearAlgebraScope::LinearAlgebraScope(int* argc, char*** argv)
    : impl_(std::make_unique<Impl>(argc, argv)) {}
LinearAlgebraScope::~LinearAlgebraScope() = default;

}  // namespace picdem::fluid
