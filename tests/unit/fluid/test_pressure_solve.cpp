// Belos CG + MueLu on the pressure matrix, on 1, 2 and 3 ranks (the 2-rank run guards against
// MueLu's coarse-solver trap, TOOLCHAIN.md): a manufactured solution reaches the tolerance by
// the true residual ||b - A x|| / ||b|| computed here with a halo exchange, not by Belos; the
// projection leaves divergence below 1e-10 |u|/h in every fluid cell; still water gets the
// hydrostatic pressure and stays at rest.
#include <gtest/gtest.h>

#include <cmath>

#include "fluid_test_support.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/rng.hpp"
#include "picdem/fluid/pressure_solver.hpp"

using namespace picdem;
using namespace picdem::grid;

namespace {

using fluid_test::kAir;
using fluid_test::kFluid;
using fluid_test::kSolid;

/// Dam-break-like column: fluid for i < nx/2 and k < 3 nz/4 (and a thin layer on the rest of
/// the floor), air elsewhere; halo filled too.
fluid::CellStates dam(const Decomposition& d) {
  const int nx = d.spec().nx, nz = d.spec().nz;
  fluid::CellStates c(d, Stagger::Cell, kAir);
  const auto& b = c.storage();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i)
      if (i >= 0 && i < nx && k >= 0 && k < nz && ((i < nx / 2 && k < 3 * nz / 4) || k < nz / 8))
        c(i, k) = kFluid;
  return c;
}

}  // namespace

TEST(PressureSolve, ManufacturedSolutionReachesToleranceByTrueResidual) {
  core::Comm comm;
  const auto params = fluid_test::tank_params(1.0, 1.0, 1.0 / 96);
  const GridSpec s = spec_from(params);
  Decomposition d(s, comm, 1);
  Halo halo(d);
  const auto cells = dam(d);
  const auto E = fluid::open_apertures(d);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  const auto cfg = fluid::config_from(params);
  fluid::PressureSolver solver(d, params);
  auto sys = solver.assemble(cells, E, u, w, {}, 1e-3, cfg);
  // x* = smooth field of the cell centre; b = A x* from the assembled rows.
  auto exact = [&](long long gid) {
    const Vec2 p =
        s.position(Stagger::Cell, static_cast<int>(gid % s.nx), static_cast<int>(gid / s.nx));
    return 1000.0 * std::cos(3.0 * p.x) * (1.0 - p.z) + 50.0 * p.x * p.z;
  };
  for (std::size_t r = 0; r < sys.rows.size(); ++r) {
    sys.rhs[r] = 0.0;
    for (const auto& [c, v] : sys.entries[r]) sys.rhs[r] += v * exact(c);
  }
  std::vector<double> x(sys.rows.size(), 0.0);
  const auto stats = fluid::solve_system(d, params, sys, x);
  EXPECT_EQ(stats.unknowns, 96LL * 72 / 2 + 96LL * 12 / 2);
  EXPECT_LE(stats.iterations, 25);

  // Independent true residual: x into a cell field, halo forwarded, 5-point rows applied.
  CellField p(d, Stagger::Cell, 0.0);
  for (std::size_t r = 0; r < sys.rows.size(); ++r)
    p(static_cast<int>(sys.rows[r] % s.nx), static_cast<int>(sys.rows[r] / s.nx)) = x[r];
  halo.forward(p);
  double r2 = 0.0, b2 = 0.0, e2 = 0.0, x2 = 0.0;
  for (std::size_t r = 0; r < sys.rows.size(); ++r) {
    double ax = 0.0;
    for (const auto& [c, v] : sys.entries[r])
      ax += v * p(static_cast<int>(c % s.nx), static_cast<int>(c / s.nx));
    r2 += (sys.rhs[r] - ax) * (sys.rhs[r] - ax);
    b2 += sys.rhs[r] * sys.rhs[r];
    e2 += (x[r] - exact(sys.rows[r])) * (x[r] - exact(sys.rows[r]));
    x2 += exact(sys.rows[r]) * exact(sys.rows[r]);
  }
  const double rel = std::sqrt(comm.sum(r2) / comm.sum(b2));
  EXPECT_LT(rel, 1e-8);
  EXPECT_NEAR(rel, stats.relative_residual, 1e-12);
  EXPECT_LT(std::sqrt(comm.sum(e2) / comm.sum(x2)), 1e-4);
  if (comm.is_root())
    std::printf("manufactured 96^2 dam: %lld unknowns, %d iterations, residual %.2e\n",
                stats.unknowns, stats.iterations, rel);
}

TEST(PressureSolve, ProjectionLeavesNoDivergence) {
  core::Comm comm;
  const auto params = fluid_test::tank_params(1.0, 1.0, 1.0 / 32, {"solver/tolerance=1e-11"});
  const GridSpec s = spec_from(params);
  Decomposition d(s, comm, 1);
  Halo halo(d);
  // Fluid below k = 20 around a solid block [10,14) x [5,9); air above.
  fluid::CellStates cells(d, Stagger::Cell, kAir);
  const auto& cb = cells.storage();
  for (int k = cb.k0; k < cb.k1; ++k)
    for (int i = cb.i0; i < cb.i1; ++i) {
      if (i < 0 || i >= s.nx || k < 0 || k >= s.nz) continue;
      if (i >= 10 && i < 14 && k >= 5 && k < 9)
        cells(i, k) = kSolid;
      else if (k < 20)
        cells(i, k) = kFluid;
    }
  auto E = fluid::open_apertures(d);
  for (int k = E.E_x.storage().k0; k < E.E_x.storage().k1; ++k)
    for (int i = E.E_x.storage().i0; i < E.E_x.storage().i1; ++i)
      if ((i >= 10 && i <= 14) && k >= 5 && k < 9) E.E_x(i, k) = 0.0;
  for (int k = E.E_z.storage().k0; k < E.E_z.storage().k1; ++k)
    for (int i = E.E_z.storage().i0; i < E.E_z.storage().i1; ++i)
      if (i >= 10 && i < 14 && k >= 5 && k <= 9) E.E_z(i, k) = 0.0;
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  for (FaceField* f : {&u, &w}) {
    const int tag = f == &u ? 1 : 2;
    for (int k = f->owned().k0; k < f->owned().k1; ++k)
      for (int i = f->owned().i0; i < f->owned().i1; ++i)
        (*f)(i, k) = core::uniform01(42, tag, i + 10, k + 10) - 0.5;
  }
  const auto cfg = fluid::config_from(params);
  fluid::apply_gravity(u, w, cells, 0.01, cfg);
  halo.forward(u), halo.forward(w);
  fluid::enforce_walls(u, w, cfg, d);
  double umax = 0.0;
  for (const FaceField* f : {&u, &w})
    for (int k = f->owned().k0; k < f->owned().k1; ++k)
      for (int i = f->owned().i0; i < f->owned().i1; ++i)
        umax = std::max(umax, std::abs((*f)(i, k)));
  umax = comm.max(umax);

  CellField D(d, Stagger::Cell, 0.0), p(d, Stagger::Cell, 0.0);
  fluid::divergence(u, w, E, cells, D);
  double before = 0.0;
  for (double v : D.data()) before = std::max(before, std::abs(v));
  EXPECT_GT(comm.max(before) / (s.h * umax), 0.1);  // the field starts far from solenoidal

  fluid::PressureSolver solver(d, params);
  const auto stats = solver.solve(cells, E, u, w, {}, 0.01, cfg, p);
  fluid::project(u, w, p, cells, E, 0.01, cfg);
  halo.forward(u), halo.forward(w);
  fluid::divergence(u, w, E, cells, D);
  double after = 0.0;
  for (int k = D.owned().k0; k < D.owned().k1; ++k)
    for (int i = D.owned().i0; i < D.owned().i1; ++i)
      if (cells(i, k) == kFluid) after = std::max(after, std::abs(D(i, k)));
  after = comm.max(after) / (s.h * umax);
  EXPECT_LT(after, 1e-10) << "after " << stats.iterations << " iterations";
  // Solid and air cells hold p = 0; the halo was forwarded.
  for (int k = cb.k0; k < cb.k1; ++k)
    for (int i = cb.i0; i < cb.i1; ++i)
      if (cells.owned().contains(i, k) && cells(i, k) != kFluid) {
        EXPECT_EQ(p(i, k), 0.0);
      }
  if (comm.is_root())
    std::printf("projection 32^2: max |D| / (h |u|) = %.2e after %d iterations\n", after,
                stats.iterations);
}

// Still water 20 cells deep: gravity + solve + project gives p = rho g h (20 - k) (p = 0 at
// the centre of the air cells above) and w = 0 on every face.
TEST(PressureSolve, StillWaterIsHydrostaticAndStaysAtRest) {
  core::Comm comm;
  const auto params = fluid_test::tank_params(0.64, 0.32, 0.01, {"solver/tolerance=1e-12"});
  const GridSpec s = spec_from(params);
  Decomposition d(s, comm, 1);
  Halo halo(d);
  fluid::CellStates cells(d, Stagger::Cell, kAir);
  const auto& cb = cells.storage();
  for (int k = cb.k0; k < cb.k1; ++k)
    for (int i = cb.i0; i < cb.i1; ++i)
      if (i >= 0 && i < s.nx && k >= 0 && k < 20) cells(i, k) = kFluid;
  const auto E = fluid::open_apertures(d);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  const auto cfg = fluid::config_from(params);
  const double dt = 0.005;
  fluid::apply_gravity(u, w, cells, dt, cfg);
  halo.forward(u), halo.forward(w);
  fluid::enforce_walls(u, w, cfg, d);
  CellField p(d, Stagger::Cell, 0.0);
  fluid::PressureSolver solver(d, params);
  solver.solve(cells, E, u, w, {}, dt, cfg, p);
  fluid::project(u, w, p, cells, E, dt, cfg);
  double perr = 0.0, wmax = 0.0;
  for (int k = cells.owned().k0; k < cells.owned().k1; ++k)
    for (int i = cells.owned().i0; i < cells.owned().i1; ++i)
      if (k < 20) perr = std::max(perr, std::abs(p(i, k) / (1000.0 * 9.81 * 0.01 * (20 - k)) - 1));
  for (int k = w.owned().k0; k < w.owned().k1; ++k)
    for (int i = w.owned().i0; i < w.owned().i1; ++i)
      if (k <= 20) wmax = std::max(wmax, std::abs(w(i, k)));
  EXPECT_LT(comm.max(perr), 1e-9);
  EXPECT_LT(comm.max(wmax), 1e-9 * 9.81 * dt);
}

TEST(PressureSolve, RejectedMueLuSettingsNameTheKey) {
  core::Comm comm;
  const auto params = fluid_test::tank_params(
      1.0, 1.0, 1.0 / 64,
      {"solver/MueLu={\"smoother: type\": RELAXATION, \"smoother: params\": {\"bogus\": 1}}"});
  const GridSpec s = spec_from(params);
  Decomposition d(s, comm, 1);
  const auto cells = dam(d);
  const auto E = fluid::open_apertures(d);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  const auto cfg = fluid::config_from(params);
  fluid::apply_gravity(u, w, cells, 0.01, cfg);
  Halo(d).forward(w);
  fluid::enforce_walls(u, w, cfg, d);
  CellField p(d, Stagger::Cell, 0.0);
  // Refused when the solver reads its settings, before any hierarchy is built (Ifpack2's
  // RELAXATION validates its keys), with the key's full path.
  try {
    fluid::PressureSolver solver(d, params);
    solver.solve(cells, E, u, w, {}, 0.01, cfg, p);
    ADD_FAILURE() << "bad MueLu key accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("key 'solver/MueLu/smoother: params/bogus' = 1 is not "
                                         "allowed: Ifpack2's RELAXATION smoother rejects it"),
              std::string::npos)
        << e.what();
  }
}

// The Tpetra structure is kept while the mask and the coupled cells are unchanged: a solve with
// other velocities and solid velocity (values only) reuses it and gives bitwise the pressure of a
// fresh solver from the same initial guess; a changed mask rebuilds it, again bitwise equal to a
// fresh solver. This is what keeps restarts bitwise (a restarted run starts with a fresh solver).
TEST(PressureSolve, KeptStructureGivesTheFreshSolversBits) {
  core::Comm comm;
  const auto params = fluid_test::tank_params(1.0, 1.0, 1.0 / 48);
  const GridSpec s = spec_from(params);
  Decomposition d(s, comm, 1);
  Halo halo(d);
  auto cells = dam(d);
  const auto E = fluid::open_apertures(d);
  const auto cfg = fluid::config_from(params);
  auto velocities = [&](int seed, FaceField& u, FaceField& w) {
    for (FaceField* f : {&u, &w})
      for (int k = f->owned().k0; k < f->owned().k1; ++k)
        for (int i = f->owned().i0; i < f->owned().i1; ++i)
          (*f)(i, k) = 0.1 * (core::uniform01(seed, f == &u, i, k) - 0.5);
    fluid::apply_gravity(u, w, cells, 0.01, cfg);
    halo.forward(u), halo.forward(w);
    fluid::enforce_walls(u, w, cfg, d);
  };
  // A solid cutting cells (10..19, 12), each listed by its owner.
  fluid::SolidCoupling solid;
  solid.id = 4, solid.mass = 0.3, solid.inertia = 1e-3;
  for (int n = 0; n < 10; ++n)
    if (d.owned_cells().contains(10 + n, 12)) {
      solid.cells.push_back(s.cell_gid(10 + n, 12));
      solid.a.push_back({0.01 * std::cos(0.7 * n), 0.01 * std::sin(0.7 * n), 1e-4 * (n - 4.5)});
    }
  auto same_bits = [&](const CellField& a, const CellField& b) {
    long long differ = 0;
    for (int k = a.owned().k0; k < a.owned().k1; ++k)
      for (int i = a.owned().i0; i < a.owned().i1; ++i) differ += a(i, k) != b(i, k) ? 1 : 0;
    return comm.sum(differ) == 0;
  };
  fluid::PressureSolver kept(d, params);
  CellField p(d, Stagger::Cell, 0.0);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  velocities(1, u, w);
  solid.v_star = {0.1, -0.2, 0.3};
  EXPECT_FALSE(kept.solve(cells, E, u, w, {solid}, 0.01, cfg, p).reused_structure);
  for (int round = 0; round < 2; ++round) {
    if (round == 1) {  // the mask changes: one more fluid cell above the column
      const int i = 3, k = 3 * s.nz / 4;
      if (cells.in_storage(i, k)) cells(i, k) = static_cast<signed char>(CellState::Fluid);
    }
    velocities(2 + round, u, w);
    solid.v_star = {-0.1, 0.05 * round, 1.0};
    CellField p_fresh = p;
    const auto st = kept.solve(cells, E, u, w, {solid}, 0.01, cfg, p);
    EXPECT_EQ(st.reused_structure, round == 0);
    fluid::PressureSolver fresh(d, params);
    const auto st_fresh = fresh.solve(cells, E, u, w, {solid}, 0.01, cfg, p_fresh);
    EXPECT_FALSE(st_fresh.reused_structure);
    EXPECT_EQ(st.iterations, st_fresh.iterations);
    EXPECT_TRUE(same_bits(p, p_fresh)) << "round " << round;
  }
}

// Trilinos' lists of valid parameters check the case's solver lists when the solver is built:
// a misspelt MueLu or Belos key is an InputError naming the case key and the misspelt name.
TEST(PressureSolve, UnknownSolverKeysAreRejectedByTrilinosValidators) {
  core::Comm comm;
  const GridSpec s = spec_from(fluid_test::tank_params(1.0, 1.0, 1.0 / 16));
  Decomposition d(s, comm, 1);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"solver/MueLu={\"smoother: tpye\": CHEBYSHEV}", "smoother: tpye"},
      {"solver/MueLu_solids={\"aggregation: drop tolerance\": 0.02}",
       "aggregation: drop tolerance"},
      {"solver/MueLu={\"coarse: max size\": 800.5}", "coarse: max size"},
      {"solver/Belos={\"Verbosty\": 0}", "Verbosty"}};
  for (const auto& [setting, name] : bad) {
    const auto params = fluid_test::tank_params(1.0, 1.0, 1.0 / 16, {setting});
    const std::string key = setting.substr(0, setting.find('='));
    try {
      fluid::PressureSolver solver(d, params);
      ADD_FAILURE() << setting << " accepted";
    } catch (const core::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key + ":"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
  // The declared defaults pass.
  EXPECT_NO_THROW(fluid::PressureSolver(d, fluid_test::tank_params(1.0, 1.0, 1.0 / 16)));
}

// Sub-cell free surface at z_s = 20.3 h (level set phi = z - z_s): the ghost-fluid Dirichlet
// condition makes the hydrostatic pressure exact at every cell centre, p = rho g (z_s - z_c),
// including the top fluid row (theta = 0.8), and the projected water stays at rest.
TEST(PressureSolve, SubCellSurfaceIsHydrostaticAtTheTrueSurface) {
  core::Comm comm;
  const auto params = fluid_test::tank_params(0.64, 0.32, 0.01, {"solver/tolerance=1e-12"});
  const GridSpec s = spec_from(params);
  Decomposition d(s, comm, 1);
  Halo halo(d);
  const double zs = 20.3 * s.h;
  fluid::CellStates cells(d, Stagger::Cell, kAir);
  CellField phi(d, Stagger::Cell, 1.0);
  const auto& cb = cells.storage();
  for (int k = cb.k0; k < cb.k1; ++k)
    for (int i = cb.i0; i < cb.i1; ++i) {
      phi(i, k) = s.position(Stagger::Cell, i, k).z - zs;
      if (i >= 0 && i < s.nx && k >= 0 && phi(i, k) < 0.0) cells(i, k) = kFluid;
    }
  const auto surface = fluid::surface_fractions(phi, cells, d);
  if (surface.theta_z.owned().contains(3, 20)) {
    EXPECT_NEAR(surface.theta_z(3, 20), 0.8, 1e-12);
  }
  const auto E = fluid::open_apertures(d);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  const auto cfg = fluid::config_from(params);
  const double dt = 0.005;
  fluid::apply_gravity(u, w, cells, dt, cfg);
  halo.forward(u), halo.forward(w);
  fluid::enforce_walls(u, w, cfg, d);
  CellField p(d, Stagger::Cell, 0.0);
  fluid::PressureSolver solver(d, params);
  solver.solve(cells, E, u, w, {}, dt, cfg, p, &surface);
  fluid::project(u, w, p, cells, E, dt, cfg, &surface);
  double perr = 0.0, wmax = 0.0;
  for (int k = cells.owned().k0; k < cells.owned().k1; ++k)
    for (int i = cells.owned().i0; i < cells.owned().i1; ++i)
      if (cells(i, k) == kFluid) {
        const double exact = 1000.0 * 9.81 * (zs - s.position(Stagger::Cell, i, k).z);
        perr = std::max(perr, std::abs(p(i, k) / exact - 1.0));
      }
  for (int k = w.owned().k0; k < w.owned().k1; ++k)
    for (int i = w.owned().i0; i < w.owned().i1; ++i)
      if (k <= 20) wmax = std::max(wmax, std::abs(w(i, k)));
  EXPECT_LT(comm.max(perr), 1e-9);
  EXPECT_LT(comm.max(wmax), 1e-9 * 9.81 * dt);
}

// Only rank 0's block holds fluid: the other ranks own no rows, with and without rebalancing.
TEST(PressureSolve, RanksWithoutFluid) {
  core::Comm comm;
  for (const char* rebalance : {"solver/rebalance=true", "solver/rebalance=false"}) {
    const auto params = fluid_test::tank_params(1.0, 1.0, 1.0 / 64, {rebalance});
    const GridSpec s = spec_from(params);
    Decomposition d(s, comm, 1);
    Halo halo(d);
    const auto block = d.owned_cells(0);
    fluid::CellStates cells(d, Stagger::Cell, kAir);
    const auto& cb = cells.storage();
    for (int k = cb.k0; k < cb.k1; ++k)
      for (int i = cb.i0; i < cb.i1; ++i)
        if (block.contains(i, k) && k < block.k1 - 1) cells(i, k) = kFluid;
    const auto E = fluid::open_apertures(d);
    FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
    const auto cfg = fluid::config_from(params);
    fluid::apply_gravity(u, w, cells, 0.01, cfg);
    halo.forward(u), halo.forward(w);
    fluid::enforce_walls(u, w, cfg, d);
    CellField p(d, Stagger::Cell, 0.0);
    fluid::PressureSolver solver(d, params);
    const auto stats = solver.solve(cells, E, u, w, {}, 0.01, cfg, p);
    EXPECT_EQ(stats.unknowns, static_cast<long long>(block.nx()) * (block.nz() - 1)) << rebalance;
    EXPECT_LT(stats.relative_residual, 1e-8) << rebalance;
    // Hydrostatic below the block's top fluid row: p = rho g h (top - k).
    double perr = 0.0;
    for (int k = cells.owned().k0; k < cells.owned().k1; ++k)
      for (int i = cells.owned().i0; i < cells.owned().i1; ++i)
        if (cells(i, k) == kFluid)
          perr =
              std::max(perr, std::abs(p(i, k) / (1000.0 * 9.81 * s.h * (block.k1 - 1 - k)) - 1.0));
    EXPECT_LT(comm.max(perr), 1e-6) << rebalance;
  }
}
