// Rank-count invariance of the pressure step: the same dam-break state with a solid that
// straddles ranks, solved on all ranks and by rank 0 alone, gives the same pressure (to the
// solver tolerance) and the same loads on the solid. With the default solver settings for
// systems with solids (drop tol 0.02): on this system a 10-step Chebyshev eigenvalue estimate
// made the preconditioner indefinite (doc/performance.md).
#include <gtest/gtest.h>

#include <cmath>

#include "picdem/core/rng.hpp"
#include "picdem/fluid/pressure_solver.hpp"

using namespace picdem;
using namespace picdem::grid;

namespace {

constexpr signed char kAir = static_cast<signed char>(CellState::Air);
constexpr signed char kFluid = static_cast<signed char>(CellState::Fluid);

core::Params case_params() {
  core::ParamSchema schema;
  grid::declare_parameters(schema);
  fluid::declare_parameters(schema);
  return core::read_case_text("grid: {length: 1.0, height: 0.5, cell_size: 0.0125}\n", "rank test",
                              {"solver/tolerance=1e-11"}, schema);
}

struct Result {
  std::vector<double> p;  // every cell, gathered
  std::vector<core::SolidLoads> loads;
  int iterations = 0;
};

/// Dam-break state (fluid for x < 0.6 or z < 0.1, up to z = 0.4), random velocities plus
/// gravity, one solid cutting 20 cells around (0.4, 0.2) on `comm`.
Result run(const core::Comm& comm) {
  const auto params = case_params();
  const GridSpec s = spec_from(params);
  Decomposition d(s, comm, 1);
  Halo halo(d);
  const auto cfg = fluid::config_from(params);
  fluid::CellStates cells(d, Stagger::Cell, kAir);
  const auto& cb = cells.storage();
  for (int k = cb.k0; k < cb.k1; ++k)
    for (int i = cb.i0; i < cb.i1; ++i)
      if (i >= 0 && k >= 0 && i < s.nx && k < 32 && (i < 48 || k < 8)) cells(i, k) = kFluid;
  const auto E = fluid::open_apertures(d);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  for (FaceField* f : {&u, &w})
    for (int k = f->owned().k0; k < f->owned().k1; ++k)
      for (int i = f->owned().i0; i < f->owned().i1; ++i)
        (*f)(i, k) = 0.2 * (core::uniform01(5, f == &u, i, k) - 0.5);
  const double dt = 2e-3;
  fluid::apply_gravity(u, w, cells, dt, cfg);
  halo.forward(u), halo.forward(w);
  fluid::enforce_walls(u, w, cfg, d);
  // The solid's cut cells, each listed by the rank that owns it (partial lists joined by id).
  fluid::SolidCoupling solid;
  solid.id = 1, solid.mass = 0.5, solid.inertia = 2e-3, solid.v_star = {0.05, -0.3, 1.0};
  for (int n = 0; n < 20; ++n) {
    const int i = 22 + n, k = 16 + (n % 2);
    if (d.owner_of_cell(i, k) != comm.rank()) continue;
    solid.cells.push_back(s.cell_gid(i, k));
    const double phi = 0.6 * n;
    solid.a.push_back({0.01 * std::cos(phi), 0.01 * std::sin(phi), 1e-4 * (n - 9.5)});
  }
  const std::vector<fluid::SolidCoupling> couplings = {solid};
  CellField p(d, Stagger::Cell, 0.0);
  fluid::PressureSolver solver(d, params);
  Result r;
  r.iterations = solver.solve(cells, E, u, w, couplings, dt, cfg, p).iterations;
  r.loads = solver.solid_loads(p);
  r.p.assign(static_cast<std::size_t>(s.nx * s.nz), 0.0);
  const auto own = d.owned_cells();
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) r.p[static_cast<std::size_t>(s.cell_gid(i, k))] = p(i, k);
  comm.sum_in_place(r.p);
  return r;
}

}  // namespace

TEST(PressureRanks, AllRanksEqualOneRank) {
  core::Comm world;
  ASSERT_GT(world.size(), 1);
  const Result all = run(world);
  // The solid really straddles ranks in the parallel run.
  const auto s = spec_from(case_params());
  Decomposition d(s, world, 1);
  EXPECT_NE(d.owner_of_cell(22, 16), d.owner_of_cell(41, 17));
  if (world.rank() != 0) return;
  const Result one = run(core::Comm(MPI_COMM_SELF));
  double pmax = 0.0, diff = 0.0;
  for (std::size_t c = 0; c < one.p.size(); ++c) {
    pmax = std::max(pmax, std::abs(one.p[c]));
    diff = std::max(diff, std::abs(one.p[c] - all.p[c]));
  }
  EXPECT_GT(pmax, 100.0);
  EXPECT_LT(diff / pmax, 1e-8) << "iterations " << one.iterations << " vs " << all.iterations;
  ASSERT_EQ(one.loads.size(), 1u);
  ASSERT_EQ(all.loads.size(), 1u);
  const double fscale = std::hypot(one.loads[0].force.x, one.loads[0].force.z);
  EXPECT_GT(fscale, 0.0);
  EXPECT_NEAR(all.loads[0].force.x, one.loads[0].force.x, 1e-8 * fscale);
  EXPECT_NEAR(all.loads[0].force.z, one.loads[0].force.z, 1e-8 * fscale);
  EXPECT_NEAR(all.loads[0].torque, one.loads[0].torque, 1e-8 * fscale);
  std::printf("ranks %d: iterations %d (1 rank: %d), max |p_P - p_1| / max|p| = %.2e\n",
              world.size(), all.iterations, one.iterations, diff / pmax);
}
