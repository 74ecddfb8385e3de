// SPDX-License-Identifier: MIT
// The IBM kernels keep their discrete moment conditions at every marker position.
#include <gtest/gtest.h>

#include <cmath>

#include "resolved/ibm/delta_kernel.hpp"

using namespace hs::resolved;

class DeltaKernelMoments : public ::testing::TestWithParam<int> {};

TEST_P(DeltaKernelMoments, PartitionOfUnityAndFirstMoment) {
  const DeltaKernel kernel = delta_kernel_from_points(GetParam());
  for (double x : {0.0, 0.13, 0.5, 0.77, 1.0, -0.3, -2.61, 41.999}) {
    const auto s = delta_stencil(kernel, {x, x + 0.25, x - 0.4});
    for (int d = 0; d < 3; ++d) {
      const double xd = (d == 0 ? x : d == 1 ? x + 0.25 : x - 0.4);
      double sum = 0.0, first = 0.0;
      for (int k = 0; k < s.points; ++k) {
        const double w = s.weight[static_cast<std::size_t>(d)][static_cast<std::size_t>(k)];
        EXPECT_GE(w, 0.0);
        sum += w;
        first += (s.base[static_cast<std::size_t>(d)] + k - xd) * w;
      }
      // Closed-form kernels: the moment identities hold to round-off (a few ulp of the sqrt).
      EXPECT_NEAR(sum, 1.0, 1e-14) << "x = " << xd;
      EXPECT_NEAR(first, 0.0, 1e-14) << "x = " << xd;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllKernels, DeltaKernelMoments, ::testing::Values(2, 3, 4));

TEST(DeltaKernel, KnownValues) {
  EXPECT_DOUBLE_EQ(delta_1d(DeltaKernel::four_point, 0.0), 0.5);    // (3 + 1)/8
  EXPECT_DOUBLE_EQ(delta_1d(DeltaKernel::four_point, 1.0), 0.25);   // (3 - 2 + sqrt(1))/8; phi(0) + 2 phi(1) = 1
  EXPECT_DOUBLE_EQ(delta_1d(DeltaKernel::four_point, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(delta_1d(DeltaKernel::three_point, 0.0), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(delta_1d(DeltaKernel::two_point, 0.25), 0.75);
  EXPECT_THROW(delta_kernel_from_points(5), std::invalid_argument);
}
