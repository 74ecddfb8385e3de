// SPDX-License-Identifier: MIT
// The (s, y) pairs of L-BFGS in preallocated storage and the two-loop recursion with a given initial inverse Hessian.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "resolved/membrane/membrane_energy.hpp"

namespace hs::resolved {

/// The last m pairs (s = x_{k+1} - x_k, y = grad_{k+1} - grad_k) and the two-loop recursion (Nocedal & Wright 2006,
/// Alg. 7.4) with the prefactored proxy as the initial inverse Hessian (Liu et al. 2017). No allocation after the
/// first pairs: the oldest slot is overwritten.
class LbfgsMemory {
 public:
  using InverseProxy = std::function<void(const Positions& q, Positions& out)>;
  LbfgsMemory(int m, int vertices);
  void clear() { count_ = 0; }
  [[nodiscard]] bool empty() const { return count_ == 0; }
  /// Keeps the pair only if its curvature s.y is positive (otherwise the update would not be positive definite).
  void push(const Positions& s, const Positions& y);
  /// out = -H g with H the L-BFGS inverse Hessian built on apply_h0_inverse.
  void direction(const Positions& g, const InverseProxy& apply_h0_inverse, Positions& out);
  /// Appends the pairs (oldest first) to `state`; restore() reads the same layout and returns the doubles used.
  void save(std::vector<double>& state) const;
  std::size_t restore(std::span<const double> state);

 private:
  [[nodiscard]] int slot(int k) const { return (head_ + k) % m_; }   // k-th oldest pair
  int m_;
  int vertices_;
  int head_ = 0;
  int count_ = 0;
  std::vector<Positions> s_, y_;
  std::vector<double> rho_, alpha_;
  Positions q_;
};

}  // namespace hs::resolved
