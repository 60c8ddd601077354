#include "input_checks.hpp"

#include <fstream>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/dem/parameters.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/fluid/viscous_settings.hpp"
#include "solid_placement.hpp"

namespace picdem::driver {

namespace {

// Sizes measured with /usr/bin/time's maximum resident size on the 0.2 m x 0.1 m tank of
// tests/unit/coupling/good_case.yaml, 2 steps, 5,000 to 320,000 cells, 2 x 2 and 3 x 3
// particles per cell (doc/cases.md): about 160 B for every cell, 580 B more for every cell of
// water (the pressure system, MueLu's hierarchy, the water's fields) and 70 B per particle;
// rounded up to the figures below. The process itself (MPI, Kokkos, libraries) takes 80 MB.
constexpr double bytes_per_cell = 200.0;
constexpr double bytes_per_water_cell = 700.0;
constexpr double bytes_per_particle = 100.0;
constexpr double bytes_per_process = 80e6;

std::string gb(double bytes) {
  std::ostringstream s;
  s.precision(3);
  s << bytes / 1e9 << " GB";
  return s.str();
}

/// The area of the water regions at t = 0 (their overlaps counted twice: an upper bound).
double water_area(const core::Params& p) {
  const auto o = p.reals("grid/origin");
  double area = 0.0;
  for (const auto& name : p.sublist_names("water")) {
    const auto w = p.sub("water/" + name);
    if (w.string("type") == "box") {
      const auto x = w.reals("x"), z = w.reals("z");
      area += (x[1] - x[0]) * (z[1] - z[0]);
    } else {
      area += (w.real("z") - o[1]) * p.real("grid/length");
    }
  }
  return std::min(area, p.real("grid/length") * p.real("grid/height"));
}

int ranks_on_this_node(const core::Comm& comm) {
  MPI_Comm node;
  MPI_Comm_split_type(comm.raw(), MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int n = 1;
  MPI_Comm_size(node, &n);
  MPI_Comm_free(&node);
  return n;
}

double mem_total_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0.0;
  while (in >> key) {
    if (key == "MemTotal:" && in >> kb) return kb * 1024.0;
    std::getline(in, key);
  }
  return 0.0;  // unknown: no limit
}

void check_memory(const core::Comm& comm, const core::Params& params,
                  std::vector<std::string>& errors) {
  const double need = memory_estimate_bytes(params, comm.size());
  const double limit = memory_limit_bytes(comm, params);
  if (!(limit > 0.0) || need <= limit) return;
  const double h = params.real("grid/cell_size");
  const double cells = params.real("grid/length") / h * (params.real("grid/height") / h);
  std::ostringstream m;
  m.precision(4);
  m << "the case needs about " << gb(need) << " per rank on " << comm.size() << " rank(s) ("
    << cells << " cells of grid/cell_size = " << h
    << " m, particles/per_cell_1d = " << params.integer("particles/per_cell_1d")
    << "), more than the " << gb(limit) << " a rank may use ("
    << (params.real("run/memory_limit_gb") > 0.0 ? "run/memory_limit_gb"
                                                 : "MemTotal of /proc/meminfo / ranks on the node")
    << "); allowed: a larger grid/cell_size, fewer particles, more ranks, or "
       "run/memory_limit_gb set to what the ranks may really use";
  errors.push_back(m.str());
}

}  // namespace

double memory_estimate_bytes(const core::Params& params, int ranks) {
  const double h = params.real("grid/cell_size");
  const double cells = params.real("grid/length") / h * (params.real("grid/height") / h);
  const double water_cells = water_area(params) / (h * h);
  const double n1 = static_cast<double>(params.integer("particles/per_cell_1d"));
  const double particles = water_cells * n1 * n1;
  const double shared =
      cells * bytes_per_cell + water_cells * bytes_per_water_cell + particles * bytes_per_particle;
  return bytes_per_process + shared / ranks;
}

double memory_limit_bytes(const core::Comm& comm, const core::Params& params) {
  double limit = params.real("run/memory_limit_gb") * 1e9;
  if (!(limit > 0.0)) limit = mem_total_bytes() / ranks_on_this_node(comm);
  return -comm.max(-limit);  // the smallest over the ranks: the same verdict everywhere
}

std::string checks_markdown() {
  return R"(## Checks before the run

`picdem CASE.yaml` and `picdem --check CASE.yaml` read the case the same way on every rank and
stop before anything is computed, with exit code 2 and a message naming the key (or the solid),
the value and what is allowed, when:

- a key is unknown (misspelt), of the wrong type, out of its range, or a required key is missing;
  a `solids` or `water` entry has an unknown `type`; a vertex list is odd, too short, clockwise
  or not simple (the builder's message, prefixed with `solids/NAME`);
- a solid's outline reaches outside the tank (`grid/origin`, `grid/length`, `grid/height`): its
  exact extent (support points of its segments and arcs) is compared with the walls;
- a solid lies closer to a tank wall, another solid or an obstacle than the DEM's contact gap
  (`dem/gap_cells` x `grid/cell_size`, eq. 19) less `dem/theta` cells: the contact spring, which
  starts at the gap, would start compressed by the gap less the distance, that many times
  (theta cells) the heaviest solid's weight, and throw the bodies apart at the first step (a
  disk placed on the floor with the defaults starts under 200 weights: with water a particle
  reached 19 m/s in the first step, dry the disk jumped 8.6 cm). The message gives the distance,
  the compression and the distance allowed. The shipped cylinder stacks and packings place their
  solids exactly the gap apart, and pass; a resting contact, pressed by theta cells per weight
  it carries, is let through up to one weight. A generator's own `gap` key below that distance
  is named as the cause (once, instead of every pair it places). Distances are exact: two
  circles, d - r_a - r_b; other outlines, the closest points of their segments and arcs; a wall,
  the support point;
- two solids, or a solid and an obstacle polygon, overlap. Solids are named by their entry and
  id (`solids/stack[4] (id 4)`, the k-th shape of a generator), obstacles by their entry. The
  depth is exact: two circles,
  r_a + r_b - d; other convex outlines (polygons, rounded polygons, ellipses' arc splines, and
  circles against them), the shortest translation that separates them, from the support functions
  of their segments and arcs (geometry/overlap.hpp); a non-convex polygon (a solid or an
  obstacle) is split into convex polygons (CGAL's approx_convex_partition_2) and the depth is the
  largest over its parts: any overlap is found, and the depth named is that of the deepest part.
  Depths below 1e-9 of the larger size are round-off. Candidate pairs come from a grid of buckets
  of the median solid size (O(N)): 100,014 cylinders are checked in about 0.1 s;
- an obstacle reaches farther from the tank than the tank's own length (in x) or height (in z),
  the mark of a mistyped size (a fall pipe's `wall_thickness` or `funnel_height` of 1e30, which
  would also hide every overlap below in round-off); the message names the obstacle's entry;
- an obstacle lies wholly outside the tank (it would cut no cell: a coordinate with the wrong
  sign, a tank shortened by an override), or a perforated fall pipe has more than 10,000 holes
  per wall (`top` - `bottom` over `hole_spacing`: a mistyped height);
- with water, a solid or an obstacle is less than one cell (`grid/cell_size`) across at its
  narrowest (its convex hull's width over all directions): lying between two grid lines it closes
  no cell face across that width and the water flows through it (a plate thinner than a cell), or,
  narrower than a cell both ways, the pressure equation does not see it at all (a radius typed in
  mm as m); dry runs are not checked, their grid holds nothing of the solids;
- `fluid/viscosity` is more than any step can carry: with the explicit scheme its stable step
  h^2 / (4 nu) is below `time/dt_min`; with the implicit ones the viscous number
  nu `time/dt_max` / h^2 exceeds 1e12, where the solve's mass term is lost to round-off;
- a solid's density is below 1e-10 of `fluid/density` (the message names the solid and both
  densities): the pressure system's fluid terms and that solid's would then differ by more than
  round-off carries (`cases/floating_disk`, 30 steps: a ratio of 5e-10 runs, 5e-12 stops with the
  pressure solve unconverged); no real solid is that light, a mistyped `fluid/density` is;
- `time/dt_max` lies below `time/dt_min`, or (with water and `time/cfl_speed: grid`) `time/cfl`
  is so small that gravity's bound sqrt(cfl h / |g|) lies below `time/dt_min`: every step would
  stop the run as blown up;
- `free_surface/density_correction` is on while reseeding is (`particles/min_per_cell` > 0): the
  correction spreads the crowded particles and reseeding still adds to the thinned cells, which
  creates water (+15.8% on the plain dam break) or blows up (a dam break against a step and three
  bodies at 0.24 s); with the correction, `particles/min_per_cell` must be 0;
- `dem/theta` is not below `dem/gap_cells`: eq. 10's stiffness lets the heaviest solid's weight
  alone press a contact by theta cells, so resting solids would close the whole imaginary gap and
  stop the run as an overlap of real boundaries (a run that stops so names both keys);
- water regions reach outside the tank, are empty, or are thinner than one particle spacing
  (`grid/cell_size` / `particles/per_cell_1d`: they would seed no particle);
- `solver/Belos`, `solver/MueLu` (and the lists merged from `solver/MueLu_solids`,
  `solver/MueLu_one_level`), or the implicit viscous solve's `viscous_solver/Belos`,
  `viscous_solver/MueLu`, hold a key or a type that Trilinos' own validators reject, or a
  `smoother: type` Ifpack2 does not provide; the keys of the sublists `smoother: params`,
  `smoother: pre params`, `smoother: post params` and `coarse: params` are given, as MueLu would
  give them, to the Ifpack2 smoother of that type built on a 4-row matrix (or, for a direct coarse
  type, to MueLu's DirectSolver): a value or type it rejects is named with its key and Trilinos'
  reason, and so is a key that a smoother which does not validate its keys (CHEBYSHEV) never reads
  and would silently ignore (the keys MueLu takes out of the list itself, such as
  `chebyshev: use rowsumabs diagonal scaling`, are checked for their type only). The `level N`
  sublists are not checked;
- the estimated memory of a rank exceeds what it may use: `run/memory_limit_gb`, or, when 0,
  MemTotal of /proc/meminfo divided by the ranks on the node (the smallest over the ranks). The
  estimate is 80 MB per process + (200 B per cell + 700 B per cell of water at t = 0 + 100 B per
  particle, per_cell_1d^2 per cell of water) / ranks, sizes measured with the maximum resident
  size on 5,000 to 320,000 cells and rounded up; it assumes an even share over the ranks. So a
  cell size of 1e-7 m is refused by name. Raise `run/memory_limit_gb` to run a case the
  estimate refuses. A `std::bad_alloc` that still happens stops the run (exit code 4) with the
  process's size and the keys to change.

)";
}

void check_case(const core::Comm& comm, const core::Params& params) {
  std::vector<std::string> errors;
  try {
    fluid::check_solver_settings(params);
  } catch (const core::InputError& e) {
    errors.push_back(e.what());
  }
  try {
    fluid::viscous_solver_settings_from(params);  // checks the viscous_solver/ lists
  } catch (const core::InputError& e) {
    errors.push_back(e.what());
  }
  try {
    dem::config_from(params, params.real("grid/cell_size"));  // the DEM's keys taken together
  } catch (const core::InputError& e) {
    errors.push_back(e.what());
  }
  check_memory(comm, params, errors);
  for (auto& e : check_solid_placement(params)) errors.push_back(std::move(e));
  if (errors.empty()) return;
  std::string text = errors.size() == 1 ? "" : std::to_string(errors.size()) + " problems:\n";
  for (std::size_t n = 0; n < errors.size(); ++n) text += (n ? "\n" : "") + errors[n];
  throw core::InputError(text);
}

}  // namespace picdem::driver
