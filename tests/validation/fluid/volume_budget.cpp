// The fluid volume's budget, step by step (issue 14): where timeseries.csv's fluid_volume (the
// area where the bilinear interpolant of the occupancy S exceeds 1/2, less the solids:
// fluid::occupied_area) parts from the particles' own area, N h^2 / (per_cell_1d)^2.
//   [mpirun -n R] volume_budget CASE.yaml OUT.csv END [KEY=VALUE ...]
// One row per step (S and the cut cells exactly as the step's diagnostic used them):
//   particles, added / removed   the count; reseeded this step (ids of this step's reseeding) and
//                                removed (added less the change of the count: trimming above
//                                particles/max_per_cell, outflows)
//   volume                       fluid_volume of the step
//   particle_area                N h^2 / per_cell_1d^2
//   occupancy_area               sum of S f h^2 over the cells (f the fluid fraction)
//   wet_cells                    sum of f h^2 over the cells with S > 1/2 (the cell count of
//                                the volume: volume less the sub-cell interpolation)
//   crowded                      sum of (S - 1) f h^2 where S > 1 (particles above the bulk
//                                density: in the particle area, not in the volume)
//   thinned                      sum of (1 - S) f h^2 where 1/2 < S < 1 (in the volume, not in
//                                the particle area)
//   dry                          sum of S f h^2 where S <= 1/2 (particles outside the volume)
//   dry_isolated                 the part of dry in cells with no S > 1/2 among their eight
//                                neighbours (splash and films too thin for the level set)
//   near_solid                   sum of ([S > 1/2] - S) f h^2 over the cells with f < 1 or a
//                                neighbour with f < 1: the solids' part of wet_cells - occupancy
//   full_cells, full_cut_cells   cells holding particles/max_per_cell particles or more after
//                                the step (trimming's candidates), and those of them with f < 1
//   bulk                         sum of (1 - S) f h^2 over the cells with S > 1/2 whose eight
//                                neighbours (those not covered by solids) have S > 1/2 too: the
//                                bulk's share of wet_cells - occupancy, below 0 where the
//                                particles are denser than seeded (PIC/FLIP's compression); the
//                                rest of it, thinned - crowded - dry - bulk, is the surface band's
//   near_volume, near_wet        the volume's part and wet_cells' part in those cells next to
//                                solids (near_volume - near_wet: the sub-cell interpolation there)
//   volume_after                 the volume recomputed here from the particles and the solids
//                                where the step leaves them (X^{n+1}): S, its open share
//                                correction and the fluid fractions of their cut cells; equal to
//                                volume since the diagnostic weights with X^{n+1} too (until
//                                issue 14's fix it used the solids at X^n, where the step started)
// wet_cells = occupancy_area - crowded + thinned - dry exactly.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/coupling/schema.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/coupling/solids_in_fluid.hpp"
#include "picdem/dem/scene.hpp"
#include "picdem/fluid/bodies.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/fluid/free_surface.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/grid/grid.hpp"
#include "picdem/particles/occupancy_pass.hpp"
#include "picdem/particles/particle_set.hpp"
#include "water_at_t0.hpp"

using namespace picdem;

namespace {

struct Sums {
  double occupancy = 0, wet = 0, crowded = 0, thinned = 0, dry = 0, dry_isolated = 0, near = 0;
  double full = 0, full_cut = 0, near_wet = 0, bulk = 0;
};

// Cells with f < 1 or a neighbour with f < 1 (next to a solid; cells of the grid only).
bool next_to_solid(const geometry::CutCells& cut, const core::IndexBox& on_grid, int i, int k) {
  for (int b = -1; b <= 1; ++b)
    for (int q = -1; q <= 1; ++q)
      if (on_grid.contains(i + q, k + b) && cut.store.contains(i + q, k + b) &&
          cut.fluid_fraction(i + q, k + b) < 1.0)
        return true;
  return false;
}

// The volume's part in the cells next to solids: the step's cut cells with the fluid fraction of
// every other cell set to 0 (collective).
double volume_next_to_solids(const grid::CellField& S, const grid::Decomposition& d,
                             const core::Comm& comm, const geometry::CutCells& cut) {
  // stored over the whole window (the cut cells store only what their bodies reach)
  geometry::CutCells near;
  near.window = cut.window;
  near.store = cut.window.cells;
  const auto& st = near.store;
  const auto nx = static_cast<std::size_t>(st.nx()), nz = static_cast<std::size_t>(st.nz());
  near.ex.assign((nx + 1) * nz, 1.0);
  near.ez.assign(nx * (nz + 1), 1.0);
  near.fraction.assign(nx * nz, 0.0);
  near.body.assign(nx * nz, -1);
  near.obstacle.assign(nx * nz, -1);
  near.tiny.assign(nx * nz, 0);
  const auto on_grid = d.spec().extent(grid::Stagger::Cell);
  for (int k = st.k0; k < st.k1; ++k)
    for (int i = st.i0; i < st.i1; ++i)
      if (next_to_solid(cut, on_grid, i, k))
        near.fraction[static_cast<std::size_t>(k - st.k0) * nx +
                      static_cast<std::size_t>(i - st.i0)] = cut.fluid_fraction(i, k);
  return fluid::occupied_area(S, d, comm, &near);
}

// The volume of the particles where the step left them with the solids where it left them
// (X^{n+1}): S again, corrected with the new cut cells' open share (collective).
double volume_after(const coupling::Simulation& sim, const grid::Decomposition& d,
                    const particles::ParticleConfig& config, double tiny, const core::Comm& comm) {
  const grid::Halo halo(d);
  particles::OccupancyPass occ;
  occ.update(sim.particles(), d, halo, config, false);
  fluid::Apertures apertures = sim.fluid().apertures;
  const dem::SolidScene scene = dem::scene_of(sim.dem(), sim.obstacles());
  const geometry::CutCells cut =
      fluid::cut_cells(scene.placements, scene.obstacles, tiny, d, apertures);
  grid::CellField S = occ.S;
  fluid::open_share_correction(S, cut, d);
  return fluid::occupied_area(S, d, comm, &cut);
}

// Cells of this rank holding at least `most` particles, and those with a fluid fraction below 1.
void full_cells(const particles::ParticleSet& ps, const grid::Decomposition& d,
                const geometry::CutCells* cut, int most, Sums& s) {
  const auto& spec = d.spec();
  const auto own = d.owned_cells();
  std::vector<int> n(static_cast<std::size_t>(own.size()), 0);
  for (std::size_t q = 0; q < ps.x.size(); ++q) {
    const int i =
        std::clamp(static_cast<int>((ps.x[q] - spec.origin.x) / spec.h), own.i0, own.i1 - 1);
    const int k =
        std::clamp(static_cast<int>((ps.z[q] - spec.origin.z) / spec.h), own.k0, own.k1 - 1);
    ++n[static_cast<std::size_t>(k - own.k0) * static_cast<std::size_t>(own.nx()) +
        static_cast<std::size_t>(i - own.i0)];
  }
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i)
      if (n[static_cast<std::size_t>(k - own.k0) * static_cast<std::size_t>(own.nx()) +
            static_cast<std::size_t>(i - own.i0)] >= most) {
        s.full += 1;
        if (cut && cut->fluid_fraction(i, k) < 1.0) s.full_cut += 1;
      }
}

// The cell sums of S over this rank's owned cells (cut: the solids at the start of the step).
Sums cell_sums(const grid::CellField& S, const grid::Decomposition& d,
               const geometry::CutCells* cut) {
  const auto& spec = d.spec();
  const auto own = d.owned_cells();
  const auto ext = spec.extent(grid::Stagger::Cell);
  const double a = spec.h * spec.h;
  auto frac = [&](int i, int k) { return cut ? cut->fluid_fraction(i, k) : 1.0; };
  Sums s;
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) {
      const double f = frac(i, k), v = S(i, k);
      bool wet_near = false, solid_near = f < 1.0, all_wet = true;
      for (int b = -1; b <= 1; ++b)
        for (int q = -1; q <= 1; ++q) {
          if (!ext.contains(i + q, k + b)) continue;
          wet_near = wet_near || S(i + q, k + b) > 0.5;
          solid_near = solid_near || frac(i + q, k + b) < 1.0;
          all_wet = all_wet && (S(i + q, k + b) > 0.5 || frac(i + q, k + b) == 0.0);
        }
      s.occupancy += v * f * a;
      if (v > 0.5) {
        s.wet += f * a;
        if (all_wet) s.bulk += (1.0 - v) * f * a;
        if (v > 1.0)
          s.crowded += (v - 1.0) * f * a;
        else
          s.thinned += (1.0 - v) * f * a;
      } else {
        s.dry += v * f * a;
        if (!wet_near) s.dry_isolated += v * f * a;
      }
      if (solid_near) {
        s.near += ((v > 0.5 ? 1.0 : 0.0) - v) * f * a;
        if (v > 0.5) s.near_wet += f * a;
      }
    }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  fluid::LinearAlgebraScope scope(&argc, &argv);
  if (argc < 4) {
    std::fprintf(stderr, "usage: volume_budget CASE.yaml OUT.csv END [KEY=VALUE ...]\n");
    return 2;
  }
  core::Comm comm;
  const std::vector<std::string> overrides(argv + 4, argv + argc);
  const auto params = core::read_case(comm, argv[1], overrides, coupling::case_schema());
  const double end = std::stod(argv[3]);
  coupling::Simulation sim(comm, params);
  const auto config = particles::config_from(params);
  const auto& d = sim.modules().decomposition;
  const auto& spec = d.spec();
  const std::int64_t id0 = particles::first_reseed_id(spec, config);
  const auto cells_total = static_cast<std::int64_t>(spec.nx) * spec.nz;
  const double particle_area = spec.h * spec.h / (config.per_cell_1d * config.per_cell_1d);
  const double tiny = params.real("coupling/tiny_cell_fraction");
  // the water at t = 0 of the dam breaks (one box, with or without cylinders), printed
  for (const std::string& region : std::vector<std::string>{"dam", "column"}) {
    if (!params.has("water/" + region + "/x")) continue;
    const bool disks = sim.dem() && params.has("solids/cylinders/radius");
    const double v0 = test_support::water_at_t0(
        params, region, disks ? sim.dem()->gather_all() : std::vector<core::SolidState>{},
        disks ? params.real("solids/cylinders/radius") : 0.0);
    if (comm.is_root()) std::printf("water at t = 0: %.9e m^2\n", v0);
  }
  std::ofstream out;
  if (comm.is_root()) {
    out.open(argv[2]);
    out << "t,step,particles,added,removed,volume,particle_area,occupancy_area,wet_cells,crowded,"
           "thinned,dry,dry_isolated,near_solid,full_cells,full_cut_cells,bulk,near_volume,"
           "near_wet,volume_after\n";
  }
  long long last_count = comm.sum(static_cast<long long>(sim.particles().size()));
  while (sim.time() < end - 1e-12) {
    const long long reseed_step = sim.step_count();
    sim.step();
    // the cut cells of the solids where the step leaves them, as the step's diagnostic reads them
    const bool bodies = sim.dem() != nullptr || !sim.obstacles().empty();
    geometry::CutCells cut;
    if (bodies) {
      fluid::Apertures apertures = sim.fluid().apertures;
      const dem::SolidScene scene = dem::scene_of(sim.dem(), sim.obstacles());
      cut = fluid::cut_cells(scene.placements, scene.obstacles, tiny, d, apertures);
    }
    const auto& g = sim.diagnostics();
    long long added = 0;
    for (const auto id : sim.particles().id)
      if (id >= id0 && (id - id0) / config.max_per_cell / cells_total == reseed_step) ++added;
    added = comm.sum(added);
    const long long removed = added - (g.particles - last_count);
    last_count = g.particles;
    Sums s = cell_sums(sim.fluid().occupancy, d, bodies ? &cut : nullptr);
    full_cells(sim.particles(), d, bodies ? &cut : nullptr, config.max_per_cell, s);
    std::vector<double> v{s.occupancy, s.wet,  s.crowded,  s.thinned, s.dry,     s.dry_isolated,
                          s.near,      s.full, s.full_cut, s.bulk,    s.near_wet};
    comm.sum_in_place(v);
    const double near_volume =
        bodies ? volume_next_to_solids(sim.fluid().occupancy, d, comm, cut) : 0.0;
    v.insert(v.end() - 1, near_volume);  // near_volume, near_wet
    v.push_back(bodies ? volume_after(sim, d, config, tiny, comm) : g.fluid_volume);
    if (comm.is_root()) {
      char row[512];
      std::snprintf(row, sizeof row, "%.9g,%lld,%lld,%lld,%lld,%.10e,%.10e", g.t, g.step,
                    g.particles, added, removed, g.fluid_volume,
                    static_cast<double>(g.particles) * particle_area);
      out << row;
      for (double x : v) {
        std::snprintf(row, sizeof row, ",%.10e", x);
        out << row;
      }
      out << "\n" << std::flush;
    }
  }
  return 0;
}
