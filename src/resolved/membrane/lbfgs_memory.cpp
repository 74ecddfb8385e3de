// SPDX-License-Identifier: MIT
// L-BFGS pair storage (a ring of m preallocated slots) and the two-loop recursion.
#include "resolved/membrane/lbfgs_memory.hpp"

#include <cmath>
#include <stdexcept>

namespace hs::resolved {
namespace {

double dot(const Positions& a, const Positions& b) { return (a.array() * b.array()).sum(); }

}  // namespace

LbfgsMemory::LbfgsMemory(int m, int vertices)
    : m_(std::max(m, 1)), vertices_(vertices),
      s_(static_cast<std::size_t>(m_), Positions::Zero(vertices, 3)),
      y_(static_cast<std::size_t>(m_), Positions::Zero(vertices, 3)),
      rho_(static_cast<std::size_t>(m_), 0.0), alpha_(static_cast<std::size_t>(m_), 0.0),
      q_(Positions::Zero(vertices, 3)) {}

void LbfgsMemory::push(const Positions& s, const Positions& y) {
  const double sy = dot(s, y);
  if (!(sy > 1e-16 * std::sqrt(dot(s, s) * dot(y, y)))) return;
  const int k = count_ < m_ ? slot(count_) : head_;   // a free slot, or the oldest one
  if (count_ < m_) ++count_; else head_ = (head_ + 1) % m_;
  s_[static_cast<std::size_t>(k)] = s;
  y_[static_cast<std::size_t>(k)] = y;
  rho_[static_cast<std::size_t>(k)] = 1.0 / sy;
}

void LbfgsMemory::direction(const Positions& g, const InverseProxy& apply_h0_inverse, Positions& out) {
  q_ = g;
  for (int k = count_ - 1; k >= 0; --k) {
    const auto j = static_cast<std::size_t>(slot(k));
    alpha_[j] = rho_[j] * dot(s_[j], q_);
    q_ -= alpha_[j] * y_[j];
  }
  apply_h0_inverse(q_, out);
  for (int k = 0; k < count_; ++k) {
    const auto j = static_cast<std::size_t>(slot(k));
    out += (alpha_[j] - rho_[j] * dot(y_[j], out)) * s_[j];
  }
  out = -out;
}

void LbfgsMemory::save(std::vector<double>& state) const {
  state.push_back(static_cast<double>(count_));
  for (int k = 0; k < count_; ++k) {
    const auto j = static_cast<std::size_t>(slot(k));
    for (const Positions* p : {&s_[j], &y_[j]})
      for (Eigen::Index i = 0; i < p->rows(); ++i)
        for (int c = 0; c < 3; ++c) state.push_back((*p)(i, c));
    state.push_back(rho_[j]);
  }
}

std::size_t LbfgsMemory::restore(std::span<const double> state) {
  const std::size_t per_pair = 6 * static_cast<std::size_t>(vertices_) + 1;
  if (state.empty()) throw std::invalid_argument("LbfgsMemory::restore: no pair count");
  const auto count = static_cast<int>(state[0]);
  if (count < 0 || count > m_ || state.size() < 1 + per_pair * static_cast<std::size_t>(count)) {
    throw std::invalid_argument("LbfgsMemory::restore: the checkpoint holds another L-BFGS memory");
  }
  head_ = 0;
  count_ = count;
  std::size_t at = 1;
  for (int k = 0; k < count_; ++k) {
    const auto j = static_cast<std::size_t>(k);
    for (Positions* p : {&s_[j], &y_[j]})
      for (Eigen::Index i = 0; i < p->rows(); ++i)
        for (int c = 0; c < 3; ++c) (*p)(i, c) = state[at++];
    rho_[j] = state[at++];
  }
  return at;
}

}  // namespace hs::resolved
