// STREAM-like triad a[i] = b[i] + s c[i] over arrays far larger than the caches, on every rank at
// once (each rank its own arrays): the memory bandwidth the particle and grid kernels are compared
// with in doc/performance.md. Bytes counted as STREAM does: 24 per element (read b and c, write
// a); the write-allocate read of a makes the traffic 32 bytes, also printed.
//   mpirun -n 1|2 build/drivers/bench/fluid/bench_triad [million elements per rank, default 16]
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const double millions = argc > 1 ? std::atof(argv[1]) : 16.0;
  const auto n = static_cast<std::size_t>(millions * 1e6);
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  const double s = 3.0;
  double best = 1e300;
  for (int rep = 0; rep < 10; ++rep) {
    MPI_Barrier(MPI_COMM_WORLD);  // the ranks run their triads at the same time
    const double t0 = MPI_Wtime();
    for (std::size_t i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
    double t = MPI_Wtime() - t0, slowest = 0.0;
    MPI_Allreduce(&t, &slowest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    best = std::min(best, slowest);
    b[rep % n] = a[(rep * 7) % n];  // keeps the loop from being hoisted
  }
  double check = a[n / 2], sum = 0.0;
  MPI_Allreduce(&check, &sum, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0)
    std::printf(
        "triad, %d rank(s), %.0f M elements each (%.0f MB per rank): best of 10 %.4f s, "
        "%.1f GB/s counted as STREAM (24 B/element), %.1f GB/s with write-allocate (32 B), "
        "all ranks together (check %.1f)\n",
        ranks, millions, 24.0 * static_cast<double>(n) / 1e6, best,
        24.0 * static_cast<double>(n) * ranks / best / 1e9,
        32.0 * static_cast<double>(n) * ranks / best / 1e9, sum);
  MPI_Finalize();
  return 0;
}
