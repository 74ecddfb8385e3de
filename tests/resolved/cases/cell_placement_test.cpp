// SPDX-License-Identifier: MIT
// Placement of many cells: the hematocrit asked is reached to within one cell, no two cells overlap (checked by an
// independent inside test: the solid-angle winding number), every vertex keeps the wall clearance, the same seed gives
// the same cells, and a hematocrit the box cannot hold is refused with a message.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>

#include "resolved/cases/cell_placement.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"

namespace hr = hs::resolved;
using hs::common::Vec3;

namespace {

/// Generalised winding number of a closed mesh about p: 1 inside, 0 outside (Van Oosterom & Strackee 1983 solid
/// angles, summed over the triangles and divided by 4 pi).
double winding_number(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles, const Vec3& p) {
  double sum = 0.0;
  for (const auto& t : triangles) {
    const Vec3 a = x[t[0]] - p, b = x[t[1]] - p, c = x[t[2]] - p;
    const double la = hs::common::norm(a), lb = hs::common::norm(b), lc = hs::common::norm(c);
    const double num = hs::common::dot(a, hs::common::cross(b, c));
    const double den = la * lb * lc + hs::common::dot(a, b) * lc + hs::common::dot(b, c) * la + hs::common::dot(c, a) * lb;
    sum += 2.0 * std::atan2(num, den);
  }
  return sum / (4.0 * std::numbers::pi);
}

// The shear-suspension box: 24 x 24 x 16 um, periodic in x and z, plates at y = 0 and 24 um.
const hr::PlacementBox kBox{.lower_m = {0.0, 0.0, 0.0}, .upper_m = {24e-6, 24e-6, 16e-6}, .periodic = {true, false, true}};

Vec3 minimum_image(Vec3 d, const hr::PlacementBox& box) {
  for (int a = 0; a < 3; ++a) {
    const double l = box.upper_m[a] - box.lower_m[a];
    if (box.periodic[a]) d[a] -= l * std::round(d[a] / l);
  }
  return d;
}

/// The placement's promises on the true meshes: every vertex keeps the clearance from the plates, vertices of
/// different cells keep the gap, and no vertex lies inside another cell (winding number, for the vertices within the
/// other cell's bounding sphere, nearest periodic image). Each cell is the rest mesh turned and moved: its edge
/// lengths are the rest mesh's (full size, undeformed).
void expect_clear(const hr::TriangleMesh& rest, const hr::Placement& p, const hr::PlacementSpec& spec,
                  const hr::PlacementBox& box = kBox) {
  EXPECT_GE(hr::min_intercell_distance_m(p.cells_m, box), spec.min_gap_m);
  long near = 0;
  for (std::size_t a = 0; a < p.cells_m.size(); ++a) {
    const auto& xa = p.cells_m[a];
    for (const auto& t : rest.triangles) {
      for (int e = 0; e < 3; ++e) {
        const double rest_edge = hs::common::norm(rest.vertices_m[t[e]] - rest.vertices_m[t[(e + 1) % 3]]);
        ASSERT_NEAR(hs::common::norm(xa[t[e]] - xa[t[(e + 1) % 3]]), rest_edge, 1e-9 * rest_edge);
      }
    }
    Vec3 centre;
    for (const auto& v : xa) centre += v / static_cast<double>(xa.size());
    double radius = 0.0;
    for (const auto& v : xa) {
      radius = std::max(radius, hs::common::norm(v - centre));
      for (int k = 0; k < 3; ++k) {
        if (box.periodic[k]) continue;
        ASSERT_GE(v[k], box.lower_m[k] + spec.wall_clearance_m);
        ASSERT_LE(v[k], box.upper_m[k] - spec.wall_clearance_m);
      }
    }
    for (std::size_t b = 0; b < p.cells_m.size(); ++b) {
      if (a == b) continue;
      for (const auto& v : p.cells_m[b]) {
        const Vec3 d = minimum_image(v - centre, box);
        if (hs::common::norm(d) > radius) continue;
        ++near;
        ASSERT_LT(winding_number(xa, rest.triangles, centre + d), 0.5)
            << "a vertex of cell " << b << " lies inside cell " << a;
      }
    }
  }
  std::printf("[placement] %ld vertices within another cell's bounding sphere, none inside it\n", near);
}

}  // namespace

TEST(CellPlacement, ReachesTheHematocritWithoutOverlaps) {
  const hr::TriangleMesh rbc = hr::make_rbc_mesh({});
  const hr::PlacementSpec spec{.hematocrit = 0.15, .min_gap_m = 0.5e-6, .wall_clearance_m = 2e-6, .seed = 3};
  const hr::Placement p = hr::place_cells(rbc, kBox, spec);
  const double one_cell = p.cell_volume_m3 / p.box_volume_m3;
  // N = round(phi V_box / V_cell): within half a cell of the target.
  EXPECT_NEAR(p.hematocrit, 0.15, 0.5 * one_cell + 1e-12);
  ASSERT_EQ(static_cast<double>(p.cells_m.size()), std::round(0.15 / one_cell));
  EXPECT_GE(hr::min_intercell_distance_m(p.cells_m, kBox), spec.min_gap_m);
  bool crosses_a_face = false;
  for (std::size_t a = 0; a < p.cells_m.size(); ++a) {
    for (const auto& v : p.cells_m[a]) {
      EXPECT_GE(v.y, spec.wall_clearance_m);
      EXPECT_LE(v.y, 24e-6 - spec.wall_clearance_m);
      crosses_a_face = crosses_a_face || v.x < 0.0 || v.x > 24e-6 || v.z < 0.0 || v.z > 16e-6;
    }
    // No vertex of another cell (moved by whole periods next to this one) inside this cell.
    for (std::size_t b = 0; b < p.cells_m.size(); ++b) {
      if (a == b) continue;
      for (const auto& v : p.cells_m[b]) {
        for (const double sx : {-24e-6, 0.0, 24e-6}) {
          for (const double sz : {-16e-6, 0.0, 16e-6}) {
            ASSERT_LT(winding_number(p.cells_m[a], rbc.triangles, v + Vec3{sx, 0.0, sz}), 0.5)
                << "a vertex of cell " << b << " lies inside cell " << a;
          }
        }
      }
    }
  }
  EXPECT_TRUE(crosses_a_face) << "at phi 0.15 some cell should straddle a periodic face (unwrapped vertices)";
  std::printf("[placement] %zu cells, hematocrit %.4f, %ld tries\n", p.cells_m.size(), p.hematocrit, p.attempts);
}

TEST(CellPlacement, SameSeedSameCells) {
  const hr::TriangleMesh rbc = hr::make_rbc_mesh({});
  const hr::PlacementSpec spec{.hematocrit = 0.1, .min_gap_m = 0.5e-6, .wall_clearance_m = 2e-6, .seed = 7};
  const auto a = hr::place_cells(rbc, kBox, spec);
  const auto b = hr::place_cells(rbc, kBox, spec);
  ASSERT_EQ(a.cells_m.size(), b.cells_m.size());
  for (std::size_t c = 0; c < a.cells_m.size(); ++c) {
    for (std::size_t v = 0; v < a.cells_m[c].size(); ++v) {
      for (int k = 0; k < 3; ++k) ASSERT_EQ(a.cells_m[c][v][k], b.cells_m[c][v][k]);
    }
  }
}

TEST(CellPlacement, PacksAQuarterOfTheShearBoxWithoutOverlaps) {
  // phi 0.25 (25 cells): beyond random sequential addition's 0.179 in this box, so the growth packing places them.
  const hr::TriangleMesh rbc = hr::make_rbc_mesh({});
  for (const std::uint64_t seed : {1ULL, 2ULL}) {
    const hr::PlacementSpec spec{.hematocrit = 0.25, .min_gap_m = 0.5e-6, .wall_clearance_m = 2e-6, .seed = seed};
    const auto start = std::chrono::steady_clock::now();
    const hr::Placement p = hr::place_cells(rbc, kBox, spec);
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(p.method, hr::PlacementMethod::growth_packing);
    ASSERT_EQ(p.cells_m.size(), 25U);
    EXPECT_NEAR(p.hematocrit, 25.0 * p.cell_volume_m3 / p.box_volume_m3, 1e-12);
    expect_clear(rbc, p, spec);
    std::printf("[packing] seed %llu: %zu cells, hematocrit %.4f, start size %.3f, %ld sweeps, %.2f s\n",
                static_cast<unsigned long long>(seed), p.cells_m.size(), p.hematocrit, p.packing_start_scale,
                p.packing_sweeps, wall_s);
  }
}

TEST(CellPlacement, PacksOtherBoxes) {
  // Any box: periodic along all three axes (13 cells at phi 0.3 in 16 um cubed), and walled on all six faces (a 20 um
  // cube with 1 um clearance, 17 cells at phi 0.2; random sequential addition stops at 10 cells, 0.115).
  const hr::TriangleMesh rbc = hr::make_rbc_mesh({});
  const hr::PlacementBox periodic{.lower_m = {0.0, 0.0, 0.0}, .upper_m = {16e-6, 16e-6, 16e-6},
                                  .periodic = {true, true, true}};
  const hr::PlacementBox walled{.lower_m = {-10e-6, -10e-6, -10e-6}, .upper_m = {10e-6, 10e-6, 10e-6}, .periodic = {}};
  for (const auto& [box, phi, clearance] : {std::tuple{periodic, 0.3, 0.0}, std::tuple{walled, 0.2, 1e-6}}) {
    const hr::PlacementSpec spec{.hematocrit = phi, .min_gap_m = 0.5e-6, .wall_clearance_m = clearance, .seed = 4};
    const hr::Placement p = hr::place_cells(rbc, box, spec);
    expect_clear(rbc, p, spec, box);
    std::printf("[packing] %zu cells, hematocrit %.4f, %s, %ld sweeps\n", p.cells_m.size(), p.hematocrit,
                hr::placement_method_name(p.method), p.packing_sweeps);
  }
}

TEST(CellPlacement, SameSeedSamePacking) {
  const hr::TriangleMesh rbc = hr::make_rbc_mesh({});
  const hr::PlacementSpec spec{.hematocrit = 0.22, .min_gap_m = 0.5e-6, .wall_clearance_m = 2e-6, .seed = 5};
  const auto a = hr::place_cells(rbc, kBox, spec);
  const auto b = hr::place_cells(rbc, kBox, spec);
  ASSERT_EQ(a.method, hr::PlacementMethod::growth_packing);
  ASSERT_EQ(a.cells_m.size(), b.cells_m.size());
  EXPECT_EQ(a.packing_sweeps, b.packing_sweeps);
  for (std::size_t c = 0; c < a.cells_m.size(); ++c) {
    for (std::size_t v = 0; v < a.cells_m[c].size(); ++v) {
      for (int k = 0; k < 3; ++k) ASSERT_EQ(a.cells_m[c][v][k], b.cells_m[c][v][k]);
    }
  }
}

TEST(CellPlacement, RefusesWhatTheBoxCannotHold) {
  const hr::TriangleMesh rbc = hr::make_rbc_mesh({});
  // 0.6 of the box in discs 0.5 um apart: beyond random sequential addition, and the growth packing stalls near
  // 0.35 in this box (measured; a budget of 300 sweeps keeps the test short, the message is the same).
  const hr::PlacementSpec full{.hematocrit = 0.6, .min_gap_m = 0.5e-6, .wall_clearance_m = 2e-6, .seed = 1,
                               .attempts_per_cell = 300, .max_packing_sweeps = 300};
  try {
    (void)hr::place_cells(rbc, kBox, full);
    FAIL() << "placement at phi 0.6 should be impossible";
  } catch (const hr::PlacementImpossible& e) {
    const std::string what = e.what();
    for (const char* part : {"random sequential addition placed", "growth packing grew the 60 cells from",
                             "and stopped: at its rate of growth", "lower the hematocrit or enlarge the box"}) {
      EXPECT_NE(what.find(part), std::string::npos) << part << " not in: " << what;
    }
  }
  // More cell volume than the room between the wall clearances: refused before any try (6 um plates, 2 um clearance).
  const hr::PlacementBox slab{.lower_m = {0.0, 0.0, 0.0}, .upper_m = {24e-6, 6e-6, 16e-6},
                              .periodic = {true, false, true}};
  try {
    (void)hr::place_cells(rbc, slab, {.hematocrit = 0.5, .min_gap_m = 0.5e-6, .wall_clearance_m = 2e-6, .seed = 1});
    FAIL() << "placement at phi 0.5 in a 2 um slab should be impossible";
  } catch (const hr::PlacementImpossible& e) {
    EXPECT_NE(std::string(e.what()).find("exceed the 768 um^3 of the box that keeps 2e-06 m from the walls"),
              std::string::npos) << e.what();
  }
  // A target below half a cell.
  const hr::PlacementSpec empty{.hematocrit = 1e-4, .min_gap_m = 0.5e-6, .wall_clearance_m = 2e-6, .seed = 1};
  EXPECT_THROW((void)hr::place_cells(rbc, kBox, empty), hr::PlacementImpossible);
}

