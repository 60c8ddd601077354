// DEM benchmark (never run by ctest): dry settling of N disks or 12-gons packed in a box, or of N
// graded disks (radii log-uniform over a factor of 10, 2.5 to 25 mm, laid in rows), on as many
// ranks as mpirun gives (vertical strips). Prints the wall-clock time per subcycle per solid and
// per contact. Usage: bench_dem [disks|gons|graded] N [subcycles]
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "picdem/core/rng.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/geometry/circle.hpp"
#include "picdem/geometry/polygon.hpp"

using namespace picdem;

namespace {

/// N disks of radii log-uniform in [2.5, 25] mm (seeded) laid left to right in rows just inside
/// each other's 2h gap, rows one largest diameter apart, in a box about twice as wide as high.
void graded_rows(long long N, double gap, std::vector<dem::SolidSpec>& out, core::Box2& tank) {
  const double r_min = 0.0025, r_max = 0.025;
  double area = 0.0;
  std::vector<double> radii;
  for (long long n = 0; n < N; ++n) {
    radii.push_back(r_min * std::pow(r_max / r_min, core::uniform01(5, n, 0)));
    area += 4.0 * radii.back() * radii.back();
  }
  const double L = std::sqrt(2.0 * area) * 1.2, row = 2.0 * r_max + gap;
  double x = gap, z = gap + r_max;
  for (long long n = 0; n < N; ++n) {
    const double r = radii[static_cast<std::size_t>(n)];
    if (x + 2.0 * r + gap > L) x = gap, z += row;
    dem::SolidSpec s;
    s.shape = std::make_shared<const geometry::Circle>(r);
    s.density = 2700.0;
    s.state.id = n;
    s.state.x = {x + r, z};
    x += 2.0 * r + 0.9 * gap;
    out.push_back(s);
  }
  tank = {{0.0, 0.0}, {L, z + r_max + 2.0 * row}};
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  {
    const core::Comm comm;
    const std::string kind = argc > 1 ? argv[1] : "disks";
    const long long N = argc > 2 ? std::atoll(argv[2]) : 1000;
    const int subcycles = argc > 3 ? std::atoi(argv[3]) : 200;
    const double r = 0.005;
    dem::DemConfig cfg;
    cfg.h = 0.0005;
    geometry::ShapePtr shape;
    if (kind == "gons") {
      std::vector<core::Vec2> v;
      for (int k = 0; k < 12; ++k)
        v.push_back({r * std::cos(2 * 3.141592653589793 * k / 12),
                     r * std::sin(2 * 3.141592653589793 * k / 12)});
      shape = std::make_shared<const geometry::Polygon>(v);
    } else {
      shape = std::make_shared<const geometry::Circle>(r);
    }
    // a hexagonal packing twice as wide as high, neighbours slightly inside the 2h gap
    const double pitch = 2 * r + 0.9 * cfg.gap(), rise = 0.5 * std::sqrt(3.0) * pitch;
    const long long per_row = static_cast<long long>(std::ceil(std::sqrt(2.0 * N)));
    const double L = (per_row + 1) * pitch, H = 2.0 * (static_cast<double>(N) / per_row + 2) * rise;
    std::vector<dem::SolidSpec> solids;
    core::Box2 graded_tank;
    if (kind == "graded") graded_rows(N, cfg.gap(), solids, graded_tank);
    for (long long n = 0; n < (kind == "graded" ? 0 : N); ++n) {
      const long long row = n / per_row, col = n % per_row;
      dem::SolidSpec s;
      s.shape = shape;
      s.density = 2700.0;
      s.state.id = n;
      s.state.x = {cfg.gap() + r + (row % 2) * 0.5 * pitch + col * pitch,
                   cfg.gap() + r + row * rise};
      s.state.v = {0.01 * (core::uniform01(1, n, 0) - 0.5), 0.0};
      solids.push_back(s);
    }
    const core::Box2 tank = kind == "graded" ? graded_tank : core::Box2{{0.0, 0.0}, {L, H}};
    const double W = tank.hi.x, Ht = tank.hi.z;
    std::vector<core::Box2> regions;
    for (int q = 0; q < comm.size(); ++q)
      regions.push_back({{W * q / comm.size(), 0.0}, {W * (q + 1) / comm.size(), Ht}});
    dem::DemSolver solver(comm, cfg, regions, tank, {});
    comm.barrier();
    const double tb = MPI_Wtime();
    solver.add_solids(solids);  // builds the neighbour lists once
    comm.barrier();
    const double build_seconds = MPI_Wtime() - tb;
    const double dt = 10 * solver.dt_dem();
    solver.advance(dt, {});  // warm-up
    const long long rebuilds0 = solver.rebuilds();
    const long long contacts0 = comm.sum(static_cast<long long>(solver.active_contacts().size()));
    comm.barrier();
    const double t0 = MPI_Wtime();
    int done = 0;
    while (done < subcycles) {
      solver.advance(dt, {});
      done += solver.last_subcycles();
    }
    comm.barrier();
    const double seconds = MPI_Wtime() - t0;
    const long long contacts = comm.sum(static_cast<long long>(solver.active_contacts().size()));
    // contacts: the mean of the counts at the start and at the end of the timed subcycles
    const double mean_contacts = 0.5 * static_cast<double>(contacts0 + contacts);
    if (comm.is_root())
      std::printf(
          "%-6s N = %7lld ranks = %d: %d subcycles in %.3f s = %.3f us per solid per "
          "subcycle, %.3f us per contact per subcycle (%.2f contacts per solid, %lld rebuilds; "
          "first neighbour build %.3f us per solid)\n",
          kind.c_str(), N, comm.size(), done, seconds,
          1e6 * seconds / done / static_cast<double>(N), 1e6 * seconds / done / mean_contacts,
          mean_contacts / static_cast<double>(N), solver.rebuilds() - rebuilds0,
          1e6 * build_seconds / static_cast<double>(N));
  }
  MPI_Finalize();
  return 0;
}
