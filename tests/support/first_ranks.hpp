#pragma once
// Runs part of a rank test on the first `ranks` ranks of the world only, so one mpirun holds runs
// on 1, 2, ... ranks side by side; and broadcasts rank 0's figures to every rank for comparison.
#include <mpi.h>

#include <vector>

namespace picdem::test_support {

/// Calls body(sub) on the members of a communicator of the world's first `ranks` ranks (ranks
/// beyond it do nothing), then frees the communicator. Collective over MPI_COMM_WORLD.
template <class Body>
void on_first_ranks(int ranks, Body&& body) {
  MPI_Group world, group;
  MPI_Comm_group(MPI_COMM_WORLD, &world);
  std::vector<int> members(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r) members[static_cast<std::size_t>(r)] = r;
  MPI_Group_incl(world, ranks, members.data(), &group);
  MPI_Comm sub;
  MPI_Comm_create(MPI_COMM_WORLD, group, &sub);
  if (sub != MPI_COMM_NULL) {
    body(sub);
    MPI_Comm_free(&sub);
  }
  MPI_Group_free(&group);
  MPI_Group_free(&world);
}

/// World rank 0's vector (size and values) on every rank.
template <class T>
void broadcast_from_root(std::vector<T>& v, MPI_Datatype type) {
  int n = static_cast<int>(v.size());
  MPI_Bcast(&n, 1, MPI_INT, 0, MPI_COMM_WORLD);
  v.resize(static_cast<std::size_t>(n));
  MPI_Bcast(v.data(), n, type, 0, MPI_COMM_WORLD);
}

}  // namespace picdem::test_support
