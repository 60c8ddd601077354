// The assembled pressure matrix against hand computations: a 3x3 free-surface case with one
// half-open face, and a 8x4 case with one solid whose cut cells straddle ranks (eqs. 5-6,
// METHOD.md section 4). The coupled matrix stays symmetric positive definite.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "fluid_test_support.hpp"
#include "picdem/fluid/pressure_solver.hpp"

using namespace picdem;
using namespace picdem::grid;

namespace {

using fluid_test::kAir;
using fluid_test::kFluid;

using Rows = std::map<long long, std::map<long long, double>>;

void expect_rows(const fluid::AssembledSystem& sys, const Rows& expected, double tol) {
  ASSERT_EQ(sys.rows.size(), sys.entries.size());
  for (std::size_t r = 0; r < sys.rows.size(); ++r) {
    const auto it = expected.find(sys.rows[r]);
    if (it == expected.end()) continue;
    std::map<long long, double> got(sys.entries[r].begin(), sys.entries[r].end());
    EXPECT_EQ(got.size(), it->second.size()) << "row " << sys.rows[r];
    for (const auto& [c, v] : it->second) {
      ASSERT_TRUE(got.count(c)) << "row " << sys.rows[r] << " misses column " << c;
      EXPECT_NEAR(got[c], v, tol) << "row " << sys.rows[r] << " column " << c;
    }
  }
}

}  // namespace

// 3x3 cells, h = 0.1, rho = 1000, dt = 0.01 (so dt/(rho h) E = 1e-5 for an open face):
//   k=2:  A A A
//   k=1:  F F A        F = fluid, A = air; face between (0,0) and (1,0) half open (E = h/2)
//   k=0:  F F F
// Cell ids k*3 + i. The grid is too small to split, so rank 0 builds it alone.
TEST(PressureMatrix, ThreeByThreeByHand) {
  core::Comm world;
  if (world.rank() != 0) return;
  core::Comm self(MPI_COMM_SELF);
  const auto params = fluid_test::tank_params(0.4, 0.4, 0.1);
  GridSpec s;
  s.nx = 3, s.nz = 3, s.h = 0.1;
  Decomposition d(s, self, 1);
  fluid::CellStates cells(d, Stagger::Cell, kAir);
  for (auto [i, k] : {std::pair{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}}) cells(i, k) = kFluid;
  auto E = fluid::open_apertures(d);
  E.E_x(1, 0) = 0.05;
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  w(1, 1) = 0.2;  // between (1,0) and (1,1)
  u(2, 0) = 0.3;  // between (1,0) and (2,0)
  const auto cfg = fluid::config_from(params);
  fluid::PressureSolver solver(d, params);
  const auto sys = solver.assemble(cells, E, u, w, {}, 0.01, cfg);
  const Rows expected = {
      {0, {{0, 1.5e-5}, {1, -0.5e-5}, {3, -1e-5}}},
      {1, {{0, -0.5e-5}, {1, 2.5e-5}, {2, -1e-5}, {4, -1e-5}}},
      {2, {{1, -1e-5}, {2, 2e-5}}},
      {3, {{0, -1e-5}, {3, 3e-5}, {4, -1e-5}}},
      {4, {{1, -1e-5}, {3, -1e-5}, {4, 4e-5}}},
  };
  ASSERT_EQ(sys.rows, (std::vector<long long>{0, 1, 2, 3, 4}));
  expect_rows(sys, expected, 1e-20);
  // b = -D: D(1,0) = 0.1*0.2 + 0.1*0.3, D(2,0) = -0.1*0.3, D(1,1) = -0.1*0.2.
  const std::vector<double> b = {0.0, -0.05, 0.03, 0.0, 0.02};
  for (std::size_t r = 0; r < 5; ++r) EXPECT_NEAR(sys.rhs[r], b[r], 1e-16) << r;
  // A source adds its value on fluid rows only (the air cell (2,1) holds 7, ignored); the matrix
  // is unchanged.
  CellField source(d, Stagger::Cell, 0.0);
  source(1, 0) = 0.25, source(0, 1) = -0.5, source(2, 1) = 7.0;
  const auto with = solver.assemble(cells, E, u, w, {}, 0.01, cfg, nullptr, &source);
  const std::vector<double> b2 = {0.0, 0.2, 0.03, -0.5, 0.02};
  for (std::size_t r = 0; r < 5; ++r) EXPECT_NEAR(with.rhs[r], b2[r], 1e-16) << r;
  expect_rows(with, expected, 1e-20);
}

// 8x4 cells, h = 0.1, fluid in rows 0..2, air in row 3. One solid (m = 2, I = 0.01,
// V* = (0.1, -0.2, 0.5)) cuts cells 11 = (3,1), 12 = (4,1), 20 = (4,2) and the air cell
// 28 = (4,3) (ignored). Rank 0 lists cells 11 and 28, the last rank 12 and 20 (one rank: both
// lists): x = 3|4 is a rank boundary on 2 ranks, x = 2|5 on 3.
//   a_11 = (0.05, 0, 0.002), a_12 = (-0.05, 0, -0.001), a_20 = (0, -0.08, 0.003)
//   dt a_c . M^-1 a_c' (dt = 0.01):  (11,11) 1.65e-5, (11,12) -1.45e-5, (11,20) 6e-6,
//                                    (12,12) 1.35e-5, (12,20) -3e-6,   (20,20) 4.1e-5
//   b_c = a_c . V*: 0.006, -0.0055, 0.0175
TEST(PressureMatrix, SolidStraddlingRanksByHand) {
  core::Comm comm;
  const auto params = fluid_test::tank_params(0.8, 0.4, 0.1);
  const GridSpec s = spec_from(params);
  Decomposition d(s, comm, 1);
  fluid::CellStates cells(d, Stagger::Cell, kAir);
  const auto& b = cells.storage();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i)
      if (i >= 0 && i < s.nx && k >= 0 && k < 3) cells(i, k) = kFluid;
  const auto E = fluid::open_apertures(d);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  fluid::SolidCoupling part;
  part.id = 7, part.mass = 2.0, part.inertia = 0.01, part.v_star = {0.1, -0.2, 0.5};
  std::vector<fluid::SolidCoupling> mine;
  if (comm.rank() == 0) {
    auto p0 = part;
    p0.cells = {11, 28};
    p0.a = {{0.05, 0.0, 0.002}, {0.0, 0.02, 0.0}};
    mine.push_back(p0);
  }
  if (comm.rank() == comm.size() - 1) {
    auto p1 = part;
    p1.cells = {12, 20};
    p1.a = {{-0.05, 0.0, -0.001}, {0.0, -0.08, 0.003}};
    mine.push_back(p1);
  }
  const auto cfg = fluid::config_from(params);
  fluid::PressureSolver solver(d, params);
  const auto sys = solver.assemble(cells, E, u, w, mine, 0.01, cfg);
  const Rows coupled = {
      {11, {{3, -1e-5}, {10, -1e-5}, {11, 5.65e-5}, {12, -2.45e-5}, {19, -1e-5}, {20, 6e-6}}},
      {12, {{4, -1e-5}, {11, -2.45e-5}, {12, 5.35e-5}, {13, -1e-5}, {20, -1.3e-5}}},
      {20, {{11, 6e-6}, {12, -1.3e-5}, {19, -1e-5}, {20, 8.1e-5}, {21, -1e-5}}},
  };
  expect_rows(sys, coupled, 1e-19);
  int coupled_rows = 0;
  for (std::size_t r = 0; r < sys.rows.size(); ++r) {
    const long long c = sys.rows[r];
    if (c == 11) {
      EXPECT_NEAR(sys.rhs[r], 0.006, 1e-16);
      ++coupled_rows;
    }
    if (c == 12) {
      EXPECT_NEAR(sys.rhs[r], -0.0055, 1e-16);
      ++coupled_rows;
    }
    if (c == 20) {
      EXPECT_NEAR(sys.rhs[r], 0.0175, 1e-16);
      ++coupled_rows;
    }
    if (c != 11 && c != 12 && c != 20) {
      EXPECT_EQ(sys.rhs[r], 0.0);
    }
  }
  EXPECT_EQ(comm.sum(static_cast<long long>(coupled_rows)), 3);
  if (comm.size() == 2) {
    // The rows really straddle: cell 11 and cell 12 or 20 are owned by different ranks.
    EXPECT_NE(d.owner_of_cell(3, 1), d.owner_of_cell(4, 2));
  }

  // The whole matrix, gathered densely: symmetric and positive definite (Cholesky succeeds).
  const int n = s.nx * s.nz;
  std::vector<double> dense(static_cast<std::size_t>(n * n), 0.0);
  for (std::size_t r = 0; r < sys.rows.size(); ++r)
    for (const auto& [c, v] : sys.entries[r])
      dense[static_cast<std::size_t>(sys.rows[r] * n + c)] = v;
  comm.sum_in_place(dense);
  std::vector<int> fluid_ids;
  for (int c = 0; c < n; ++c)
    if (c / s.nx < 3) fluid_ids.push_back(c);
  const std::size_t m = fluid_ids.size();
  std::vector<double> A(m * m);
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t bb = 0; bb < m; ++bb) {
      A[a * m + bb] = dense[static_cast<std::size_t>(fluid_ids[a] * n + fluid_ids[bb])];
      EXPECT_NEAR(A[a * m + bb], dense[static_cast<std::size_t>(fluid_ids[bb] * n + fluid_ids[a])],
                  1e-20);
    }
  for (std::size_t j = 0; j < m; ++j) {
    double dj = A[j * m + j];
    for (std::size_t q = 0; q < j; ++q) dj -= A[j * m + q] * A[j * m + q];
    ASSERT_GT(dj, 0.0) << "not positive definite at pivot " << j;
    const double ljj = std::sqrt(dj);
    A[j * m + j] = ljj;
    for (std::size_t i = j + 1; i < m; ++i) {
      double v = A[i * m + j];
      for (std::size_t q = 0; q < j; ++q) v -= A[i * m + q] * A[j * m + q];
      A[i * m + j] = v / ljj;
    }
  }
}

// J_s p = -sum_c a_{s,c} p_c over the fluid cells, summed over ranks; the air cell's piece and
// pieces listed on other ranks are handled like in the assembly. With p = 1000 + cell id:
//   F_x = -(0.05 * 1011 - 0.05 * 1012) = 0.05,  F_z = -(-0.08 * 1020) = 81.6,
//   torque = -(0.002 * 1011 - 0.001 * 1012 + 0.003 * 1020) = -4.07
// plus the p-independent loads of the two lists, (1, 2, 3) + (0.5, 0, -1).
TEST(PressureLoads, MinusSumOfAPressureByHand) {
  core::Comm comm;
  const auto params = fluid_test::tank_params(0.8, 0.4, 0.1);
  const GridSpec s = spec_from(params);
  Decomposition d(s, comm, 1);
  fluid::CellStates cells(d, Stagger::Cell, kAir);
  CellField p(d, Stagger::Cell, 0.0);
  const auto& b = cells.storage();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i)
      if (i >= 0 && i < s.nx && k >= 0 && k < 3) {
        cells(i, k) = kFluid;
        p(i, k) = 1000.0 + s.cell_gid(i, k);
      }
  fluid::SolidCoupling part;
  part.id = 3, part.mass = 2.0, part.inertia = 0.01;
  std::vector<fluid::SolidCoupling> mine;
  if (comm.rank() == 0) {
    auto p0 = part;
    p0.cells = {11, 28};
    p0.a = {{0.05, 0.0, 0.002}, {0.0, 0.02, 0.0}};
    p0.load = {1.0, 2.0, 3.0};
    mine.push_back(p0);
  }
  if (comm.rank() == comm.size() - 1) {
    auto p1 = part;
    p1.cells = {12, 20};
    p1.a = {{-0.05, 0.0, -0.001}, {0.0, -0.08, 0.003}};
    p1.load = {0.5, 0.0, -1.0};
    mine.push_back(p1);
  }
  // The solver's loads use the rows it assembled (the step's path: PressureSolver::solid_loads).
  fluid::PressureSolver solver(d, params);
  const auto E = fluid::open_apertures(d);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  solver.assemble(cells, E, u, w, mine, 0.01, fluid::config_from(params));
  const auto loads = solver.solid_loads(p);
  ASSERT_EQ(loads.size(), 1u);
  EXPECT_EQ(loads[0].id, 3);
  EXPECT_NEAR(loads[0].force.x, 0.05 + 1.5, 1e-12);
  EXPECT_NEAR(loads[0].force.z, 81.6 + 2.0, 1e-12);
  EXPECT_NEAR(loads[0].torque, -4.07 + 2.0, 1e-12);
}
