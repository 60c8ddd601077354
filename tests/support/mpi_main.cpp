// GoogleTest main for tests that need MPI only. Only rank 0 prints test progress, the other ranks
// their failures; a failure on any rank fails the run (the exit code is reduced over ranks).
#include <gtest/gtest.h>
#include <mpi.h>

#include "rank_failures.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  picdem::test::print_failures_only_off_root(rank);
  int local = RUN_ALL_TESTS();
  int global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return global;
}
