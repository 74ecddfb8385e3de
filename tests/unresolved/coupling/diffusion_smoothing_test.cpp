// SPDX-License-Identifier: MIT
// The coupling fields' smoothing: a physical footprint on every grid, conservation, bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "common/geometry/tube.hpp"
#include "unresolved/coupling/diffusion_smoothing.hpp"
#include "../everywhere_shape.hpp"

namespace {

using hs::common::Vec3;
using namespace hs::unresolved;

using hs::test::Everywhere;

/// A periodic slab, `cells` along x and 2 across: a plane source at x index 0, smoothed over l.
struct PlaneSource {
  std::vector<double> profile;   // q along x (the first row of cells)
  double dx;
};
PlaneSource smooth_plane_source(double length_m, double l_m, int cells) {
  const double dx = length_m / cells;
  const hs::common::Box3 box{{0, 0, 0}, {length_m, 2 * dx, 2 * dx}};
  const Everywhere shape;
  FvmGridSpec spec{.box_m = box, .dx_m = dx, .sides = {}};
  for (auto& side : spec.sides) side.type = SideType::periodic;
  const FvmGrid grid(shape, spec);
  BlockField<double> q(grid.cells(), 0.0);
  for (int j = 0; j < 2; ++j) {
    for (int k = 0; k < 2; ++k) q(0, j, k) = 1.0 / dx;   // unit amount per unit area
  }
  DiffusionSmoothing smoothing(grid, l_m);
  smoothing.smooth(q);
  PlaneSource out{.profile = {}, .dx = dx};
  for (int i = 0; i < cells; ++i) out.profile.push_back(q(i, 0, 0));
  return out;
}

// The continuous kernel of q - l^2 q'' = delta is exp(-|x| / l) / (2 l): variance 2 l^2. The discrete flux form has
// the same second moment exactly (sum_i i^2 (q_{i+1} - 2 q_i + q_{i-1}) = 2 sum_i q_i), so on every grid the footprint
// is l, not a number of cells. The periodic box is 40 l long: the wrapped tail is e^-20 of the peak, ~1e-7 of the
// moment at most; the CG tolerance (1e-13) is far below. Band 1e-6.
/// A D = 30 um tube, 60 um long and periodic along its axis, at dx = 2 um: cut cells at the wall.
FvmGrid periodic_tube_grid() {
  const double r = 15e-6;
  const double length = 60e-6;
  const hs::common::Tube tube({.start_m = {0, 0, 0}, .end_m = {0, 0, length}, .radius_m = r});
  FvmGridSpec spec{.box_m = {{-r, -r, 0.0}, {r, r, length}}, .dx_m = 2e-6, .sides = {}};
  spec.sides[4].type = SideType::periodic;
  spec.sides[5].type = SideType::periodic;
  return FvmGrid(tube, spec);
}

TEST(DiffusionSmoothing, APlaneSourceSpreadsOverTheSmoothingLengthOnEveryGrid) {
  const double l = 3e-6;
  for (const int per_length : {1, 2, 4}) {   // dx = l, l / 2, l / 4
    const int cells = 40 * per_length;
    const PlaneSource s = smooth_plane_source(40.0 * l, l, cells);
    double mass = 0.0;
    double second = 0.0;
    for (int i = 0; i < cells; ++i) {
      const double x = std::min(i, cells - i) * s.dx;   // distance from the plane, periodic
      mass += s.profile[static_cast<std::size_t>(i)] * s.dx;
      second += x * x * s.profile[static_cast<std::size_t>(i)] * s.dx;
    }
    EXPECT_NEAR(mass, 1.0, 1e-12) << "dx = l / " << per_length;
    EXPECT_NEAR(second / mass / (2.0 * l * l), 1.0, 1e-6) << "dx = l / " << per_length;
    // The discrete decay ratio rho of adjacent cells solves rho + 1 / rho = 2 + dx^2 / l^2.
    const double b = 2.0 + s.dx * s.dx / (l * l);
    const double rho = 0.5 * (b - std::sqrt(b * b - 4.0));
    EXPECT_NEAR(s.profile[2] / s.profile[1], rho, 1e-9) << "dx = l / " << per_length;
  }
}

// A random field in a tube (cut cells at the wall, periodic along the axis): the fluid-volume integral is kept to the
// solver's round-off (1e-13 relative residual over ~2000 cells: 1e-11 band), and every value stays within the old
// extremes (the operator is an M-matrix: a discrete maximum principle), so a void fraction stays in [eps_min, 1].
// The spread shrinks in the full cells (a cut cell whose faces are all closed keeps its value: nothing can leave it).
TEST(DiffusionSmoothing, ConservesTheFieldAndKeepsItsBoundsInATube) {
  const FvmGrid grid = periodic_tube_grid();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.1, 1.0);
  BlockField<double> q(grid.cells(), 0.0);
  const auto& n = grid.cells();
  const auto& fraction = grid.fluid_fractions();
  auto integral = [&](const BlockField<double>& f) {
    double s = 0.0;
    for (int k = 0; k < n[2]; ++k) {
      for (int j = 0; j < n[1]; ++j) {
        for (int i = 0; i < n[0]; ++i) s += fraction(i, j, k) * f(i, j, k);
      }
    }
    return s;
  };
  int fluid_cells = 0;
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        if (fraction(i, j, k) <= 0.0) continue;
        q(i, j, k) = u(rng);
        ++fluid_cells;
      }
    }
  }
  ASSERT_GT(fluid_cells, 1500);
  const double before = integral(q);
  DiffusionSmoothing smoothing(grid, 5e-6);
  smoothing.smooth(q);
  EXPECT_NEAR(integral(q) / before, 1.0, 1e-11);
  double lo = 1.0;
  double hi = 0.0;
  double full_lo = 1.0;
  double full_hi = 0.0;
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        if (fraction(i, j, k) <= 0.0) continue;
        lo = std::min(lo, q(i, j, k));
        hi = std::max(hi, q(i, j, k));
        if (fraction(i, j, k) < 1.0) continue;
        full_lo = std::min(full_lo, q(i, j, k));
        full_hi = std::max(full_hi, q(i, j, k));
      }
    }
  }
  EXPECT_GE(lo, 0.1);
  EXPECT_LE(hi, 1.0);
  // And it did smooth: 5 um over 2 um cells averages ~100 cells of a uniform 0.1-1.0 field (sd 0.26): the full cells'
  // range falls well below 0.9 (0.2 is ~8 sd of such a mean).
  EXPECT_LT(full_hi - full_lo, 0.2);
}

// Several fields in one multi-right-hand-side solve give what each gives alone, and the factor gives what CG gives:
// in CG every column is its own CG (own alpha, beta, stopping test), only the pass over the operator is shared; the
// factor's result is checked against the same residual. The arithmetic differs at round-off, so the band is the
// solver's: a
// relative residual of 1e-13 bounds each solution's error by kappa 1e-13 of its size, kappa <= 1 + 12 l^2 / dx^2 = 76
// for the Jacobi-scaled operator here (l = 5 um, dx = 2 um): 8e-12 each, 2e-11 between the two. A zero field stays 0.
TEST(DiffusionSmoothing, TogetherAndByTheFactorEqualEachAloneByConjugateGradients) {
  const FvmGrid grid = periodic_tube_grid();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  BlockField<double> scalar(grid.cells(), 0.0);
  BlockField<double> zero(grid.cells(), 0.0);
  BlockField<Vec3> vector(grid.cells(), Vec3{});
  const auto& n = grid.cells();
  const auto& fraction = grid.fluid_fractions();
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        if (fraction(i, j, k) <= 0.0) continue;
        scalar(i, j, k) = u(rng);
        // A sparse field like the exchanged impulses: nonzero in one cell of ten.
        if (u(rng) > 0.8) vector(i, j, k) = Vec3{u(rng), 1e3 * u(rng), 1e-3 * u(rng)};
      }
    }
  }
  // The reference: each field alone by CG. Then all together by CG (the multi-right-hand-side CG) and by the
  // factor (this grid's ~1800 rows are within kDirectMaxRows), alone and together.
  DiffusionSmoothing cg(grid, 5e-6, DiffusionSmoothing::Method::conjugate_gradient);
  DiffusionSmoothing factor(grid, 5e-6);
  ASSERT_FALSE(cg.direct());
  ASSERT_TRUE(factor.direct());
  BlockField<double> scalar_alone = scalar;
  BlockField<Vec3> vector_alone = vector;
  cg.smooth(scalar_alone);
  cg.smooth(vector_alone);
  EXPECT_GT(cg.last_iterations(), 0);
  std::array<double, 4> largest{};   // each column's largest value: the band is relative to it
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        largest[0] = std::max(largest[0], std::abs(scalar_alone(i, j, k)));
        for (int a = 0; a < 3; ++a) {
          largest[static_cast<std::size_t>(a) + 1] = std::max(largest[static_cast<std::size_t>(a) + 1],
                                                              std::abs(vector_alone(i, j, k)[a]));
        }
      }
    }
  }
  const auto expect_same = [&](const BlockField<double>& s_out, const BlockField<double>& z_out,
                               const BlockField<Vec3>& v_out, const char* how) {
    for (int k = 0; k < n[2]; ++k) {
      for (int j = 0; j < n[1]; ++j) {
        for (int i = 0; i < n[0]; ++i) {
          ASSERT_NEAR(s_out(i, j, k), scalar_alone(i, j, k), 2e-11 * largest[0]) << how;
          ASSERT_EQ(z_out(i, j, k), 0.0) << how;
          for (int a = 0; a < 3; ++a) {
            ASSERT_NEAR(v_out(i, j, k)[a], vector_alone(i, j, k)[a], 2e-11 * largest[static_cast<std::size_t>(a) + 1])
                << how;
          }
        }
      }
    }
  };
  for (DiffusionSmoothing* smoothing : {&cg, &factor}) {
    BlockField<double> s_together = scalar;
    BlockField<double> z_together = zero;
    BlockField<Vec3> v_together = vector;
    smoothing->smooth_together({&s_together, &z_together}, {&v_together});
    expect_same(s_together, z_together, v_together, smoothing->direct() ? "factor, together" : "CG, together");
    BlockField<double> s_alone = scalar;
    BlockField<Vec3> v_alone = vector;
    smoothing->smooth(s_alone);
    smoothing->smooth(v_alone);
    expect_same(s_alone, zero, v_alone, smoothing->direct() ? "factor, alone" : "CG, alone");
  }
}

TEST(DiffusionSmoothing, RefusesANonPositiveLength) {
  const hs::common::Box3 box{{0, 0, 0}, {4e-6, 4e-6, 4e-6}};
  const Everywhere shape;
  FvmGridSpec spec{.box_m = box, .dx_m = 1e-6, .sides = {}};
  for (auto& side : spec.sides) side.type = SideType::periodic;
  const FvmGrid grid(shape, spec);
  EXPECT_ANY_THROW(DiffusionSmoothing(grid, 0.0));
}

}  // namespace
