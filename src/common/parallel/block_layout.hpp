// SPDX-License-Identifier: MIT
// Index arithmetic of one rank's block of a Cartesian grid: nx*ny*nz interior nodes plus a ghost layer.
#pragma once

#include <array>
#include <cstddef>

namespace hs::common {

/// A local block of nodes with `ghost` layers on every side, stored x fastest. Interior local indices run
/// 0..n-1 per axis, ghosts -ghost..-1 and n..n+ghost-1. Fields on the block are structure-of-arrays: component
/// c of node (x,y,z) lives at c * volume() + index(x,y,z), so one field type serves the lattice Boltzmann
/// populations (19 components) and finite-volume fields (1 or 3 components) alike.
struct BlockLayout {
  std::array<int, 3> n{};   // interior nodes per axis
  int ghost = 1;            // ghost layers per side

  [[nodiscard]] constexpr int padded(int axis) const { return n[axis] + 2 * ghost; }
  [[nodiscard]] constexpr std::ptrdiff_t stride_y() const { return padded(0); }
  [[nodiscard]] constexpr std::ptrdiff_t stride_z() const {
    return static_cast<std::ptrdiff_t>(padded(0)) * padded(1);
  }
  /// Number of nodes including ghosts: the stride between two components of a field.
  [[nodiscard]] constexpr std::size_t volume() const {
    return static_cast<std::size_t>(padded(0)) * static_cast<std::size_t>(padded(1)) *
           static_cast<std::size_t>(padded(2));
  }
  [[nodiscard]] constexpr std::size_t interior_volume() const {
    return static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(n[2]);
  }
  /// Linear index of local node (x, y, z); ghosts have negative or >= n coordinates.
  [[nodiscard]] constexpr std::ptrdiff_t index(int x, int y, int z) const {
    return (x + ghost) + (y + ghost) * stride_y() + (z + ghost) * stride_z();
  }
  /// Linear offset of a displacement (dx, dy, dz).
  [[nodiscard]] constexpr std::ptrdiff_t offset(int dx, int dy, int dz) const {
    return dx + dy * stride_y() + dz * stride_z();
  }
  /// Local coordinates of a linear index.
  [[nodiscard]] constexpr std::array<int, 3> coords(std::ptrdiff_t i) const {
    const auto sy = stride_y();
    const auto sz = stride_z();
    return {static_cast<int>(i % sy) - ghost, static_cast<int>((i % sz) / sy) - ghost,
            static_cast<int>(i / sz) - ghost};
  }
  [[nodiscard]] constexpr bool is_interior(int x, int y, int z) const {
    return x >= 0 && y >= 0 && z >= 0 && x < n[0] && y < n[1] && z < n[2];
  }
};

}  // namespace hs::common
