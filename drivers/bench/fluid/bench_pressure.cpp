// Pressure-solve benchmark: the dam-break free-surface matrix (water column over half the tank
// width and 3/4 of its height, random velocities plus gravity, cold start) at n^2 cells for
// several MueLu settings. With the argument "balanced" the tank is full to its top row instead,
// so that every rank holds the same number of fluid cells. Prints unknowns, CG iterations to 1e-8
// and setup / solve seconds (best of `repeats`, each with a new solver, so the Tpetra structure is
// built every time), then the setup of a kept solver re-solving the same mask ("setup_kept":
// structure reused, values refilled; MueLu's hierarchy is built anew either way) and the
// assembly of the rows alone. Run with 1 and 2 ranks:
//   mpirun -n 2 build/drivers/bench/fluid/bench_pressure [balanced] [default] [--set=key=value] [n
//   ...]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "picdem/core/log.hpp"
#include "picdem/core/rng.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/pressure_solver.hpp"

using namespace picdem;
using namespace picdem::grid;

namespace {

struct Variant {
  const char* name;
  std::vector<std::string> overrides;
};

struct Options {
  std::vector<int> sizes;
  bool balanced = false, only_default = false;
  std::vector<std::string> extra;  // --set=path=value, applied after each variant's settings
};

Options parse_options(int argc, char** argv) {
  Options o;
  for (int a = 1; a < argc; ++a) {
    if (std::string(argv[a]) == "balanced")
      o.balanced = true;
    else if (std::string(argv[a]) == "default")
      o.only_default = true;
    else if (std::string(argv[a]).rfind("--set=", 0) == 0)
      o.extra.push_back(std::string(argv[a]).substr(6));
    else
      o.sizes.push_back(std::atoi(argv[a]));
  }
  if (o.sizes.empty()) o.sizes = {128, 256, 512, 1024};
  return o;
}

const std::vector<Variant>& variants() {
  static const std::vector<Variant> v = {
      {"default (cheby. deg 3, repartition)", {}},
      {"smoother sym. Gauss-Seidel",
       {"solver/MueLu={\"smoother: type\": RELAXATION, \"smoother: params\": "
        "{\"relaxation: type\": \"Symmetric Gauss-Seidel\"}}"}},
      {"default, rows not rebalanced", {"solver/rebalance=false"}},
      {"chebyshev degree 2", {"solver/MueLu={\"smoother: params\": {\"chebyshev: degree\": 2}}"}},
      {"iterative coarse (no repartition)",
       {"solver/MueLu={\"repartition: enable\": false, \"coarse: type\": RELAXATION, "
        "\"coarse: params\": {\"relaxation: type\": \"Symmetric Gauss-Seidel\", "
        "\"relaxation: sweeps\": 4}}"}},
  };
  return v;
}

/// The dam break's cells, apertures and velocities (random plus gravity, walls enforced).
struct Tank {
  Tank(const core::Comm& comm, const core::Params& params, int n, bool balanced)
      : s(spec_from(params)),
        d(s, comm, fluid::required_halo()),
        halo(d),
        cfg(fluid::config_from(params)),
        cells(d, Stagger::Cell, static_cast<signed char>(CellState::Air)),
        E(fluid::open_apertures(d)),
        u(d, Stagger::FaceX, 0.0),
        w(d, Stagger::FaceZ, 0.0),
        dt(0.2 / n) {
    const auto& cb = cells.storage();
    for (int k = cb.k0; k < cb.k1; ++k)
      for (int i = cb.i0; i < cb.i1; ++i)
        if (i >= 0 && k >= 0 && i < (balanced ? s.nx : s.nx / 2) &&
            k < (balanced ? s.nz - 1 : 3 * s.nz / 4))
          cells(i, k) = static_cast<signed char>(CellState::Fluid);
    for (FaceField* f : {&u, &w})
      for (int k = f->owned().k0; k < f->owned().k1; ++k)
        for (int i = f->owned().i0; i < f->owned().i1; ++i)
          (*f)(i, k) = 0.1 * (core::uniform01(1, f == &u, i, k) - 0.5);
    fluid::apply_gravity(u, w, cells, dt, cfg);
    halo.forward(u), halo.forward(w);
    fluid::enforce_walls(u, w, cfg, d);
  }
  GridSpec s;
  Decomposition d;
  Halo halo;
  fluid::FluidConfig cfg;
  fluid::CellStates cells;
  fluid::Apertures E;
  FaceField u, w;
  double dt;
};

/// Best-of-`repeats` times of fresh solvers, of a kept solver and of the assembly; prints a row.
void measure(const core::Comm& comm, const core::Params& params, Tank& t, const Variant& v, int n) {
  const int repeats = 3;
  double best_setup = 1e300, best_solve = 1e300, best_kept = 1e300, best_assembly = 1e300;
  fluid::SolveStats st;
  for (int r = 0; r < repeats; ++r) {
    fluid::PressureSolver fresh(t.d, params);
    CellField p(t.d, Stagger::Cell, 0.0);
    comm.barrier();
    st = fresh.solve(t.cells, t.E, t.u, t.w, {}, t.dt, t.cfg, p);
    best_setup = std::min(best_setup, comm.max(st.setup_seconds));
    best_solve = std::min(best_solve, comm.max(st.solve_seconds));
  }
  fluid::PressureSolver solver(t.d, params);
  for (int r = 0; r <= repeats; ++r) {
    CellField p(t.d, Stagger::Cell, 0.0);
    comm.barrier();
    const auto kept = solver.solve(t.cells, t.E, t.u, t.w, {}, t.dt, t.cfg, p);
    if (r > 0 && kept.reused_structure)
      best_kept = std::min(best_kept, comm.max(kept.setup_seconds));
  }
  for (int r = 0; r < repeats; ++r) {
    comm.barrier();
    const double t0 = core::wall_seconds();
    const auto sys = solver.assemble(t.cells, t.E, t.u, t.w, {}, t.dt, t.cfg);
    best_assembly = std::min(best_assembly, comm.max(core::wall_seconds() - t0));
  }
  if (comm.is_root())
    std::printf("%6d %5d %-36s %9lld %5d %8.3f %8.3f %8.3f %10.3f   (assembly %.3f)\n", n,
                comm.size(), v.name, st.unknowns, st.iterations, best_setup, best_solve,
                best_setup + best_solve, best_kept, best_assembly);
}

}  // namespace

int main(int argc, char** argv) {
  fluid::LinearAlgebraScope scope(&argc, &argv);
  core::Comm comm;
  const Options o = parse_options(argc, argv);
  if (comm.is_root())
    std::printf("%6s %5s %-36s %9s %5s %8s %8s %8s %10s\n", "n", "ranks", "MueLu setting",
                "unknowns", "iter", "setup_s", "solve_s", "total_s", "setup_kept");
  for (int n : o.sizes) {
    for (const auto& v : variants()) {
      if (o.only_default && &v != &variants().front()) continue;
      core::ParamSchema schema;
      grid::declare_parameters(schema);
      fluid::declare_parameters(schema);
      const std::string yaml =
          "grid: {length: 1.0, height: 1.0, cell_size: " + std::to_string(1.0 / n) + "}\n";
      auto overrides = v.overrides;
      overrides.insert(overrides.end(), o.extra.begin(), o.extra.end());
      const auto params = core::read_case_text(yaml, "bench", overrides, schema);
      Tank tank(comm, params, n, o.balanced);
      measure(comm, params, tank, v, n);
    }
  }
  // Where the solver's time went, summed over every solve above (slowest rank).
  const auto totals = core::timer_totals();
  for (const auto& [name, seconds] : totals)
    if (name.rfind("fluid: pressure", 0) == 0) {
      const double t = comm.max(seconds);
      if (comm.is_root()) std::printf("  %-34s %8.3f s\n", name.c_str(), t);
    }
  return 0;
}
