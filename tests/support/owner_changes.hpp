#pragma once
// Rank tests (issue 14): what each rank owns at the start and at the end of a run, and how many
// particles or solids changed owner in between (migrated across a rank boundary, or handed over
// when the cut lines moved), so that a test can assert that its run exercised migration.
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace picdem::test_support {

/// What one rank owns at one moment: the ids, sorted.
struct Holding {
  std::vector<std::int64_t> ids;
};

template <class Ids>
Holding holding(const Ids& ids) {
  Holding h;
  h.ids.assign(ids.begin(), ids.end());
  std::sort(h.ids.begin(), h.ids.end());
  return h;
}

/// Every rank's count of owned items, on every rank of `comm`.
inline std::vector<long long> counts(MPI_Comm comm, const Holding& h) {
  int n = 0;
  MPI_Comm_size(comm, &n);
  std::vector<long long> all(static_cast<std::size_t>(n));
  long long mine = static_cast<long long>(h.ids.size());
  MPI_Allgather(&mine, 1, MPI_LONG_LONG, all.data(), 1, MPI_LONG_LONG, comm);
  return all;
}

/// Over `comm`: the items owned at `after` by another rank than at `before`. An id this rank
/// owns after but did not own before was owned by another rank before, unless it is new (ids
/// above every id at `before`: reseeded particles); removed items are not counted.
inline long long owner_changes(MPI_Comm comm, const Holding& before, const Holding& after) {
  long long top = before.ids.empty() ? -1 : static_cast<long long>(before.ids.back());
  MPI_Allreduce(MPI_IN_PLACE, &top, 1, MPI_LONG_LONG, MPI_MAX, comm);
  long long arrived = 0;
  for (const auto id : after.ids)
    if (id <= top && !std::binary_search(before.ids.begin(), before.ids.end(), id)) ++arrived;
  MPI_Allreduce(MPI_IN_PLACE, &arrived, 1, MPI_LONG_LONG, MPI_SUM, comm);
  return arrived;
}

}  // namespace picdem::test_support
