// SPDX-License-Identifier: MIT
// An expression tree stored as a flat prefix (Polish) list of nodes, as gplearn stores its programs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "regression/op.hpp"

namespace hs::regression {

struct Node {
  Op op = Op::Const;
  std::uint16_t var = 0;   // feature index when op == Var
  double value = 0.0;      // constant value when op == Const

  [[nodiscard]] static Node constant(double v) { return {Op::Const, 0, v}; }
  [[nodiscard]] static Node variable(std::size_t index) { return {Op::Var, static_cast<std::uint16_t>(index), 0.0}; }
  [[nodiscard]] static Node function(Op f) { return {f, 0, 0.0}; }
  [[nodiscard]] bool is_terminal() const { return op == Op::Const || op == Op::Var; }
  friend bool operator==(const Node& a, const Node& b) {
    return a.op == b.op && (a.op != Op::Var || a.var == b.var) && (a.op != Op::Const || a.value == b.value);
  }
};

/// A well-formed prefix expression: node 0 is the root and each function is followed by its arguments.
class Expression {
 public:
  Expression() = default;
  explicit Expression(std::vector<Node> nodes) : nodes_(std::move(nodes)) {}

  [[nodiscard]] const std::vector<Node>& nodes() const { return nodes_; }
  [[nodiscard]] std::vector<Node>& nodes() { return nodes_; }
  [[nodiscard]] std::size_t size() const { return nodes_.size(); }
  [[nodiscard]] bool empty() const { return nodes_.empty(); }
  [[nodiscard]] const Node& operator[](std::size_t i) const { return nodes_[i]; }

  /// One past the last node of the subtree rooted at `start`.
  [[nodiscard]] std::size_t subtree_end(std::size_t start) const;
  /// The subtree rooted at `start`, as an expression of its own.
  [[nodiscard]] Expression subtree(std::size_t start) const;
  /// This expression with nodes [start, end) replaced by `insert` (a whole subtree).
  [[nodiscard]] Expression replaced(std::size_t start, std::size_t end, const Expression& insert) const;
  /// Depth of the tree: a lone terminal has depth 0.
  [[nodiscard]] int depth() const;
  /// Whether the prefix list is a single complete tree (every function has all its arguments).
  [[nodiscard]] bool well_formed() const;
  /// Indices of the Const nodes, in prefix order.
  [[nodiscard]] std::vector<std::size_t> constant_positions() const;
  /// Sorted, unique feature indices used.
  [[nodiscard]] std::vector<std::size_t> variables() const;
  /// Value at one point (protected semantics), by recursion; for tests and simplification, not speed.
  [[nodiscard]] double evaluate(const double* x) const;

  friend bool operator==(const Expression& a, const Expression& b) { return a.nodes_ == b.nodes_; }

 private:
  std::vector<Node> nodes_;
};

}  // namespace hs::regression
