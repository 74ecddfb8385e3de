// SPDX-License-Identifier: MIT
// Membrane frames of a cell in a periodic lattice are drawn inside the fluid's box (#31: a tube-drag cell at z 70-78 um
// in a 0-49 um lattice): the whole mesh moves by whole periods along the periodic axes only.
#include <gtest/gtest.h>

#include <vector>

#include "resolved/cases/cell_simulation.hpp"

using hs::common::Vec3;

TEST(CellFrames, PeriodicAxesWrapTheWholeMeshIntoTheBox) {
  // A 4 um "cell" around z = 74 um in a lattice of 50 nodes at 1 um along z (period 50 um), periodic in z only;
  // x lies outside its box too but is a wall axis: left alone.
  const std::vector<Vec3> x{{-30e-6, 0.0, 72e-6}, {-30e-6, 0.0, 76e-6}, {-30e-6, 1e-6, 74e-6}};
  const auto w = hs::resolved::wrapped_into_box(x, {-27e-6, -27e-6, 0.0}, {55, 55, 50}, 1e-6, {false, false, true});
  ASSERT_EQ(w.size(), x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_NEAR(w[i].z, x[i].z - 50e-6, 1e-18) << i;   // one period back: 22-26 um, inside 0-50 um
    EXPECT_EQ(w[i].x, x[i].x) << i;
    EXPECT_EQ(w[i].y, x[i].y) << i;
  }
  // Behind the box (negative z) it moves forward; inside the box it stays.
  const auto back = hs::resolved::wrapped_into_box({{0.0, 0.0, -1e-6}}, {0.0, 0.0, 0.0}, {1, 1, 50}, 1e-6, {false, false, true});
  EXPECT_NEAR(back[0].z, 49e-6, 1e-18);
  const auto inside = hs::resolved::wrapped_into_box({{0.0, 0.0, 10e-6}}, {0.0, 0.0, 0.0}, {1, 1, 50}, 1e-6, {false, false, true});
  EXPECT_EQ(inside[0].z, 10e-6);
}
