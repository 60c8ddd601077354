// What sets the time step: runs a case (1 rank) and writes, for every step, the speeds the CFL
// rule could be taken from, as seen at the start of the step, and how far the particles then
// actually moved in it.
//   build/drivers/bench/dam_break/bench_time_step CASE.yaml OUT.csv [--set key=value ...]
// Columns: t, dt (the step taken), and in m/s
//   particle    largest particle speed |v_p| (the particle term of choose_time_step)
//   grid_all    largest |u|, |w| over all owned faces (the grid term of choose_time_step)
//   grid_fluid  largest |u|, |w| over the faces next to a fluid cell with E > 0
//   sampled     largest |v(x_p)| of the grid velocity interpolated at the particles
//   solid       largest |v| + |omega| R of the solids (R their bounding radius)
//   moved       largest particle displacement over the step / dt (ids matched on one rank)
// and the last column, moved dt / h: the CFL number the particles actually met.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/coupling/schema.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/particles/particle_set.hpp"

namespace {

using picdem::grid::FaceField;
using picdem::grid::GridSpec;
using picdem::grid::Stagger;

// Bilinear interpolation of one staggered component at (x, z), the base face clamped to the grid.
double sample(const FaceField& f, const GridSpec& s, Stagger st, double x, double z) {
  const double sx = (x - s.origin.x) / s.h - (st == Stagger::FaceZ ? 0.5 : 0.0);
  const double sz = (z - s.origin.z) / s.h - (st == Stagger::FaceX ? 0.5 : 0.0);
  const int ni = s.nx + (st == Stagger::FaceX ? 1 : 0), nk = s.nz + (st == Stagger::FaceZ ? 1 : 0);
  const int i = std::clamp(static_cast<int>(std::floor(sx)), 0, ni - 2);
  const int k = std::clamp(static_cast<int>(std::floor(sz)), 0, nk - 2);
  const double fx = sx - i, fz = sz - k;
  return (1 - fx) * (1 - fz) * f(i, k) + fx * (1 - fz) * f(i + 1, k) + (1 - fx) * fz * f(i, k + 1) +
         fx * fz * f(i + 1, k + 1);
}

struct Speeds {
  double particle = 0, grid_all = 0, grid_fluid = 0, sampled = 0, solid = 0;
};

Speeds speeds(const picdem::coupling::Simulation& sim, const GridSpec& s) {
  Speeds v;
  const auto& f = sim.fluid();
  const auto& P = sim.particles();
  picdem::grid::GridArray<signed char> uv = f.u_valid, wv = f.w_valid;
  picdem::fluid::fluid_faces(f.cells, f.apertures, uv, wv);
  for (auto [g, valid] : {std::pair{&f.u, &uv}, std::pair{&f.w, &wv}}) {
    const auto b = g->owned();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) {
        const double a = std::abs((*g)(i, k));
        v.grid_all = std::max(v.grid_all, a);
        if ((*valid)(i, k)) v.grid_fluid = std::max(v.grid_fluid, a);
      }
  }
  for (std::size_t n = 0; n < P.size(); ++n) {
    v.particle = std::max(v.particle, std::hypot(P.u[n], P.w[n]));
    const double us = sample(f.u, s, Stagger::FaceX, P.x[n], P.z[n]);
    const double ws = sample(f.w, s, Stagger::FaceZ, P.x[n], P.z[n]);
    v.sampled = std::max(v.sampled, std::hypot(us, ws));
  }
  if (const auto* dem = sim.dem())
    for (const auto& st : dem->owned())
      v.solid = std::max(v.solid, std::hypot(st.v.x, st.v.z) +
                                      std::abs(st.omega) * dem->shape_of(st.id)->bounding_radius());
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  picdem::fluid::LinearAlgebraScope scope(&argc, &argv);
  picdem::core::Comm comm;
  if (argc < 3 || comm.size() != 1) {
    std::fprintf(stderr, "usage (1 rank): bench_time_step CASE.yaml OUT.csv [--set key=value]\n");
    return 2;
  }
  std::vector<std::string> sets;
  for (int a = 3; a + 1 < argc; a += 2)
    if (std::string(argv[a]) == "--set") sets.emplace_back(argv[a + 1]);
  const auto params = picdem::core::read_case(comm, argv[1], sets, picdem::coupling::case_schema());
  picdem::coupling::Simulation sim(comm, params);
  const GridSpec s = picdem::grid::spec_from(sim.params());
  std::FILE* out = std::fopen(argv[2], "w");
  std::fprintf(out, "t,dt,particle,grid_all,grid_fluid,sampled,solid,moved,moved_cfl\n");
  const double t_end = sim.params().real("time/end");
  while (sim.time() < t_end * (1.0 - 1e-12)) {
    const Speeds v = speeds(sim, s);
    std::unordered_map<std::int64_t, std::pair<double, double>> before;
    const auto& P = sim.particles();
    for (std::size_t n = 0; n < P.size(); ++n) before[P.id[n]] = {P.x[n], P.z[n]};
    sim.step();
    const double dt = sim.diagnostics().dt;
    double moved = 0.0;
    for (std::size_t n = 0; n < P.size(); ++n) {
      const auto it = before.find(P.id[n]);
      if (it != before.end())
        moved = std::max(moved, std::hypot(P.x[n] - it->second.first, P.z[n] - it->second.second));
    }
    std::fprintf(out, "%.6e,%.6e,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.4f\n", sim.time(), dt, v.particle,
                 v.grid_all, v.grid_fluid, v.sampled, v.solid, moved / dt, moved / s.h);
  }
  std::fclose(out);
  return 0;
}
