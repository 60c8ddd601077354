// Checkpoint write and read time and file size for particles (x, z, u, w, id, C).
//   mpirun -n <ranks> bench_checkpoint [particles = 1000000] [repeats = 5] [path = bench_ckpt.h5]
// Prints the best of `repeats` for: write + commit, read of every rank's own slice, and read of
// an even split by ranges (what a restart on another rank count does).
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/io/checkpoint.hpp"

namespace {

const char* const kDoubles[] = {"particles/x", "particles/z", "particles/u", "particles/w",
                                "particles/C"};

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
    const picdem::core::Comm comm;
    const long long n = argc > 1 ? std::atoll(argv[1]) : 1000000;
    const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
    const std::string path = argc > 3 ? argv[3] : "bench_ckpt.h5";
    long long b, e;
    picdem::io::even_split(n, comm.rank(), comm.size(), b, e);
    std::vector<double> v(static_cast<std::size_t>(e - b));
    std::vector<std::int64_t> id(v.size());
    for (long long g = b; g < e; ++g) {
      v[static_cast<std::size_t>(g - b)] = 1e-3 * static_cast<double>(g);
      id[static_cast<std::size_t>(g - b)] = g;
    }
    const double t_write = best_of(repeats, comm, [&] {
      picdem::io::CheckpointWriter w(comm, path);
      for (const char* name : kDoubles) w.write(name, v);
      w.write("particles/id", id);
      w.attribute("time", 1.0);
      w.commit();
    });
    std::size_t sink = 0;
    const double t_slice = best_of(repeats, comm, [&] {
      picdem::io::CheckpointReader r(comm, path);
      for (const char* name : kDoubles) sink += r.read_slice_double(name).size();
      sink += r.read_slice_int64("particles/id").size();
    });
    // Ranges shifted by a third of a slice: every reader straddles two writers' slices.
    const double t_range = best_of(repeats, comm, [&] {
      picdem::io::CheckpointReader r(comm, path);
      const long long shift = (e - b) / 3;
      const long long rb = std::max(0LL, b - shift), re = std::max(0LL, e - shift);
      for (const char* name : kDoubles) sink += r.read_range_double(name, rb, re).size();
      sink += r.read_range_int64("particles/id", rb, re).size();
    });
    if (comm.is_root()) {
      const double mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
      const double per_m = 1e6 / static_cast<double>(n);
      std::printf(
          "checkpoint of %lld particles (x z u w C double, id int64) on %d rank(s), "
          "best of %d\n",
          n, comm.size(), repeats);
      std::printf("  file size      %8.2f MB   (%.2f MB per million particles, %.2f bytes each)\n",
                  mb, mb * per_m, mb * 1e6 / static_cast<double>(n));
      std::printf("  write+commit   %8.4f s    (%.4f s per million, %.0f MB/s)\n", t_write,
                  t_write * per_m, mb / t_write);
      std::printf("  read slices    %8.4f s    (%.4f s per million, %.0f MB/s)\n", t_slice,
                  t_slice * per_m, mb / t_slice);
      std::printf("  read ranges    %8.4f s    (%.4f s per million, %.0f MB/s)\n", t_range,
                  t_range * per_m, mb / t_range);
      std::printf("  (elements read %zu)\n", sink);
    }
  }
  MPI_Finalize();
  return 0;
}
