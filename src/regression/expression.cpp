// SPDX-License-Identifier: MIT
// Prefix expression trees: subtree ranges, depth, recursion-based evaluation.
#include "regression/expression.hpp"

#include <algorithm>
#include <stdexcept>

namespace hs::regression {
namespace {

double eval_at(const std::vector<Node>& nodes, std::size_t& i, const double* x) {
  const Node& n = nodes[i++];
  if (n.op == Op::Const) return n.value;
  if (n.op == Op::Var) return x[n.var];
  const double a = eval_at(nodes, i, x);
  const double b = arity(n.op) == 2 ? eval_at(nodes, i, x) : 0.0;
  return apply(n.op, a, b);
}

}  // namespace

std::size_t Expression::subtree_end(std::size_t start) const {
  std::size_t need = 1;
  std::size_t i = start;
  while (need > 0) {
    if (i >= nodes_.size()) throw std::logic_error("Expression::subtree_end: malformed prefix list");
    need += static_cast<std::size_t>(arity(nodes_[i].op));
    --need;
    ++i;
  }
  return i;
}

Expression Expression::subtree(std::size_t start) const {
  const auto first = nodes_.begin() + static_cast<std::ptrdiff_t>(start);
  const auto last = nodes_.begin() + static_cast<std::ptrdiff_t>(subtree_end(start));
  return Expression(std::vector<Node>(first, last));
}

Expression Expression::replaced(std::size_t start, std::size_t end, const Expression& insert) const {
  std::vector<Node> out;
  out.reserve(nodes_.size() - (end - start) + insert.size());
  out.insert(out.end(), nodes_.begin(), nodes_.begin() + static_cast<std::ptrdiff_t>(start));
  out.insert(out.end(), insert.nodes_.begin(), insert.nodes_.end());
  out.insert(out.end(), nodes_.begin() + static_cast<std::ptrdiff_t>(end), nodes_.end());
  return Expression(std::move(out));
}

int Expression::depth() const {
  // Walk the prefix list keeping, for every open function, how many arguments it still expects.
  std::vector<int> open;
  int deepest = 0;
  for (const Node& n : nodes_) {
    deepest = std::max(deepest, static_cast<int>(open.size()));
    if (!open.empty()) --open.back();
    if (!n.is_terminal()) open.push_back(arity(n.op));
    while (!open.empty() && open.back() == 0) open.pop_back();
  }
  return deepest;
}

bool Expression::well_formed() const {
  long need = 1;
  for (const Node& n : nodes_) {
    if (need <= 0) return false;
    need += arity(n.op) - 1;
  }
  return need == 0;
}

std::vector<std::size_t> Expression::constant_positions() const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (nodes_[i].op == Op::Const) out.push_back(i);
  }
  return out;
}

std::vector<std::size_t> Expression::variables() const {
  std::vector<std::size_t> out;
  for (const Node& n : nodes_) {
    if (n.op == Op::Var) out.push_back(n.var);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double Expression::evaluate(const double* x) const {
  std::size_t i = 0;
  return eval_at(nodes_, i, x);
}

}  // namespace hs::regression
