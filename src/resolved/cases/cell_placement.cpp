// SPDX-License-Identifier: MIT
// Cells at a target hematocrit: random sequential addition when it suffices, growth packing when it does not.
#include "resolved/cases/cell_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <fmt/format.h>

#include "resolved/cases/cell_packing.hpp"
#include "resolved/cases/placement_geometry.hpp"

namespace hs::resolved {
namespace {

using common::Vec3;

std::vector<std::vector<Vec3>> full_size_vertices(const placement::CellGeometry& g,
                                                  const std::vector<placement::Pose>& poses) {
  std::vector<std::vector<Vec3>> cells(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) (void)g.vertices_within_walls(poses[i], 1.0, cells[i]);
  return cells;
}

}  // namespace

Placement place_cells(const TriangleMesh& rest, const PlacementBox& box, const PlacementSpec& spec) {
  Placement out;
  out.cell_volume_m3 = mesh_volume_m3(rest);
  out.box_volume_m3 = 1.0;
  for (int a = 0; a < 3; ++a) out.box_volume_m3 *= box.upper_m[a] - box.lower_m[a];
  const long n = std::lround(spec.hematocrit * out.box_volume_m3 / out.cell_volume_m3);
  if (n < 1) {
    throw PlacementImpossible(fmt::format("hematocrit {:g} is under half a cell in the {:.4g} um^3 box (one cell of "
                                          "{:.4g} um^3 is {:.4g}); raise it or enlarge the box", spec.hematocrit,
                                          out.box_volume_m3 * 1e18, out.cell_volume_m3 * 1e18,
                                          out.cell_volume_m3 / out.box_volume_m3));
  }
  double room_m3 = 1.0;   // where the vertices may lie: the cells' insides too, as each spans its vertices
  for (int a = 0; a < 3; ++a) {
    room_m3 *= std::max(0.0, box.upper_m[a] - box.lower_m[a] - (box.periodic[a] ? 0.0 : 2.0 * spec.wall_clearance_m));
  }
  if (static_cast<double>(n) * out.cell_volume_m3 > room_m3) {
    throw PlacementImpossible(fmt::format("{} cells of {:.4g} um^3 (hematocrit {:g}) exceed the {:.4g} um^3 of the box "
                                          "that keeps {:g} m from the walls; lower the hematocrit or enlarge the box",
                                          n, out.cell_volume_m3 * 1e18, spec.hematocrit, room_m3 * 1e18,
                                          spec.wall_clearance_m));
  }
  const placement::CellGeometry g(rest, box, spec.min_gap_m, spec.wall_clearance_m);
  const auto phi = [&](double cells) { return cells * out.cell_volume_m3 / out.box_volume_m3; };
  std::mt19937_64 rng(spec.seed);
  const auto added = placement::random_sequential_addition(g, n, 1.0, spec.attempts_per_cell, rng, out.attempts);
  if (static_cast<long>(added.size()) == n) {
    out.method = PlacementMethod::random_sequential_addition;
    out.cells_m = full_size_vertices(g, added);
    out.hematocrit = phi(static_cast<double>(n));
    return out;
  }
  const std::string addition = fmt::format("random sequential addition placed {} of {} cells (hematocrit {:.4g} of the "
                                           "{:g} asked; {} tries a cell)", added.size(), n,
                                           phi(static_cast<double>(added.size())), spec.hematocrit,
                                           spec.attempts_per_cell);
  const auto packed = placement::grow_packing(g, n, spec.seed, spec.attempts_per_cell, spec.max_packing_sweeps);
  out.attempts += packed.attempts;
  out.packing_sweeps = packed.sweeps;
  out.packing_start_scale = packed.start_scale;
  if (!packed.complete()) {
    const std::string growth =
        packed.start_scale == 0.0
            ? fmt::format("growth packing found no start even at {:g} of the cells' size", 0.2)
            : fmt::format("growth packing grew the {} cells from {:.3f} to {:.4f} of their size in {} sweeps (the "
                          "hematocrit of cells that size: {:.4g}) and stopped: at its rate of growth full size would "
                          "take more than {} sweeps", n, packed.start_scale, packed.scale, packed.sweeps,
                          phi(static_cast<double>(n)) * std::pow(packed.scale, 3), spec.max_packing_sweeps);
    throw PlacementImpossible(fmt::format("{}; {} (gap {:g} m, wall clearance {:g} m); lower the hematocrit or enlarge "
                                          "the box", addition, growth, spec.min_gap_m, spec.wall_clearance_m));
  }
  out.method = PlacementMethod::growth_packing;
  out.cells_m = full_size_vertices(g, packed.poses);
  out.hematocrit = phi(static_cast<double>(n));
  return out;
}

double min_intercell_distance_m(const std::vector<std::vector<common::Vec3>>& cells_m, const PlacementBox& box) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < cells_m.size(); ++a) {
    for (std::size_t b = a + 1; b < cells_m.size(); ++b) {
      for (const auto& p : cells_m[a]) {
        for (const auto& q : cells_m[b]) {
          Vec3 d = q - p;
          for (int k = 0; k < 3; ++k) {
            if (!box.periodic[k]) continue;
            const double l = box.upper_m[k] - box.lower_m[k];
            d[k] -= l * std::round(d[k] / l);
          }
          best = std::min(best, common::norm(d));
        }
      }
    }
  }
  return best;
}

}  // namespace hs::resolved
