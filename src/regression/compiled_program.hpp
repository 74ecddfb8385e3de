// SPDX-License-Identifier: MIT
// The fast evaluator: an expression compiled to a postfix program with fixed stack slots, run over
// blocks of rows so that each instruction is one vectorisable loop.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "regression/data_view.hpp"
#include "regression/expression.hpp"

namespace hs::regression {

class CompiledProgram {
 public:
  /// Rows evaluated per block: the stack of one block stays in L1 cache.
  static constexpr std::size_t block_rows = 256;

  CompiledProgram() = default;
  explicit CompiledProgram(const Expression& e);

  /// out[i] = e(row i) for every row of `data` (protected semantics). Thread-safe (const, no shared scratch).
  void evaluate(const DataView& data, std::span<double> out) const;
  /// The value at one point x[feature]; the scalar path the closures take per particle.
  [[nodiscard]] double evaluate_point(const double* x) const;

  /// Number of Const instructions, in the prefix order of the expression's constants.
  [[nodiscard]] std::size_t constant_count() const { return constant_slots_.size(); }
  /// Replaces the constants (same order as Expression::constant_positions()).
  void set_constants(std::span<const double> values);
  [[nodiscard]] std::size_t size() const { return code_.size(); }
  [[nodiscard]] std::size_t stack_depth() const { return stack_depth_; }

 private:
  struct Instruction {
    Op op;
    std::uint16_t var;
    std::uint16_t dst;          // slot written; binary ops read dst and dst + 1, unary ops read dst
    double value;
    bool var_operand = false;   // binary op whose second argument is feature `var`, read in place
  };
  void evaluate_block(const DataView& data, std::size_t row0, std::size_t len, double* stack, double* out) const;

  std::vector<Instruction> code_;
  std::vector<std::size_t> constant_slots_;   // indices into code_ of the Const instructions
  std::size_t stack_depth_ = 0;
};

}  // namespace hs::regression
