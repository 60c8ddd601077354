// DEM benchmark (never run by ctest): dry settling of N disks or 12-gons packed in a box, on as
// many ranks as mpirun gives (vertical strips). Prints the wall-clock time per subcycle per
// solid. Usage: bench_dem [disks|gons] N [subcycles]
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
    for (long long n = 0; n < N; ++n) {
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
    const core::Box2 tank{{0.0, 0.0}, {L, H}};
    std::vector<core::Box2> regions;
    for (int q = 0; q < comm.size(); ++q)
      regions.push_back({{L * q / comm.size(), 0.0}, {L * (q + 1) / comm.size(), H}});
    dem::DemSolver solver(comm, cfg, regions, tank, {});
    solver.add_solids(solids);
    const double dt = 10 * solver.dt_dem();
    solver.advance(dt, {});  // warm-up
    const long long rebuilds0 = solver.rebuilds();
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
    if (comm.is_root())
      std::printf(
          "%-5s N = %7lld ranks = %d: %d subcycles in %.3f s = %.3f us per solid per "
          "subcycle (%.2f contacts per solid, %lld rebuilds)\n",
          kind.c_str(), N, comm.size(), done, seconds,
          1e6 * seconds / done / static_cast<double>(N),
          static_cast<double>(contacts) / static_cast<double>(N), solver.rebuilds() - rebuilds0);
  }
  MPI_Finalize();
  return 0;
}
