#pragma once
// The dry collapse case (cases/dry_collapse_6layers) run through the DEM API, shared by the
// validation test and the rank-count test. The `time` and `output` keys belong to the coupling
// module; they are declared here only so that the same case file validates.
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::dem::testing {

inline core::ParamSchema collapse_schema() {
  core::ParamSchema s;
  grid::declare_parameters(s);
  declare_parameters(s);
  s.real("time/end", 1.0, "end time [s]").positive();
  s.real("time/dt_max", 1e-3, "largest step [s]").positive();
  s.real("time/cfl", 0.5, "CFL number").positive();
  s.real("output/interval", 0.01, "output interval [s]").positive();
  s.string("output/directory", "out", {}, "output folder");
  return s;
}

struct CollapseCase {
  core::Params params;
  DemConfig cfg;
  core::Box2 tank;
  std::vector<SolidSpec> solids;
  double t_end = 0.0, dt = 0.0, interval = 0.0;
};

inline CollapseCase load_collapse(const core::Comm& comm,
                                  const std::vector<std::string>& overrides = {}) {
  CollapseCase c;
  c.params = core::read_case(
      comm, std::string(PICDEM_SOURCE_DIR) + "/cases/dry_collapse_6layers/case.yaml", overrides,
      collapse_schema());
  const grid::GridSpec g = grid::spec_from(c.params);
  c.cfg = config_from(c.params, g.h);
  c.tank = {g.origin, g.origin + core::Vec2{g.length(), g.height()}};
  c.solids = solids_from(c.params);
  c.t_end = c.params.real("time/end");
  c.dt = c.params.real("time/dt_max");
  c.interval = c.params.real("output/interval");
  return c;
}

/// Runs the case on `comm` with the given regions; `at_output(t, solver)` at t = 0 and every
/// output interval.
inline void run_collapse(const core::Comm& comm, const CollapseCase& c,
                         std::vector<core::Box2> regions,
                         const std::function<void(double, const DemSolver&)>& at_output) {
  DemSolver solver(comm, c.cfg, std::move(regions), c.tank, {});
  solver.add_solids(c.solids);
  const long long steps = std::llround(c.t_end / c.dt);
  const long long every = std::max(1LL, std::llround(c.interval / c.dt));
  at_output(0.0, solver);
  for (long long n = 1; n <= steps; ++n) {
    solver.advance(c.dt, {});
    if (n % every == 0) at_output(static_cast<double>(n) * c.dt, solver);
  }
}

/// Vertical strips cutting the tank at the given x positions.
inline std::vector<core::Box2> strips(const core::Box2& tank, const std::vector<double>& cuts) {
  std::vector<core::Box2> r;
  double lo = tank.lo.x;
  for (double x : cuts) {
    r.push_back({{lo, tank.lo.z}, {x, tank.hi.z}});
    lo = x;
  }
  r.push_back({{lo, tank.lo.z}, tank.hi});
  return r;
}

/// solids.csv rows (long format) for every solid at time t.
inline void append_solids_csv(std::string& out, double t,
                              const std::vector<core::SolidState>& all) {
  char line[512];
  for (const auto& s : all) {
    std::snprintf(line, sizeof line, "%.17g,%lld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", t,
                  static_cast<long long>(s.id), s.x.x, s.x.z, s.theta, s.v.x, s.v.z, s.omega);
    out += line;
  }
}

}  // namespace picdem::dem::testing
