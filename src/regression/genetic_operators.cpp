// SPDX-License-Identifier: MIT
// Program generation, subtree choice, crossover and the three mutations, after gplearn/_program.py.
#include "regression/genetic_operators.hpp"

#include <stdexcept>

namespace hs::regression {
namespace {

std::size_t uniform_index(std::size_t n, Rng& rng) {
  return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
}

double uniform01(Rng& rng) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng); }

}  // namespace

GeneticOperators::GeneticOperators(const SearchSettings& settings, std::size_t n_features)
    : settings_(settings), n_features_(n_features) {
  if (n_features_ == 0) throw std::invalid_argument("GeneticOperators: no features");
  if (settings_.functions.empty()) throw std::invalid_argument("GeneticOperators: empty function set");
}

Node GeneticOperators::random_terminal(Rng& rng) const {
  const std::size_t choices = n_features_ + (settings_.use_constants ? 1 : 0);
  const std::size_t t = uniform_index(choices, rng);
  if (t == n_features_) {
    return Node::constant(std::uniform_real_distribution<double>(settings_.const_lo, settings_.const_hi)(rng));
  }
  return Node::variable(t);
}

Op GeneticOperators::random_function(Rng& rng) const {
  return settings_.functions[uniform_index(settings_.functions.size(), rng)];
}

Op GeneticOperators::random_function_of_arity(int a, Rng& rng) const {
  std::vector<Op> same;
  for (Op f : settings_.functions) {
    if (arity(f) == a) same.push_back(f);
  }
  return same[uniform_index(same.size(), rng)];
}

void GeneticOperators::grow(std::vector<Node>& out, int depth, int max_depth, bool full, Rng& rng) const {
  // gplearn: the root is always a function; below it, a function while depth < max_depth and ('full' or
  // randint(n_features + n_functions) <= n_functions), else a terminal.
  const std::size_t n_functions = settings_.functions.size();
  const bool function = depth == 0 || (depth < max_depth &&
                                       (full || uniform_index(n_features_ + n_functions, rng) <= n_functions));
  if (!function) {
    out.push_back(random_terminal(rng));
    return;
  }
  const Op f = random_function(rng);
  out.push_back(Node::function(f));
  for (int k = 0; k < arity(f); ++k) grow(out, depth + 1, max_depth, full, rng);
}

Expression GeneticOperators::random_program(Rng& rng) const {
  const bool full = uniform01(rng) < 0.5;
  const int max_depth = std::uniform_int_distribution<int>(settings_.init_depth_lo, settings_.init_depth_hi)(rng);
  std::vector<Node> out;
  grow(out, 0, max_depth, full, rng);
  return Expression(std::move(out));
}

std::pair<std::size_t, std::size_t> GeneticOperators::random_subtree(const Expression& e, Rng& rng) const {
  double total = 0.0;
  for (const Node& n : e.nodes()) total += n.is_terminal() ? 0.1 : 0.9;
  const double pick = uniform01(rng) * total;
  double cumulative = 0.0;
  std::size_t start = e.size() - 1;
  for (std::size_t i = 0; i < e.size(); ++i) {
    cumulative += e[i].is_terminal() ? 0.1 : 0.9;
    if (pick < cumulative) {
      start = i;
      break;
    }
  }
  return {start, e.subtree_end(start)};
}

Expression GeneticOperators::crossover(const Expression& parent, const Expression& donor, Rng& rng) const {
  const auto [start, end] = random_subtree(parent, rng);
  const auto [d_start, d_end] = random_subtree(donor, rng);
  (void)d_end;
  return parent.replaced(start, end, donor.subtree(d_start));
}

Expression GeneticOperators::subtree_mutation(const Expression& parent, Rng& rng) const {
  const Expression chicken = random_program(rng);
  return crossover(parent, chicken, rng);
}

Expression GeneticOperators::hoist_mutation(const Expression& parent, Rng& rng) const {
  const auto [start, end] = random_subtree(parent, rng);
  const Expression sub = parent.subtree(start);
  const auto [s_start, s_end] = random_subtree(sub, rng);
  (void)s_end;
  return parent.replaced(start, end, sub.subtree(s_start));
}

Expression GeneticOperators::point_mutation(const Expression& parent, Rng& rng) const {
  Expression out = parent;
  for (Node& n : out.nodes()) {
    if (uniform01(rng) >= settings_.p_point_replace) continue;
    n = n.is_terminal() ? random_terminal(rng) : Node::function(random_function_of_arity(arity(n.op), rng));
  }
  return out;
}

}  // namespace hs::regression
