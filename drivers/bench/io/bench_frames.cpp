// ParaView frame and PNG snapshot cost for a state of typical size.
//   mpirun -n <ranks> bench_frames [nx = 1024] [particles = 1000000] [repeats = 3]
// Grid nx x nx/2 cells with three cell fields; particles with two scalars (speed, id); 100 solid
// outlines of 64 vertices. Prints the best of `repeats` for FrameWriter::write and
// render_snapshot (1200 pixels wide), and the frame file size.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "picdem/core/comm.hpp"
#include "picdem/core/rng.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/grid/grid.hpp"
#include "picdem/io/frame_writer.hpp"
#include "picdem/io/render.hpp"

namespace {

template <class F>
double best_of(int repeats, const picdem::core::Comm& comm, const F& f) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    comm.barrier();
    const double t0 = MPI_Wtime();
    f();
    comm.barrier();
    best = std::min(best, comm.max(MPI_Wtime() - t0));
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  {
    namespace grid = picdem::grid;
    namespace io = picdem::io;
    const picdem::core::Comm comm;
    const int nx = argc > 1 ? std::atoi(argv[1]) : 1024;
    const long long n = argc > 2 ? std::atoll(argv[2]) : 1000000;
    const int repeats = argc > 3 ? std::atoi(argv[3]) : 3;
    grid::GridSpec spec;
    spec.nx = nx;
    spec.nz = nx / 2;
    spec.h = 1.0 / nx;
    const grid::Decomposition d(spec, comm, 1);
    grid::CellField p(d, grid::Stagger::Cell, 1.0), state(d, grid::Stagger::Cell, 1.0),
        speed(d, grid::Stagger::Cell, 0.5);
    // Particles spread uniformly over the tank; each rank keeps those in its cells.
    io::PointSet particles;
    for (long long g = 0; g < n; ++g) {
      const double x = picdem::core::uniform01(7, g, 0, 0) * spec.length();
      const double z = picdem::core::uniform01(7, g, 1, 0) * spec.height();
      if (d.owner_of_point({x, z}) != d.rank()) continue;
      particles.x.push_back(x);
      particles.z.push_back(z);
      particles.scalars["speed"].push_back(std::hypot(x, z));
      particles.integers["id"].push_back(g);
    }
    io::Polylines solids, obstacles;
    for (int b = comm.rank(); b < 100; b += comm.size()) {
      std::vector<picdem::core::Vec2> ring;
      const double cx = 0.1 + 0.008 * b, cz = 0.25, r = 0.004;
      for (int v = 0; v < 64; ++v)
        ring.push_back({cx + r * std::cos(v * 0.0982), cz + r * std::sin(v * 0.0982)});
      solids.lines.push_back(ring);
      solids.body_id.push_back(b);
    }
    io::FrameWriter frames("bench_frames_out", d);
    const double t_frame = best_of(repeats, comm, [&] {
      frames.write(0.0, 0, {{{"pressure", &p}, {"state", &state}, {"speed", &speed}}, {}, {}},
                   particles, solids, obstacles);
    });
    io::SnapshotStyle style;
    style.width_pixels = 1200;
    style.speed_max = 1.0;
    style.particle_radius = 0.3 * spec.h;
    style.title = "bench_frames";
    const double t_png = best_of(repeats, comm, [&] {
      io::render_snapshot(comm, "bench_frames_out/snapshot.png",
                          {{0.0, 0.0}, {spec.length(), spec.height()}}, particles, solids,
                          obstacles, style);
    });
    if (comm.is_root()) {
      const double mb = static_cast<double>(std::filesystem::file_size(frames.frame_path(0))) / 1e6;
      const double png_kb =
          static_cast<double>(std::filesystem::file_size("bench_frames_out/snapshot.png")) / 1e3;
      std::printf(
          "frame: %d x %d cells (3 fields), %lld particles (2 scalars), 100 outlines of 64 "
          "vertices, %d rank(s), best of %d\n",
          spec.nx, spec.nz, n, comm.size(), repeats);
      std::printf("  FrameWriter::write   %8.4f s   file %.1f MB\n", t_frame, mb);
      std::printf("  render_snapshot      %8.4f s   PNG %.0f kB (1200 px wide)\n", t_png, png_kb);
    }
  }
  MPI_Finalize();
  return 0;
}
