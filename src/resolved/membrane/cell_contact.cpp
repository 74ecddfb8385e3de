// SPDX-License-Identifier: MIT
// Cell-cell contact forces through a hashed bin grid.
#include "resolved/membrane/cell_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace hs::resolved {
namespace {

struct VertexRef {
  int cell, vertex;
};

/// x wrapped into [0, L) along periodic axes.
common::Vec3 wrapped(common::Vec3 x, const common::Vec3& period) {
  for (int a = 0; a < 3; ++a) {
    if (period[a] > 0.0) x[a] -= period[a] * std::floor(x[a] / period[a]);
  }
  return x;
}

/// x_i - x_j by the minimum image along periodic axes.
common::Vec3 separation(const common::Vec3& xi, const common::Vec3& xj, const common::Vec3& period) {
  common::Vec3 d = xi - xj;
  for (int a = 0; a < 3; ++a) {
    if (period[a] > 0.0) d[a] -= period[a] * std::round(d[a] / period[a]);
  }
  return d;
}

}  // namespace

CellContactReport add_cell_contact_forces(const std::vector<std::span<const common::Vec3>>& cells_m,
                                          std::vector<std::vector<common::Vec3>>& forces_N,
                                          const CellContactSpec& spec) {
  CellContactReport report{0, spec.range_m, 0.0};
  if (spec.range_m <= 0.0 || spec.stiffness_N_m <= 0.0 || cells_m.size() < 2) return report;
  if (forces_N.size() != cells_m.size()) throw std::invalid_argument("add_cell_contact_forces: one force list per cell");
  // Bins of at least d0 per axis (a whole number of them across a periodic length, so that the minimum image of
  // a pair within d0 lies in a neighbouring bin).
  std::array<int, 3> nbins{0, 0, 0};
  std::array<double, 3> bin{spec.range_m, spec.range_m, spec.range_m};
  for (int a = 0; a < 3; ++a) {
    if (spec.period_m[a] > 0.0) {
      nbins[a] = std::max(1, static_cast<int>(std::floor(spec.period_m[a] / spec.range_m)));
      bin[a] = spec.period_m[a] / nbins[a];
    }
  }
  auto bin_of = [&](const common::Vec3& x) {
    std::array<std::int64_t, 3> b{};
    for (int a = 0; a < 3; ++a) b[a] = static_cast<std::int64_t>(std::floor(x[a] / bin[a]));
    return b;
  };
  auto key = [&](std::array<std::int64_t, 3> b) {
    for (int a = 0; a < 3; ++a) {
      if (nbins[a] > 0) b[a] = ((b[a] % nbins[a]) + nbins[a]) % nbins[a];
    }
    return (b[0] * 2097152 + b[1]) * 2097152 + b[2];   // 2^21 bins per axis before the key wraps
  };
  std::unordered_map<std::int64_t, std::vector<VertexRef>> grid;
  for (int c = 0; c < static_cast<int>(cells_m.size()); ++c) {
    if (forces_N[c].size() != cells_m[c].size()) throw std::invalid_argument("add_cell_contact_forces: one force per vertex");
    for (int v = 0; v < static_cast<int>(cells_m[c].size()); ++v) {
      grid[key(bin_of(wrapped(cells_m[c][v], spec.period_m)))].push_back({c, v});
    }
  }
  for (const auto& [k, members] : grid) {
    const auto& first = members.front();
    const auto b0 = bin_of(wrapped(cells_m[first.cell][first.vertex], spec.period_m));
    // The distinct bins around this one, each pair of bins once: with fewer than 3 bins along a periodic axis two
    // offsets land in the same bin.
    std::vector<std::int64_t> around;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const std::int64_t nk = key({b0[0] + dx, b0[1] + dy, b0[2] + dz});
          if (nk >= k && std::find(around.begin(), around.end(), nk) == around.end()) around.push_back(nk);
        }
      }
    }
    for (const std::int64_t other_key : around) {
      const auto it = grid.find(other_key);
      if (it == grid.end()) continue;
      for (const auto& p : members) {
        for (const auto& q : it->second) {
          if (p.cell == q.cell) continue;
          if (other_key == k && p.cell > q.cell) continue;   // within one bin: each pair of cells once
          const common::Vec3 d = separation(cells_m[p.cell][p.vertex], cells_m[q.cell][q.vertex], spec.period_m);
          const double r = common::norm(d);
          if (r >= spec.range_m || r == 0.0) continue;
          const double f = spec.stiffness_N_m * (spec.range_m - r);
          forces_N[p.cell][p.vertex] += (f / r) * d;
          forces_N[q.cell][q.vertex] -= (f / r) * d;
          report.pairs += 1;
          report.total_N += f;
          report.min_distance_m = std::min(report.min_distance_m, r);
        }
      }
    }
  }
  return report;
}

}  // namespace hs::resolved
