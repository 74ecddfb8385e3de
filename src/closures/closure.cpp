// SPDX-License-Identifier: MIT
// Validity checks and usage counting shared by all closures.
#include "closures/closure.hpp"

#include <fmt/format.h>

namespace hs::closures {

bool Closure::inside(const ClosureInputs& in) const {
  for (const auto& [var, range] : validity_) {
    if (!range.contains(in.*var.field)) return false;
  }
  return true;
}

void Closure::count(const ClosureInputs& in) const {
  evaluations_.fetch_add(1, std::memory_order_relaxed);
  if (!inside(in)) outside_.fetch_add(1, std::memory_order_relaxed);
}

std::string Closure::usage_report() const {
  std::string ranges;
  for (const auto& [var, range] : validity_) {
    ranges += fmt::format("{}{} [{}, {}]", ranges.empty() ? "" : ", ", var.name, range.lo, range.hi);
  }
  const long n = evaluations();
  const long out = outside_validity();
  const double pct = n > 0 ? 100.0 * static_cast<double>(out) / static_cast<double>(n) : 0.0;
  return fmt::format("{}: {} evaluations, {} ({:.2f}%) outside validity ({})", name_, n, out, pct, ranges);
}

}  // namespace hs::closures
