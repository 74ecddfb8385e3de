// SPDX-License-Identifier: MIT
// Epsilon-lexicase selection over per-case errors.
#include "regression/lexicase_selector.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hs::regression {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

LexicaseSelector::LexicaseSelector(std::vector<const std::vector<double>*> errors, const std::vector<bool>& eligible)
    : errors_(std::move(errors)) {
  std::size_t n_cases = 0;
  for (std::size_t i = 0; i < errors_.size(); ++i) {
    if (eligible[i] && !errors_[i]->empty()) {
      pool_.push_back(i);
      n_cases = errors_[i]->size();
    }
  }
  if (pool_.empty()) {   // nothing eligible: fall back to everyone
    for (std::size_t i = 0; i < errors_.size(); ++i) pool_.push_back(i);
  }
  epsilon_.assign(n_cases, 0.0);
  std::vector<double> column(pool_.size());
  for (std::size_t c = 0; c < n_cases; ++c) {
    for (std::size_t k = 0; k < pool_.size(); ++k) column[k] = (*errors_[pool_[k]])[c];
    const double m = median(column);
    for (double& v : column) v = std::abs(v - m);
    epsilon_[c] = median(column);
  }
}

std::size_t LexicaseSelector::select(Rng& rng) const {
  std::vector<std::size_t> cases(epsilon_.size());
  std::iota(cases.begin(), cases.end(), std::size_t{0});
  std::vector<std::size_t> survivors = pool_;
  std::vector<std::size_t> next;
  for (std::size_t k = 0; k < cases.size() && survivors.size() > 1; ++k) {
    // Draw the next case without replacement (partial Fisher-Yates with our own draws).
    const std::size_t j = k + static_cast<std::size_t>(rng() % (cases.size() - k));
    std::swap(cases[k], cases[j]);
    const std::size_t c = cases[k];
    double best = HUGE_VAL;
    for (std::size_t i : survivors) best = std::min(best, (*errors_[i])[c]);
    next.clear();
    for (std::size_t i : survivors) {
      if ((*errors_[i])[c] <= best + epsilon_[c]) next.push_back(i);
    }
    survivors.swap(next);
  }
  return survivors[static_cast<std::size_t>(rng() % survivors.size())];
}

}  // namespace hs::regression
