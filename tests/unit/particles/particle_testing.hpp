#pragma once
// Helpers shared by the particle tests: the union of every rank's particles, sorted by id, and a
// single-rank reference decomposition of the same grid.
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "picdem/particles/particle_set.hpp"

namespace picdem::particles::ptest {

/// One particle as seen by a test.
struct Row {
  std::int64_t id;
  double x, z, u, w;
};

/// Every rank's particles, sorted by id, on every rank.
inline std::vector<Row> gather_all(const ParticleSet& p, const core::Comm& comm) {
  std::vector<double> mine;
  mine.reserve(5 * p.size());
  for (std::size_t n = 0; n < p.size(); ++n)
    for (double v : {static_cast<double>(p.id[n]), p.x[n], p.z[n], p.u[n], p.w[n]})
      mine.push_back(v);
  const std::vector<double> all = comm.all_gather(mine);
  std::vector<Row> rows(all.size() / 5);
  for (std::size_t n = 0; n < rows.size(); ++n)
    rows[n] = {static_cast<std::int64_t>(all[5 * n]), all[5 * n + 1], all[5 * n + 2],
               all[5 * n + 3], all[5 * n + 4]};
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.id < b.id; });
  return rows;
}

/// This rank alone, holding the whole grid: the reference every rank count must reproduce.
inline core::Comm self_comm() {
  return core::Comm(MPI_COMM_SELF);
}

}  // namespace picdem::particles::ptest
