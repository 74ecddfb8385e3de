// SPDX-License-Identifier: MIT
// The D3Q19 velocity set: directions, weights, opposites (Krüger et al. 2017, section 3.4.7).
#pragma once

#include <array>

namespace hs::resolved {

/// D3Q19 in lattice units. Direction 0 is at rest; directions k = 1..9 and k + 9 are opposite, so the
/// collision can work on the pairs (k, k + 9) without a lookup. c_s^2 = 1/3.
struct D3Q19 {
  static constexpr int q = 19;
  static constexpr int half = 9;   // number of direction pairs
  static constexpr double cs2 = 1.0 / 3.0;
  static constexpr std::array<std::array<int, 3>, 19> c{{{0, 0, 0},
                                                         {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                                         {1, 1, 0}, {1, -1, 0}, {1, 0, 1},
                                                         {1, 0, -1}, {0, 1, 1}, {0, 1, -1},
                                                         {-1, 0, 0}, {0, -1, 0}, {0, 0, -1},
                                                         {-1, -1, 0}, {-1, 1, 0}, {-1, 0, -1},
                                                         {-1, 0, 1}, {0, -1, -1}, {0, -1, 1}}};
  static constexpr double w0 = 1.0 / 3.0;
  static constexpr double w_face = 1.0 / 18.0;
  static constexpr double w_edge = 1.0 / 36.0;
  static constexpr std::array<double, 19> w{w0,     w_face, w_face, w_face, w_edge, w_edge, w_edge,
                                            w_edge, w_edge, w_edge, w_face, w_face, w_face, w_edge,
                                            w_edge, w_edge, w_edge, w_edge, w_edge};

  [[nodiscard]] static constexpr int opposite(int i) { return i == 0 ? 0 : (i <= half ? i + half : i - half); }
};

}  // namespace hs::resolved
