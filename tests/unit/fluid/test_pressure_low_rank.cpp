// The solids' term kept out of the pressure matrix (solver/coupling_operator: low_rank, METHOD.md
// option (b)): the operator L_f + dt U M^-1 U^T applied to a vector equals the assembled matrix's
// product to round-off, and both solve to the same pressure and loads, on 1, 2 and 3 ranks with
// two solids, one straddling the ranks, sharing a cut cell, and the rows rebalanced over the
// ranks (the dam's fluid is uneven across the grid blocks, so rows and U's rows move). A kept
// solver gives a fresh solver's bits (restarts).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fluid_test_support.hpp"
#include "picdem/core/rng.hpp"
#include "picdem/fluid/pressure_solver.hpp"

using namespace picdem;
using namespace picdem::grid;

namespace {

using fluid_test::kAir;
using fluid_test::kFluid;

/// 80 x 40 cells of h = 0.0125: fluid for i < 48 or k < 8, up to k = 32; random velocities.
struct CoupledSystem : fluid_test::TankFields {
  core::Params assembled, low_rank;

  static core::Params params(const std::string& coupling_operator) {
    return fluid_test::tank_params(
        1.0, 0.5, 0.0125,
        {"solver/tolerance=1e-11", "solver/coupling_operator=" + coupling_operator});
  }

  explicit CoupledSystem(const core::Comm& comm)
      : TankFields(params("assembled"), comm),
        assembled(params("assembled")),
        low_rank(params("low_rank")) {
    const auto& cb = cells.storage();
    for (int k = cb.k0; k < cb.k1; ++k)
      for (int i = cb.i0; i < cb.i1; ++i)
        if (i >= 0 && k >= 0 && i < s.nx && k < 32 && (i < 48 || k < 8)) cells(i, k) = kFluid;
    random_velocities(9);
    // Solid 1 cuts (22..41, 16/17), across the rank boundary; solid 2 cuts (41..46, 17/18),
    // sharing cell (41, 17) with solid 1. Each cell listed by the rank that owns it.
    fluid::SolidCoupling one, two;
    one.id = 1, one.mass = 0.5, one.inertia = 2e-3, one.v_star = {0.05, -0.3, 1.0};
    two.id = 2, two.mass = 0.1, two.inertia = 5e-4, two.v_star = {-0.2, 0.1, -0.5};
    for (int n = 0; n < 20; ++n) {
      const int i = 22 + n, k = 16 + (n % 2);
      if (d.owner_of_cell(i, k) != comm.rank()) continue;
      one.cells.push_back(s.cell_gid(i, k));
      one.a.push_back({0.01 * std::cos(0.6 * n), 0.01 * std::sin(0.6 * n), 1e-4 * (n - 9.5)});
    }
    for (int n = 0; n < 6; ++n) {
      const int i = 41 + n, k = 17 + (n % 2);
      if (d.owner_of_cell(i, k) != comm.rank()) continue;
      two.cells.push_back(s.cell_gid(i, k));
      two.a.push_back({-0.004 * std::sin(n), 0.006 * std::cos(n), 3e-5 * (n - 2.5)});
    }
    solids = {one, two};
  }
};

/// Two solves' pressures agree to the solver's tolerance (1e-11): within 1e-8 of max |p| > 10 Pa.
void expect_same_pressure(const CellField& a, const CellField& b, const core::Comm& comm) {
  double p_max = 0.0, dp = 0.0;
  for (int k = a.owned().k0; k < a.owned().k1; ++k)
    for (int i = a.owned().i0; i < a.owned().i1; ++i)
      p_max = std::max(p_max, std::abs(a(i, k))), dp = std::max(dp, std::abs(a(i, k) - b(i, k)));
  p_max = comm.max(p_max), dp = comm.max(dp);
  EXPECT_GT(p_max, 10.0);
  EXPECT_LT(dp, 1e-8 * p_max);
}

}  // namespace

TEST(PressureLowRank, ApplyEqualsTheAssembledMatrixAndTheSolutionsAgree) {
  core::Comm comm;
  CoupledSystem t(comm);
  fluid::PressureSolver a(t.d, t.assembled), b(t.d, t.low_rank);
  CellField pa(t.d, Stagger::Cell, 0.0), pb(t.d, Stagger::Cell, 0.0);
  const double dt = 2e-3;
  const auto sa = a.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pa);
  const auto sb = b.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pb);
  // The matrix MueLu sees loses the blocks' off-diagonal entries; U has 3 per (solid, cell).
  EXPECT_EQ(sa.low_rank_entries, 0);
  EXPECT_EQ(sb.low_rank_entries, 3 * (20 + 6));
  EXPECT_LT(sb.matrix_entries, sa.matrix_entries);
  const auto sys = a.assemble(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg);
  // x on every cell (known to all ranks), and y = A x from the assembled rows by hand.
  std::vector<double> x_all(static_cast<std::size_t>(t.s.nx * t.s.nz), 0.0), x(sys.rows.size());
  for (std::size_t c = 0; c < x_all.size(); ++c)
    x_all[c] = std::sin(0.37 * static_cast<double>(c)) + 1e-3 * static_cast<double>(c);
  double y_max = 0.0, d_ref = 0.0, d_low = 0.0;
  for (std::size_t r = 0; r < sys.rows.size(); ++r)
    x[r] = x_all[static_cast<std::size_t>(sys.rows[r])];
  const auto y_assembled = a.apply(x), y_low = b.apply(x);
  ASSERT_EQ(y_assembled.size(), sys.rows.size());
  ASSERT_EQ(y_low.size(), sys.rows.size());
  for (std::size_t r = 0; r < sys.rows.size(); ++r) {
    double y = 0.0;
    for (const auto& [c, v] : sys.entries[r]) y += v * x_all[static_cast<std::size_t>(c)];
    y_max = std::max(y_max, std::abs(y));
    d_ref = std::max(d_ref, std::abs(y_assembled[r] - y));
    d_low = std::max(d_low, std::abs(y_low[r] - y_assembled[r]));
  }
  y_max = comm.max(y_max), d_ref = comm.max(d_ref), d_low = comm.max(d_low);
  EXPECT_GT(y_max, 1e-6);
  EXPECT_LT(d_ref, 1e-13 * y_max);
  EXPECT_LT(d_low, 1e-13 * y_max);
  // The same pressure and loads to the solver's tolerance.
  expect_same_pressure(pa, pb, comm);
  const auto la = a.solid_loads(pa), lb = b.solid_loads(pb);
  ASSERT_EQ(la.size(), 2u);
  ASSERT_EQ(lb.size(), 2u);
  for (std::size_t n = 0; n < 2; ++n) {
    const double f = std::hypot(la[n].force.x, la[n].force.z);
    EXPECT_GT(f, 0.0);
    EXPECT_NEAR(lb[n].force.x, la[n].force.x, 1e-8 * f);
    EXPECT_NEAR(lb[n].force.z, la[n].force.z, 1e-8 * f);
    EXPECT_NEAR(lb[n].torque, la[n].torque, 1e-8 * f);
  }
  if (comm.rank() == 0)
    std::printf(
        "ranks %d: CG iterations assembled %d, low rank %d; entries %lld vs %lld + U %lld\n",
        comm.size(), sa.iterations, sb.iterations, sa.matrix_entries, sb.matrix_entries,
        sb.low_rank_entries);
  if (comm.size() > 1) {
    EXPECT_NE(t.d.owner_of_cell(22, 16), t.d.owner_of_cell(41, 17));
  }
}

// A kept low-rank solver, solving again with other solid velocities (values only), gives the
// bits of a fresh solver: nothing but the system enters the solve (restarts stay bitwise).
TEST(PressureLowRank, KeptSolverGivesTheFreshSolversBits) {
  core::Comm comm;
  CoupledSystem t(comm);
  fluid::PressureSolver kept(t.d, t.low_rank);
  CellField p(t.d, Stagger::Cell, 0.0);
  kept.solve(t.cells, t.E, t.u, t.w, t.solids, 2e-3, t.cfg, p);
  for (auto& sc : t.solids) sc.v_star = {0.3, 0.2, -1.0};
  CellField p_fresh = p;
  const auto st = kept.solve(t.cells, t.E, t.u, t.w, t.solids, 2e-3, t.cfg, p);
  fluid::PressureSolver fresh(t.d, t.low_rank);
  const auto st_fresh = fresh.solve(t.cells, t.E, t.u, t.w, t.solids, 2e-3, t.cfg, p_fresh);
  EXPECT_TRUE(st.reused_structure);
  EXPECT_EQ(st.iterations, st_fresh.iterations);
  long long differ = 0;
  for (int k = p.owned().k0; k < p.owned().k1; ++k)
    for (int i = p.owned().i0; i < p.owned().i1; ++i) differ += p(i, k) != p_fresh(i, k) ? 1 : 0;
  EXPECT_EQ(comm.sum(differ), 0);
}

// A preconditioner made indefinite on purpose (Chebyshev built on a largest eigenvalue of D^-1 A
// far too small, as a short estimate can give next to a light solid's cut cells) breaks CG down;
// the solve is done again with solver/MueLu_solids merged (its own eigenvalue estimate) and
// reaches the pressure of the sound preconditioner.
TEST(PressureLowRank, BreakdownIsSolvedAgainWithTheSolidsList) {
  core::Comm comm;
  CoupledSystem t(comm);
  const auto bad = fluid_test::tank_params(
      1.0, 0.5, 0.0125,
      {"solver/tolerance=1e-11", "solver/coupling_operator=low_rank",
       "solver/MueLu={\"smoother: params\": {\"chebyshev: max eigenvalue\": 0.05}}",
       "solver/MueLu_solids={\"smoother: params\": {\"chebyshev: max eigenvalue\": 2.5}}"});
  fluid::PressureSolver sound(t.d, t.low_rank), retried(t.d, bad);
  CellField p(t.d, Stagger::Cell, 0.0), q(t.d, Stagger::Cell, 0.0);
  const double dt = 2e-3;
  const auto s0 = sound.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, p);
  const auto s1 = retried.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, q);
  EXPECT_EQ(s0.preconditioner_retries, 0);
  EXPECT_EQ(s1.preconditioner_retries, 1);
  expect_same_pressure(p, q, comm);
  if (comm.rank() == 0)
    std::printf("iterations: sound %d, after the breakdown %d\n", s0.iterations, s1.iterations);
}
