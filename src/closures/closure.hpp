// SPDX-License-Identifier: MIT
// What every closure shares: a name, a declared validity range, and counts of evaluations outside it.
#pragma once

#include <atomic>
#include <string>
#include <utility>
#include <vector>

#include "closures/closure_inputs.hpp"

namespace hs::closures {

/// The box of inputs where a closure is trusted: one interval per input it uses.
using Validity = std::vector<std::pair<InputVariable, Interval>>;

class Closure {
 public:
  virtual ~Closure() = default;
  Closure(const Closure&) = delete;
  Closure& operator=(const Closure&) = delete;

  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] const Validity& validity() const { return validity_; }
  /// Evaluations so far, and how many had an input outside the validity box (thread-safe counters).
  [[nodiscard]] long evaluations() const { return evaluations_.load(std::memory_order_relaxed); }
  [[nodiscard]] long outside_validity() const { return outside_.load(std::memory_order_relaxed); }
  [[nodiscard]] bool inside(const ClosureInputs& in) const;
  /// One line for log.txt: "cd_di_rep: 1200 evaluations, 3 (0.25%) outside validity (di [0.05, 0.45], ...)".
  [[nodiscard]] std::string usage_report() const;

 protected:
  Closure(std::string name, Validity validity) : name_(std::move(name)), validity_(std::move(validity)) {}
  /// Called by every public evaluation; relaxed atomics (counts only, no ordering needed).
  void count(const ClosureInputs& in) const;

 private:
  std::string name_;
  Validity validity_;
  mutable std::atomic<long> evaluations_{0};
  mutable std::atomic<long> outside_{0};
};

}  // namespace hs::closures
