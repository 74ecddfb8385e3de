// SPDX-License-Identifier: MIT
// GoogleTest main for the FVM tests: hypre needs MPI initialised, as the hemoscale executable does.
#include <mpi.h>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  const int code = RUN_ALL_TESTS();
  MPI_Finalize();
  return code;
}
