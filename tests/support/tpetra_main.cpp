// GoogleTest main for tests that use Tpetra: Tpetra::ScopeGuard initialises MPI and Kokkos.
#include <gtest/gtest.h>
#include <Tpetra_Core.hpp>

#include "rank_failures.hpp"

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  picdem::test::print_failures_only_off_root(rank);
  int local = RUN_ALL_TESTS();
  int global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return global;
}
