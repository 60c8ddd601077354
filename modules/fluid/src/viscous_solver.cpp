// Implicit viscosity (viscous.hpp), the theta scheme for one velocity component
// (beta = 1 backward Euler, 1/2 Crank-Nicolson; theta below is a leg's boundary fraction; m_P the
// node's mass in units of rho h^2, 1 unless set_cut_node_masses gave the stencil its masses):
//   m_P (u_new - u_old) / dt = nu L (beta u_new + (1 - beta) u_old) + m_P f,
// multiplied by h^2 / nu (alpha = h^2 / (nu dt), 0 for the steady problem):
//   (alpha m_P + beta diag_P) u_P - beta sum_{interior legs} u_N
//     = m_P (alpha u_old,P + h^2 f_P / nu) + beta sum_{boundary legs} u_B / theta
//       + (1 - beta) h^2 (L u_old)_P,
// a symmetric positive definite matrix (an M-matrix, strictly diagonally dominant on rows with a
// boundary leg or alpha > 0), solved with Belos CG preconditioned with MueLu (smoothed
// aggregation), both given the viscous_solver/ lists of the case (declared here, with their
// defaults, and checked by Trilinos' validators). One of the few files that include Tpetra,
// Belos and MueLu.
#include <BelosLinearProblem.hpp>
#include <BelosPseudoBlockCGSolMgr.hpp>
#include <BelosTpetraAdapter.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/fluid/viscous.hpp"
#include "solver_sublists.hpp"

namespace picdem::fluid {

// Belos' own defaults for PseudoBlockCG (BelosPseudoBlockCGSolMgr.hpp), stated; MueLu's, silenced.
const char* const kViscousBelosDefaults =
    "\"Implicit Residual Scaling\": \"Norm of Initial Residual\"\n"
    "Verbosity: 0\n";
const char* const kViscousMueLuDefaults = "verbosity: none\n";

void declare_viscous_solver_parameters(core::ParamSchema& schema) {
  schema.section("viscous_solver",
                 "The implicit viscous solve (fluid/viscosity_scheme implicit or crank_nicolson): "
                 "Belos CG preconditioned by MueLu, one solve per velocity component.");
  schema
      .real("viscous_solver/tolerance", kViscousTolerance,
            "relative true residual ||b - A u|| / ||b|| to reach")
      .positive()
      .less_than(1.0);
  schema
      .integer("viscous_solver/max_iterations", kViscousMaxIterations,
               "CG iterations allowed per solve")
      .at_least(1);
  schema.passthrough("viscous_solver/Belos", kViscousBelosDefaults,
                     "settings handed to Belos::PseudoBlockCGSolMgr (tolerance and iteration limit "
                     "come from viscous_solver/tolerance and viscous_solver/max_iterations)");
  schema.passthrough("viscous_solver/MueLu", kViscousMueLuDefaults,
                     "settings handed to MueLu::CreateTpetraPreconditioner (no coordinates: "
                     "MueLu's defaults otherwise, smoothed aggregation)");
  // A viscosity no step can carry: the explicit limit h^2 / (4 nu) below time/dt_min, or an
  // implicit viscous number nu dt_max / h^2 above 1e12, where the system's mass term h^2 / (nu dt)
  // falls to round-off against its Laplacian and the solve returns noise (a mistyped value, or a
  // dynamic viscosity in Pa s where the key takes m^2/s).
  schema.check([](const core::Params& params, std::vector<std::string>& errors) {
    for (const char* key : {"grid/cell_size", "fluid/viscosity", "time/dt_max", "time/dt_min"})
      if (!params.has(key)) return;  // a schema without the fluid or the grid (unit tests)
    const double nu = params.real("fluid/viscosity"), h = params.real("grid/cell_size");
    if (!(nu > 0.0)) return;
    std::ostringstream e;
    if (params.string("fluid/viscosity_scheme") == "explicit") {
      if (viscous_time_step(h, nu) < params.real("time/dt_min"))
        e << "key 'fluid/viscosity' = " << nu << " m^2/s: the explicit scheme's stable step h^2 / "
          << "(4 nu) = " << viscous_time_step(h, nu)
          << " s is below time/dt_min = " << params.real("time/dt_min")
          << " s; allowed: nu <= h^2 / (4 dt_min) = " << h * h / (4.0 * params.real("time/dt_min"))
          << " m^2/s, or fluid/viscosity_scheme implicit";
    } else if (nu * params.real("time/dt_max") / (h * h) > 1e12) {
      e << "key 'fluid/viscosity' = " << nu << " m^2/s: the viscous number nu dt / h^2 at "
        << "time/dt_max is " << nu * params.real("time/dt_max") / (h * h)
        << ", beyond which the implicit solve's mass term is lost to round-off; allowed: "
        << "nu time/dt_max / grid/cell_size^2 <= 1e12 (is the viscosity in m^2/s?)";
    }
    if (!e.str().empty()) errors.push_back(e.str());
  });
}

ViscousSolverSettings viscous_solver_settings_from(const core::Params& params) {
  ViscousSolverSettings s;
  s.tolerance = params.real("viscous_solver/tolerance");
  s.max_iterations = static_cast<int>(params.integer("viscous_solver/max_iterations"));
  auto belos = std::make_shared<Teuchos::ParameterList>(params.teuchos("viscous_solver/Belos"));
  auto muelu = std::make_shared<Teuchos::ParameterList>(params.teuchos("viscous_solver/MueLu"));
  detail::check_muelu_list("viscous_solver/MueLu", *muelu);
  try {
    Belos::PseudoBlockCGSolMgr<double, Tpetra::MultiVector<>, Tpetra::Operator<>> cg;
    belos->validateParameters(*cg.getValidParameters(), 0);
  } catch (const std::exception& e) {
    throw core::InputError(std::string("viscous_solver/Belos: Belos rejected the settings: ") +
                           e.what());
  }
  s.belos = std::move(belos);
  s.muelu = std::move(muelu);
  return s;
}

namespace {

using Teuchos::RCP;
using Teuchos::rcp;
using Map = Tpetra::Map<>;
using Matrix = Tpetra::CrsMatrix<>;
using MV = Tpetra::MultiVector<>;
using OP = Tpetra::Operator<>;
using GO = Map::global_ordinal_type;

/// Unknown r's mass in units of rho h^2 (1 without cut-node masses).
double mass_of(const ViscousStencil& s, std::size_t r) {
  return s.mass.empty() ? 1.0 : s.mass[r];
}

/// The matrix alpha M + beta A of the stencil on a map of all unknowns (this rank alone).
RCP<Matrix> assemble(const ViscousStencil& s, double alpha, double beta,
                     const RCP<const Map>& map) {
  auto A = rcp(new Matrix(map, 5));
  for (std::size_t r = 0; r < s.node_of.size(); ++r) {
    Teuchos::Array<GO> cols;
    Teuchos::Array<double> vals;
    cols.push_back(static_cast<GO>(r));
    vals.push_back(alpha * mass_of(s, r) + beta * s.diag[r]);
    for (int rn : s.neighbours[r])
      if (rn >= 0) {
        cols.push_back(static_cast<GO>(rn));
        vals.push_back(-beta);
      }
    A->insertGlobalValues(static_cast<GO>(r), cols(), vals());
  }
  A->fillComplete();
  return A;
}

/// The declared default of viscous_solver/Belos (`belos`) or viscous_solver/MueLu, read once.
const Teuchos::ParameterList& declared_default(bool belos) {
  static const auto b = core::parse_yaml(kViscousBelosDefaults, "default of viscous_solver/Belos");
  static const auto m = core::parse_yaml(kViscousMueLuDefaults, "default of viscous_solver/MueLu");
  return belos ? *b : *m;
}

double true_residual(const Matrix& A, const MV& X, const MV& B) {
  MV R(A.getRangeMap(), 1);
  A.apply(X, R);
  R.update(1.0, B, -1.0);
  Teuchos::Array<double> rn(1), bn(1);
  R.norm2(rn());
  B.norm2(bn());
  return bn[0] > 0.0 ? rn[0] / bn[0] : rn[0];
}

}  // namespace

int solve_viscous_implicit(const ViscousStencil& s, double nu, double dt,
                           const std::vector<double>& f, std::vector<double>& u, double tolerance,
                           double beta) {
  ViscousSolverSettings solver;
  solver.tolerance = tolerance;
  return solve_viscous_implicit(s, nu, dt, f, u, solver, beta);
}

int solve_viscous_implicit(const ViscousStencil& s, double nu, double dt,
                           const std::vector<double>& f, std::vector<double>& u,
                           const ViscousSolverSettings& solver, double beta) {
  if (!Tpetra::isInitialized())
    throw core::SolverError(
        "the implicit viscous solve needs Tpetra initialised: create a fluid::LinearAlgebraScope");
  if (!(nu > 0.0) || !(dt > 0.0))
    throw core::InputError("implicit viscosity needs nu > 0 and dt > 0");
  if (!(beta >= 0.5 && beta <= 1.0))
    throw core::InputError("implicit viscosity needs beta in [1/2, 1]");
  if (std::isinf(dt)) beta = 1.0;  // the steady problem
  const std::size_t n = s.node_of.size();
  if (n == 0) return 0;
  const double h2 = s.h * s.h;
  const double alpha = std::isinf(dt) ? 0.0 : h2 / (nu * dt);
  RCP<const Teuchos::Comm<int>> comm = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  auto map = rcp(new Map(static_cast<Tpetra::global_size_t>(n), 0, comm));
  RCP<Matrix> A = assemble(s, alpha, beta, map);
  const std::vector<double> lap_old =
      beta < 1.0 ? apply_viscous_operator(s, u) : std::vector<double>();
  auto X = rcp(new MV(map, 1)), B = rcp(new MV(map, 1));
  {
    auto x = X->getLocalViewHost(Tpetra::Access::OverwriteAll);
    auto b = B->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t r = 0; r < n; ++r) {
      const auto node = static_cast<std::size_t>(s.node_of[r]);
      x(r, 0) = u[node];
      b(r, 0) = mass_of(s, r) * (alpha * u[node] + h2 * f[node] / nu);
      if (beta < 1.0) b(r, 0) += (1.0 - beta) * h2 * lap_old[node];
    }
    for (const ViscousLeg& leg : s.legs)
      b(static_cast<std::size_t>(leg.unknown), 0) += beta * leg.weight * leg.value;
  }
  Teuchos::ParameterList muelu = solver.muelu ? *solver.muelu : declared_default(false);
  RCP<OP> prec = MueLu::CreateTpetraPreconditioner(RCP<OP>(A), muelu);
  auto problem = rcp(new Belos::LinearProblem<double, MV, OP>(A, X, B));
  // Given as the right preconditioner, as the pressure solve does: Belos' CG applies it to the
  // residual either way, but with a left one setProblem also applied it to the initial residual.
  problem->setRightPrec(prec);
  problem->setProblem();
  auto belos =
      rcp(new Teuchos::ParameterList(solver.belos ? *solver.belos : declared_default(true)));
  belos->set("Convergence Tolerance", solver.tolerance);
  belos->set("Maximum Iterations", solver.max_iterations);
  Belos::PseudoBlockCGSolMgr<double, MV, OP> cg(problem, belos);
  int iterations = 0;
  double res = 0.0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    cg.solve();
    iterations += cg.getNumIters();
    res = true_residual(*A, *X, *B);
    if (res <= solver.tolerance) break;
    problem->setProblem();
    cg.reset(Belos::Problem);
  }
  if (!(res <= solver.tolerance)) {
    std::ostringstream msg;
    msg << "implicit viscous solve did not converge: relative true residual " << res << " after "
        << iterations << " iterations, viscous_solver/tolerance = " << solver.tolerance
        << " (viscous_solver/max_iterations = " << solver.max_iterations << ")";
    // the mass term h^2 / (nu dt) lost to round-off against the Laplacian: nearly singular
    if (alpha < 1e-8)
      msg << "; the viscous number nu dt / h^2 = " << 1.0 / alpha << " (fluid/viscosity = " << nu
          << " m^2/s, dt = " << dt << " s, h = " << s.h
          << " m) leaves the system nearly singular: is fluid/viscosity in m^2/s?";
    throw core::SolverError(msg.str());
  }
  auto x = X->getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t r = 0; r < n; ++r) u[static_cast<std::size_t>(s.node_of[r])] = x(r, 0);
  return iterations;
}

}  // namespace picdem::fluid
