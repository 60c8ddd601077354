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
// aggregation, its defaults). One of the few files that include Tpetra, Belos and MueLu.
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

namespace picdem::fluid {

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
  Teuchos::ParameterList muelu;
  muelu.set("verbosity", "none");
  RCP<OP> prec = MueLu::CreateTpetraPreconditioner(RCP<OP>(A), muelu);
  auto problem = rcp(new Belos::LinearProblem<double, MV, OP>(A, X, B));
  problem->setLeftPrec(prec);
  problem->setProblem();
  auto belos = rcp(new Teuchos::ParameterList());
  belos->set("Convergence Tolerance", tolerance);
  belos->set("Maximum Iterations", 1000);
  Belos::PseudoBlockCGSolMgr<double, MV, OP> solver(problem, belos);
  int iterations = 0;
  double res = 0.0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    solver.solve();
    iterations += solver.getNumIters();
    res = true_residual(*A, *X, *B);
    if (res <= tolerance) break;
    problem->setProblem();
    solver.reset(Belos::Problem);
  }
  if (!(res <= tolerance)) {
    std::ostringstream msg;
    msg << "implicit viscous solve did not converge: relative true residual " << res << " after "
        << iterations << " iterations";
    throw core::SolverError(msg.str());
  }
  auto x = X->getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t r = 0; r < n; ++r) u[static_cast<std::size_t>(s.node_of[r])] = x(r, 0);
  return iterations;
}

}  // namespace picdem::fluid
