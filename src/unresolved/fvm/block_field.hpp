// SPDX-License-Identifier: MIT
// A field on one block of a Cartesian grid, with a ghost layer on every side (ready for a halo exchange).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace hs::unresolved {

/// Values on the index box [-1, n_d + 1] of each axis d: the interior cells 0..n_d-1, one more index for
/// the last face of a staggered grid (n_d), and one ghost layer on each side. x runs fastest.
/// Periodic ghosts are filled by fill_periodic(); an MPI halo exchange will fill the same layer later
/// (to be unified with the lattice's block type in common/parallel once it exists).
template <typename T>
class BlockField {
 public:
  BlockField() = default;
  BlockField(std::array<int, 3> cells, T value)
      : n_(cells), stride_{1, cells[0] + 3, (cells[0] + 3) * (cells[1] + 3)},
        data_(static_cast<std::size_t>(cells[0] + 3) * static_cast<std::size_t>(cells[1] + 3) *
                  static_cast<std::size_t>(cells[2] + 3),
              value) {}

  [[nodiscard]] std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>((i + 1) + stride_[1] * (j + 1) + stride_[2] * (k + 1));
  }
  [[nodiscard]] T& operator()(int i, int j, int k) { return data_[index(i, j, k)]; }
  [[nodiscard]] const T& operator()(int i, int j, int k) const { return data_[index(i, j, k)]; }
  [[nodiscard]] T& operator[](std::size_t idx) { return data_[idx]; }
  [[nodiscard]] const T& operator[](std::size_t idx) const { return data_[idx]; }
  /// Index offset of one step along axis d.
  [[nodiscard]] long stride(int d) const { return stride_[static_cast<std::size_t>(d)]; }
  [[nodiscard]] const std::array<int, 3>& cells() const { return n_; }
  [[nodiscard]] std::vector<T>& data() { return data_; }
  [[nodiscard]] const std::vector<T>& data() const { return data_; }
  void fill(T value) { std::fill(data_.begin(), data_.end(), value); }

  /// Periodic wrap along `axis` with `period` indices: index -1 <- period-1, period <- 0, period+1 <- 1.
  void fill_periodic(int axis, int period) {
    std::array<int, 3> lo{-1, -1, -1};
    std::array<int, 3> hi{n_[0] + 1, n_[1] + 1, n_[2] + 1};
    const int a = axis;
    const int b = (axis + 1) % 3;
    const int c = (axis + 2) % 3;
    for (int q = lo[static_cast<std::size_t>(c)]; q <= hi[static_cast<std::size_t>(c)]; ++q) {
      for (int r = lo[static_cast<std::size_t>(b)]; r <= hi[static_cast<std::size_t>(b)]; ++r) {
        auto at = [&](int s) -> T& {
          std::array<int, 3> ijk{};
          ijk[static_cast<std::size_t>(a)] = s;
          ijk[static_cast<std::size_t>(b)] = r;
          ijk[static_cast<std::size_t>(c)] = q;
          return (*this)(ijk[0], ijk[1], ijk[2]);
        };
        at(-1) = at(period - 1);
        at(period) = at(0);
        if (period + 1 <= n_[static_cast<std::size_t>(a)] + 1) at(period + 1) = at(1);
      }
    }
  }

  /// Calls fn(flat index) for every point of the plane where axis `axis` has index `along`, ghosts included.
  template <typename Fn>
  void for_each_in_plane(int axis, int along, Fn&& fn) const {
    const int b = (axis + 1) % 3;
    const int c = (axis + 2) % 3;
    const long base = (along + 1) * stride_[static_cast<std::size_t>(axis)];
    for (int q = 0; q < n_[static_cast<std::size_t>(c)] + 3; ++q) {
      for (int r = 0; r < n_[static_cast<std::size_t>(b)] + 3; ++r) {
        fn(static_cast<std::size_t>(base + q * stride_[static_cast<std::size_t>(c)] + r * stride_[static_cast<std::size_t>(b)]));
      }
    }
  }

  /// Copies the first interior layer into the ghost layer on both sides of a non-periodic `axis`.
  void fill_zero_gradient(int axis) {
    const int n = n_[static_cast<std::size_t>(axis)];
    const auto st = static_cast<std::size_t>(stride_[static_cast<std::size_t>(axis)]);
    for_each_in_plane(axis, -1, [&](std::size_t idx) { data_[idx] = data_[idx + st]; });
    for_each_in_plane(axis, n, [&](std::size_t idx) { data_[idx] = data_[idx - st]; });
  }

 private:
  std::array<int, 3> n_{0, 0, 0};
  std::array<long, 3> stride_{0, 0, 0};
  std::vector<T> data_;
};

}  // namespace hs::unresolved
