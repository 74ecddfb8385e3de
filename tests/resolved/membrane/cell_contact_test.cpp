// SPDX-License-Identifier: MIT
// Cell-cell contact: the binned search finds exactly the pairs a brute-force search finds (also across periodic
// boundaries), the forces are equal and opposite, and two spheres pushed together repel along their axis.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <span>
#include <vector>

#include "resolved/membrane/cell_contact.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"
#include "resolved/membrane/triangle_mesh.hpp"

namespace hr = hs::resolved;
using hs::common::Vec3;

namespace {

// The O(N^2) reference: every vertex pair of different cells, minimum image along periodic axes.
std::vector<std::vector<Vec3>> brute_force(const std::vector<std::vector<Vec3>>& cells, const hr::CellContactSpec& s) {
  std::vector<std::vector<Vec3>> f;
  for (const auto& c : cells) f.emplace_back(c.size());
  for (std::size_t a = 0; a < cells.size(); ++a) {
    for (std::size_t b = a + 1; b < cells.size(); ++b) {
      for (std::size_t i = 0; i < cells[a].size(); ++i) {
        for (std::size_t j = 0; j < cells[b].size(); ++j) {
          Vec3 d = cells[a][i] - cells[b][j];
          for (int k = 0; k < 3; ++k) {
            if (s.period_m[k] > 0.0) d[k] -= s.period_m[k] * std::round(d[k] / s.period_m[k]);
          }
          const double r = hs::common::norm(d);
          if (r >= s.range_m || r == 0.0) continue;
          const Vec3 force = (s.stiffness_N_m * (s.range_m - r) / r) * d;
          f[a][i] += force;
          f[b][j] -= force;
        }
      }
    }
  }
  return f;
}

std::vector<std::span<const Vec3>> spans(const std::vector<std::vector<Vec3>>& cells) {
  return {cells.begin(), cells.end()};
}

}  // namespace

TEST(CellContact, BinnedSearchEqualsBruteForceAlsoAcrossPeriodicFaces) {
  // Three clouds of 400 vertices in a 10 x 3 x 10 um box, periodic along x and y (3 um: only 3 bins of 1 um, the
  // smallest count where the 27 neighbour bins are distinct), open along z.
  hr::CellContactSpec spec{.range_m = 1e-6, .stiffness_N_m = 2e-6, .period_m = {10e-6, 3e-6, 0.0}};
  std::mt19937_64 rng(9);
  std::vector<std::vector<Vec3>> cells(3);
  for (auto& c : cells) {
    for (int v = 0; v < 400; ++v) {
      c.push_back({std::uniform_real_distribution<double>(-2e-6, 12e-6)(rng),
                   std::uniform_real_distribution<double>(0.0, 3e-6)(rng),
                   std::uniform_real_distribution<double>(0.0, 10e-6)(rng)});
    }
  }
  std::vector<std::vector<Vec3>> f;
  for (const auto& c : cells) f.emplace_back(c.size());
  const auto report = hr::add_cell_contact_forces(spans(cells), f, spec);
  const auto reference = brute_force(cells, spec);
  ASSERT_GT(report.pairs, 100);
  Vec3 total;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (std::size_t v = 0; v < cells[c].size(); ++v) {
      // Same pairs summed in another order: round-off of a few terms of ~1e-12 N.
      EXPECT_NEAR(f[c][v].x, reference[c][v].x, 1e-20);
      EXPECT_NEAR(f[c][v].y, reference[c][v].y, 1e-20);
      EXPECT_NEAR(f[c][v].z, reference[c][v].z, 1e-20);
      total += f[c][v];
    }
  }
  EXPECT_LT(hs::common::norm(total), 1e-20);   // equal and opposite: no net force on the cells
}

TEST(CellContact, TwoSpheresPushedTogetherRepelAlongTheirAxis) {
  // Two 4 um spheres (642 vertices, ~0.55 um apart on the surface) with centres 8.2 um apart along x: their
  // surfaces are 0.2 um apart, inside d0 = 0.5 um. Each is pushed away from the other, only along x (symmetry),
  // and no vertex of one is nearer than the gap to the other.
  hr::TriangleMesh sphere = hr::make_sphere_mesh(642);
  std::vector<std::vector<Vec3>> cells(2);
  for (const auto& v : sphere.vertices_m) {
    cells[0].push_back(hs::common::normalized(v) * 4e-6);
    cells[1].push_back(hs::common::normalized(v) * 4e-6 + Vec3{8.2e-6, 0.0, 0.0});
  }
  std::vector<std::vector<Vec3>> f{std::vector<Vec3>(642), std::vector<Vec3>(642)};
  const auto report = hr::add_cell_contact_forces(spans(cells), f, {.range_m = 0.5e-6, .stiffness_N_m = 1e-5});
  Vec3 on0, on1;
  for (const auto& v : f[0]) on0 += v;
  for (const auto& v : f[1]) on1 += v;
  EXPECT_LT(on0.x, 0.0);
  EXPECT_GT(on1.x, 0.0);
  EXPECT_NEAR(on0.x, -on1.x, 1e-12 * std::abs(on0.x));
  EXPECT_LT(std::abs(on0.y) + std::abs(on0.z), 1e-6 * std::abs(on0.x));
  EXPECT_GE(report.min_distance_m, 0.2e-6 * (1.0 - 1e-9));   // the closest vertices are the two poles
  EXPECT_LT(report.min_distance_m, 0.5e-6);
  // Off: nothing added.
  std::vector<std::vector<Vec3>> none{std::vector<Vec3>(642), std::vector<Vec3>(642)};
  EXPECT_EQ(hr::add_cell_contact_forces(spans(cells), none, {}).pairs, 0);
}
