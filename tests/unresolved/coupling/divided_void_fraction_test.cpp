// SPDX-License-Identifier: MIT
// The divided (29-marker) void fraction: marker geometry and conservation of the solid volume.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>
#include <algorithm>

#include <omp.h>

#include "common/geometry/tube.hpp"
#include "unresolved/coupling/divided_void_fraction.hpp"

namespace {

using hs::common::Vec3;
using namespace hs::unresolved;

TEST(DividedMarkers, CentroidIsTheCentreAndMarkersLieInsideTheSphere) {
  Vec3 sum{};
  for (const Vec3& m : divided_markers()) {
    sum += m;
    EXPECT_LT(norm(m), 1.0);
  }
  // The marker set is symmetric: its centroid is the centre up to round-off (29 unit-size terms).
  EXPECT_NEAR(norm(sum), 0.0, 1e-14);
  // Radii: the centre, then 14 markers at each shell's volume centroid (3/4)(b^4 - a^4)/(b^3 - a^3), shells split
  // at (1/29)^(1/3) and (15/29)^(1/3) of the radius (equal volumes 1/29, 14/29, 14/29).
  const double r1 = std::cbrt(1.0 / 29.0);
  const double r2 = std::cbrt(15.0 / 29.0);
  const double inner = 0.75 * (std::pow(r2, 4) - std::pow(r1, 4)) / (std::pow(r2, 3) - std::pow(r1, 3));
  const double outer = 0.75 * (1.0 - std::pow(r2, 4)) / (1.0 - std::pow(r2, 3));
  int n_inner = 0;
  int n_outer = 0;
  for (const Vec3& m : divided_markers()) {
    n_inner += std::abs(norm(m) - inner) < 1e-14 ? 1 : 0;
    n_outer += std::abs(norm(m) - outer) < 1e-14 ? 1 : 0;
  }
  EXPECT_EQ(n_inner, 14);
  EXPECT_EQ(n_outer, 14);
  EXPECT_EQ(norm(divided_markers()[0]), 0.0);
}

TEST(DividedVoidFraction, SolidVolumeIsConservedAwayFromWalls) {
  const double r_tube = 25e-6;
  const double length = 40e-6;
  const hs::common::Tube tube({.start_m = {0, 0, 0}, .end_m = {0, 0, length}, .radius_m = r_tube});
  FvmGridSpec spec{.box_m = {{-r_tube, -r_tube, 0.0}, {r_tube, r_tube, length}}, .dx_m = 5e-6, .sides = {}};
  spec.sides[4].type = SideType::periodic;
  spec.sides[5].type = SideType::periodic;
  const FvmGrid grid(tube, spec);
  ParticleStore particles;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double radius = 2.8e-6;
  int n = 0;
  while (n < 30) {   // centres at least 2 radii + one cell inside the wall: every marker in a full cell
    const Vec3 x{12e-6 * u(rng), 12e-6 * u(rng), 0.5 * length * (1.0 + u(rng))};
    if (std::hypot(x.x, x.y) > 12e-6) continue;
    particles.add({.position_m = x, .velocity_m_s = {}, .angular_velocity_rad_s = {}, .radius_m = radius, .mass_kg = 1.0, .id = n});
    ++n;
  }
  DividedMap map(grid);
  map.locate(particles);
  BlockField<double> eps(grid.cells(), 1.0);
  const double lost = map.void_fraction(particles, 0.0, eps);
  EXPECT_EQ(lost, 0.0);
  double solid = 0.0;
  const auto& c = grid.cells();
  for (int k = 0; k < c[2]; ++k)
    for (int j = 0; j < c[1]; ++j)
      for (int i = 0; i < c[0]; ++i) {
        const std::size_t idx = eps.index(i, j, k);
        solid += (1.0 - eps[idx]) * map.fluid_volume_m3(idx);
      }
  const double expected = n * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  // Round-off of ~1e3 cell sums of O(1) relative terms: 1e-12 relative.
  EXPECT_NEAR(solid, expected, 1e-12 * expected);
}

TEST(DividedVoidFraction, ClippingReportsTheDroppedVolume) {
  const double h = 5e-6;
  const hs::common::Tube tube({.start_m = {0, 0, 0}, .end_m = {0, 0, 4 * h}, .radius_m = 2 * h});
  FvmGridSpec spec{.box_m = {{-2 * h, -2 * h, 0.0}, {2 * h, 2 * h, 4 * h}}, .dx_m = h, .sides = {}};
  spec.sides[4].type = SideType::periodic;
  spec.sides[5].type = SideType::periodic;
  const FvmGrid grid(tube, spec);
  ParticleStore particles;
  // Ten coincident spheres of radius 0.4 h at a cell centre: solid 10 x 0.268 h^3 > (1 - eps_min) h^3.
  for (int i = 0; i < 10; ++i) {
    particles.add({.position_m = {-0.5 * h, -0.5 * h, 1.5 * h}, .velocity_m_s = {}, .angular_velocity_rad_s = {},
                   .radius_m = 0.4 * h, .mass_kg = 1.0, .id = i});
  }
  DividedMap map(grid);
  map.locate(particles);
  BlockField<double> eps(grid.cells(), 1.0);
  const double lost = map.void_fraction(particles, 0.1, eps);
  const double solid = 10.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(0.4 * h, 3);
  const auto cell = grid.cell_of({-0.5 * h, -0.5 * h, 1.5 * h});
  ASSERT_TRUE(cell.has_value());
  EXPECT_DOUBLE_EQ(eps((*cell)[0], (*cell)[1], (*cell)[2]), 0.1);
  // All markers of a sphere of radius 0.4 h centred in a cell stay in it: lost = solid - 0.9 V_cell exactly.
  EXPECT_NEAR(lost, solid - 0.9 * h * h * h, 1e-12 * solid);
}

TEST(DividedVoidFraction, ThreadedCellSumsAreTheSerialLoopByIdBitForBit) {
  // Enough cells for the threaded path (> 4096 occupied): a 60 um tube, 2 um cells, 20000 spheres.
  const double r_tube = 30e-6;
  const double length = 60e-6;
  const hs::common::Tube tube({.start_m = {0, 0, 0}, .end_m = {0, 0, length}, .radius_m = r_tube});
  FvmGridSpec spec{.box_m = {{-r_tube, -r_tube, 0.0}, {r_tube, r_tube, length}}, .dx_m = 2e-6, .sides = {}};
  spec.sides[4].type = SideType::periodic;
  spec.sides[5].type = SideType::periodic;
  const FvmGrid grid(tube, spec);
  ParticleStore particles;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // Ids not in the store's order (the DEM sorts its particles by place): the sums go by id.
  std::vector<std::int64_t> ids(20000);
  std::iota(ids.begin(), ids.end(), 0);
  std::shuffle(ids.begin(), ids.end(), rng);
  for (int n = 0; n < 20000;) {
    const Vec3 x{27e-6 * u(rng), 27e-6 * u(rng), 0.5 * length * (1.0 + u(rng))};
    if (std::hypot(x.x, x.y) > 27e-6) continue;
    particles.add({.position_m = x, .velocity_m_s = {}, .angular_velocity_rad_s = {}, .radius_m = 1.0e-6 * (1.0 + 0.5 * u(rng)),
                   .mass_kg = 1.0, .id = ids[static_cast<std::size_t>(n)]});
    ++n;
  }
  // The serial loop: particles by id, each once per distinct cell of its markers with the markers it has there.
  DividedMap map(grid);
  map.locate(particles);
  std::vector<std::size_t> row_of_id(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) row_of_id[static_cast<std::size_t>(particles.id()[i])] = i;
  BlockField<double> serial(grid.cells(), 0.0);
  for (const std::size_t i : row_of_id) {
    std::map<std::size_t, int> markers;
    for (int m = 0; m < kMarkersPerSphere; ++m) ++markers[map.cell(i, m)];
    for (const auto& [c, n] : markers) serial[c] += n * particles.radius_m()[i] / map.fluid_volume_m3(c);
  }
  const int threads = omp_get_max_threads();
  for (const int t : {1, 2}) {
    omp_set_num_threads(t);
    DividedMap threaded(grid);
    threaded.locate(particles);
    BlockField<double> sum(grid.cells(), 0.0);
    threaded.for_each_cell([&](std::size_t c, std::size_t i, int markers) {
      sum[c] += markers * particles.radius_m()[i] / threaded.fluid_volume_m3(c);
    });
    std::size_t differ = 0;
    for (std::size_t c = 0; c < sum.data().size(); ++c) differ += sum[c] == serial[c] ? 0 : 1;
    EXPECT_EQ(differ, 0u) << t << " threads";   // same terms in the same order: the same bits
  }
  omp_set_num_threads(threads);
}

}  // namespace
