// solver/pressure_structure fixed (rows: a kept band of cells around the fluid, or with a margin
// as large as the grid every cell; identity rows for air and solid cells) against active (rows =
// fluid cells): the same pressure and solid loads to the solver's tolerance and the same operator
// to round-off on a tank with a sloping free surface, a block of solid cells and a coupled solid,
// on 1, 2 and 3 ranks; when the surface moves within the band the fixed system keeps its
// structure (values refilled only), beyond it the band is chosen again, and a kept solver gives
// a fresh solver's bits (restarts).
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
using fluid_test::kSolid;

/// 64 x 32 cells of h = 0.0125: water below a sloping surface (k < level - i / 8), a block of
/// solid cells (30..33, 0..3) in it, and one solid cutting cells (10..25, 12/13).
struct SurfaceTank : fluid_test::TankFields {
  core::Params active, fixed, whole;

  explicit SurfaceTank(const core::Comm& comm)
      : TankFields(params("active", 4), comm),
        active(params("active", 4)),
        fixed(params("fixed", 4)),
        whole(params("fixed", 64)) {
    set_level(22);
    random_velocities(5);
    fluid::SolidCoupling one;
    one.id = 7, one.mass = 0.3, one.inertia = 1e-3, one.v_star = {0.1, -0.2, 0.5};
    for (int n = 0; n < 32; ++n) {
      const int i = 10 + n / 2, k = 12 + (n % 2);
      if (d.owner_of_cell(i, k) != comm.rank()) continue;
      one.cells.push_back(s.cell_gid(i, k));
      one.a.push_back({0.01 * std::cos(0.4 * n), 0.01 * std::sin(0.4 * n), 1e-4 * (n - 15.5)});
    }
    solids = {one};
  }

  static core::Params params(const std::string& structure, int margin) {
    return fluid_test::tank_params(
        0.8, 0.4, 0.0125,
        {"solver/tolerance=1e-11", "solver/pressure_structure=" + structure,
         "solver/structure_margin=" + std::to_string(margin)});
  }

  /// Water below k = level - i / 8, the solid block, air elsewhere (halo included).
  void set_level(int level) {
    const auto& cb = cells.storage();
    for (int k = cb.k0; k < cb.k1; ++k)
      for (int i = cb.i0; i < cb.i1; ++i) {
        const bool inside = i >= 0 && k >= 0 && i < s.nx && k < s.nz;
        cells(i, k) = !inside                        ? kSolid
                      : (i >= 30 && i < 34 && k < 4) ? kSolid
                      : (k < level - i / 8)          ? kFluid
                                                     : kAir;
      }
  }
};

/// max |a - b| and max |a| over the owned cells of all ranks.
std::pair<double, double> max_difference(const core::Comm& comm, const CellField& a,
                                         const CellField& b) {
  double d = 0.0, m = 0.0;
  for (int k = a.owned().k0; k < a.owned().k1; ++k)
    for (int i = a.owned().i0; i < a.owned().i1; ++i)
      d = std::max(d, std::abs(a(i, k) - b(i, k))), m = std::max(m, std::abs(a(i, k)));
  return {comm.max(d), comm.max(m)};
}

}  // namespace

TEST(PressureStructure, FixedRowsGiveTheActiveRowsPressureLoadsAndOperator) {
  core::Comm comm;
  SurfaceTank t(comm);
  fluid::PressureSolver a(t.d, t.active), b(t.d, t.fixed), c(t.d, t.whole);
  CellField pa(t.d, Stagger::Cell, 0.0), pb(t.d, Stagger::Cell, 0.0), pc(t.d, Stagger::Cell, 0.0);
  const double dt = 2e-3;
  const auto sa = a.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pa);
  const auto sb = b.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pb);
  const auto sc = c.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pc);
  EXPECT_EQ(sb.unknowns, sa.unknowns);  // the fluid cells, not the rows
  EXPECT_EQ(sc.unknowns, sa.unknowns);
  EXPECT_LT(sa.unknowns, static_cast<long long>(t.s.nx) * t.s.nz);
  // The band's matrix holds more rows than the fluid's; the whole grid's every cell's 5-point
  // row (zeros included): 5 nx nz - 2 nx - 2 nz entries.
  EXPECT_GT(sb.matrix_entries, sa.matrix_entries);
  EXPECT_EQ(sc.matrix_entries, 5LL * t.s.nx * t.s.nz - 2LL * t.s.nx - 2LL * t.s.nz);
  EXPECT_LT(sb.matrix_entries, sc.matrix_entries);
  const auto [dp, p_max] = max_difference(comm, pa, pb);
  EXPECT_GT(p_max, 10.0);
  EXPECT_LT(dp, 1e-8 * p_max);
  EXPECT_LT(max_difference(comm, pa, pc).first, 1e-8 * p_max);
  long long nonzero_off_fluid = 0;
  for (int k = pb.owned().k0; k < pb.owned().k1; ++k)
    for (int i = pb.owned().i0; i < pb.owned().i1; ++i)
      nonzero_off_fluid += t.cells(i, k) != kFluid && pb(i, k) != 0.0 ? 1 : 0;
  EXPECT_EQ(comm.sum(nonzero_off_fluid), 0);
  const auto la = a.solid_loads(pa), lb = b.solid_loads(pb);
  ASSERT_EQ(la.size(), 1u);
  ASSERT_EQ(lb.size(), 1u);
  const double f = std::hypot(la[0].force.x, la[0].force.z);
  EXPECT_GT(f, 0.0);
  EXPECT_NEAR(lb[0].force.x, la[0].force.x, 1e-8 * f);
  EXPECT_NEAR(lb[0].force.z, la[0].force.z, 1e-8 * f);
  EXPECT_NEAR(lb[0].torque, la[0].torque, 1e-8 * f);
  // The operators on the fluid rows (apply takes and gives the fluid rows of either).
  const auto sys = a.assemble(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg);
  std::vector<double> x(sys.rows.size());
  for (std::size_t r = 0; r < x.size(); ++r)
    x[r] = std::sin(0.37 * static_cast<double>(sys.rows[r]));
  const auto ya = a.apply(x), yb = b.apply(x);
  ASSERT_EQ(ya.size(), x.size());
  ASSERT_EQ(yb.size(), x.size());
  double y_max = 0.0, dy = 0.0;
  for (std::size_t r = 0; r < x.size(); ++r)
    y_max = std::max(y_max, std::abs(ya[r])), dy = std::max(dy, std::abs(ya[r] - yb[r]));
  y_max = comm.max(y_max), dy = comm.max(dy);
  EXPECT_GT(y_max, 1e-6);
  EXPECT_LT(dy, 1e-13 * y_max);
  if (comm.rank() == 0)
    std::printf("ranks %d: CG iterations active %d, band %d, whole %d; entries %lld, %lld, %lld\n",
                comm.size(), sa.iterations, sb.iterations, sc.iterations, sa.matrix_entries,
                sb.matrix_entries, sc.matrix_entries);
}

// The surface drops by a cell: the active rows change (a new structure), the band and its
// structure are kept; both still agree. The rows then depend on when the band was chosen, so a
// restart (a fresh solver) gives the kept solver's bits only after choose_rows_again(), which the
// run calls where it writes a checkpoint; with it the kept solver rebuilds the fresh solver's
// structure and gives its bits.
TEST(PressureStructure, BandKeptAsTheSurfaceMovesAndBitwiseWithAFreshSolverAfterChoosingAgain) {
  core::Comm comm;
  SurfaceTank t(comm);
  fluid::PressureSolver a(t.d, t.active), b(t.d, t.fixed);
  CellField pa(t.d, Stagger::Cell, 0.0), pb(t.d, Stagger::Cell, 0.0);
  const double dt = 2e-3;
  a.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pa);
  const auto first = b.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pb);
  EXPECT_FALSE(first.reused_structure);
  t.set_level(21);
  const CellField p0 = pb;
  const auto sa = a.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pa);
  const auto sb = b.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pb);
  EXPECT_FALSE(sa.reused_structure);
  EXPECT_TRUE(sb.reused_structure);
  EXPECT_LT(sb.unknowns, first.unknowns);
  const auto [dp, p_max] = max_difference(comm, pa, pb);
  EXPECT_GT(p_max, 10.0);
  EXPECT_LT(dp, 1e-8 * p_max);
  // As at a checkpoint: both from p0, the kept solver after choose_rows_again(), a fresh one.
  CellField p_kept = p0, p_fresh = p0;
  b.choose_rows_again();
  const auto sk = b.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, p_kept);
  fluid::PressureSolver fresh(t.d, t.fixed);
  const auto sf = fresh.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, p_fresh);
  EXPECT_FALSE(sk.reused_structure);  // the band of the lower surface is smaller
  EXPECT_LT(sk.matrix_entries, sb.matrix_entries);
  EXPECT_EQ(sf.iterations, sk.iterations);
  const auto [differ, scale] = max_difference(comm, p_kept, p_fresh);
  EXPECT_GT(scale, 10.0);
  EXPECT_EQ(differ, 0.0);
}

// The surface rises by 6 cells, beyond the margin of 4: the band is chosen again (a new
// structure) and the pressure is still the active rows'; choose_rows_again() with the same fluid
// gives the same band, so the structure is kept.
TEST(PressureStructure, BandChosenAgainWhenTheFluidLeavesIt) {
  core::Comm comm;
  SurfaceTank t(comm);
  fluid::PressureSolver a(t.d, t.active), b(t.d, t.fixed);
  CellField pa(t.d, Stagger::Cell, 0.0), pb(t.d, Stagger::Cell, 0.0);
  const double dt = 2e-3;
  b.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pb);
  t.set_level(28);
  a.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pa);
  const auto moved = b.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pb);
  EXPECT_FALSE(moved.reused_structure);
  const auto [dp, p_max] = max_difference(comm, pa, pb);
  EXPECT_GT(p_max, 10.0);
  EXPECT_LT(dp, 1e-8 * p_max);
  b.choose_rows_again();
  const auto again = b.solve(t.cells, t.E, t.u, t.w, t.solids, dt, t.cfg, pb);
  EXPECT_TRUE(again.reused_structure);
  EXPECT_EQ(again.matrix_entries, moved.matrix_entries);
}
