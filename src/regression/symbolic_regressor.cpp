// SPDX-License-Identifier: MIT
// The generational GP loop: tournament selection, gplearn's operator probabilities, parsimony pressure.
#include "regression/symbolic_regressor.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "regression/compiled_program.hpp"
#include "regression/genetic_operators.hpp"
#include "regression/polynomial.hpp"
#include "regression/simplify.hpp"

namespace hs::regression {
namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

Rng rng_for(std::uint64_t seed, int generation, std::size_t index) {
  const std::uint64_t key = (static_cast<std::uint64_t>(generation) << 32) ^ static_cast<std::uint64_t>(index);
  return Rng(splitmix64(splitmix64(seed) ^ splitmix64(key + 0x1234567ULL)));
}

// Every `stride`-th row, at most `max_rows` of them: the rows Levenberg-Marquardt works on.
ColumnData strided_rows(const DataView& x, std::size_t max_rows, std::vector<double>& y_out,
                        std::span<const double> y) {
  const std::size_t stride = x.rows <= max_rows ? 1 : (x.rows + max_rows - 1) / max_rows;
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < x.rows; i += stride) index.push_back(i);
  std::vector<std::vector<double>> cols(x.columns.size());
  for (std::size_t j = 0; j < cols.size(); ++j) {
    for (std::size_t i : index) cols[j].push_back(x.columns[j][i]);
  }
  for (std::size_t i : index) y_out.push_back(y[i]);
  return ColumnData(std::move(cols));
}

// gplearn's 'auto' parsimony (Poli & McPhee): cov(length, loss) / var(length) over the population.
template <class Pop>
double auto_parsimony(const Pop& pop) {
  double ml = 0.0, mf = 0.0;
  std::size_t n = 0;
  for (const auto& ind : pop) {
    if (!std::isfinite(ind.loss)) continue;
    ml += static_cast<double>(ind.model.tree.size());
    mf += ind.loss;
    ++n;
  }
  if (n < 2) return 0.0;
  ml /= static_cast<double>(n);
  mf /= static_cast<double>(n);
  double cov = 0.0, var = 0.0;
  for (const auto& ind : pop) {
    if (!std::isfinite(ind.loss)) continue;
    const double dl = static_cast<double>(ind.model.tree.size()) - ml;
    cov += dl * (ind.loss - mf);
    var += dl * dl;
  }
  return var > 0.0 ? cov / var : 0.0;
}

// All but one of each group of clones (same length, loss equal to 1e-12 relative) get +inf.
template <class Pop>
void penalise_clones(const Pop& pop, std::vector<double>& penalised) {
  std::vector<std::size_t> order(pop.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto la = pop[a].model.tree.size(), lb = pop[b].model.tree.size();
    return la != lb ? la < lb : (pop[a].loss != pop[b].loss ? pop[a].loss < pop[b].loss : a < b);
  });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const auto& a = pop[order[k - 1]];
    const auto& b = pop[order[k]];
    if (a.model.tree.size() == b.model.tree.size() && std::abs(a.loss - b.loss) <= 1e-12 * std::abs(a.loss)) {
      penalised[order[k]] = std::numeric_limits<double>::infinity();
    }
  }
}

}  // namespace

SymbolicRegressor::SymbolicRegressor(SearchSettings settings) : settings_(std::move(settings)) {
  const double p = settings_.p_crossover + settings_.p_subtree_mutation + settings_.p_hoist_mutation +
                   settings_.p_point_mutation;
  if (p > 1.0 + 1e-12) throw std::invalid_argument("the operator probabilities add up to more than 1");
  if (settings_.population_size < 2 || settings_.tournament_size < 1 || settings_.generations < 1) {
    throw std::invalid_argument("population_size >= 2, tournament_size >= 1 and generations >= 1 are required");
  }
}

void SymbolicRegressor::evaluate(Individual& ind, const DataView& x, std::span<const double> y, const DataView& x_lm,
                                 std::span<const double> y_lm) const {
  std::vector<double> f(x.rows);
  CompiledProgram program(ind.model.tree);
  program.evaluate(x, f);
  ind.evaluations = 1;
  if (settings_.linear_scaling) fit_linear_scaling(f, y, ind.model.offset, ind.model.scale);
  if (settings_.lm_iterations > 0 && (program.constant_count() > 0)) {
    // LM runs on the (possibly fewer) LM rows: count its evaluations in units of full training passes.
    const long lm_evals = optimize_constants(ind.model, x_lm, y_lm, settings_.lm_iterations, settings_.linear_scaling);
    ind.evaluations += lm_evals * static_cast<long>(x_lm.rows) / static_cast<long>(std::max<std::size_t>(x.rows, 1));
    program = CompiledProgram(ind.model.tree);
    program.evaluate(x, f);
    ++ind.evaluations;
  }
  for (double& v : f) v = ind.model.offset + ind.model.scale * v;
  ind.loss = loss(settings_.metric, y, f);
  if (!settings_.feature_dimensions.empty()) {
    // Under linear scaling the fitted scale is a free constant, so the output's dimension is always reachable.
    const auto& target = settings_.linear_scaling ? std::optional<Dimension>{} : settings_.target_dimension;
    ind.consistent = dimensionally_consistent(ind.model.tree, settings_.feature_dimensions, target);
  }
  if (settings_.lexicase) {
    const std::size_t cases = static_cast<std::size_t>(std::max(1, settings_.lexicase_cases));
    const std::size_t stride = x.rows <= cases ? 1 : (x.rows + cases - 1) / cases;
    ind.case_errors.clear();
    for (std::size_t i = 0; i < x.rows; i += stride) {
      const double e = std::abs(y[i] - f[i]);
      ind.case_errors.push_back(std::isfinite(e) ? e : HUGE_VAL);
    }
  }
}

Expression SymbolicRegressor::materialize(const ScaledModel& model, double y_scale) {
  std::vector<Node> nodes;
  const bool keep_offset = std::abs(model.offset) > 1e-10 * y_scale;
  const bool keep_scale = std::abs(model.scale - 1.0) > 1e-10;
  if (keep_offset) {
    nodes.push_back(Node::function(Op::Add));
    nodes.push_back(Node::constant(model.offset));
  }
  if (keep_scale) {
    nodes.push_back(Node::function(Op::Mul));
    nodes.push_back(Node::constant(model.scale));
  }
  nodes.insert(nodes.end(), model.tree.nodes().begin(), model.tree.nodes().end());
  constexpr auto mode = SimplifyMode::Algebraic;
  const Expression expanded = expand_polynomials(simplify(Expression(std::move(nodes)), mode));
  return simplify(snap_constants(simplify(expanded, mode)), mode);
}

SymbolicRegressor::Individual SymbolicRegressor::offspring(const std::vector<Individual>& pop,
                                                          const std::vector<double>& penalised,
                                                          const GeneticOperators& ops,
                                                          const LexicaseSelector* lexicase, Rng& rng) const {
  auto tournament = [&] {
    if (lexicase != nullptr) return lexicase->select(rng);
    std::size_t best = pop.size();
    for (int t = 0; t < settings_.tournament_size; ++t) {
      const std::size_t j = std::uniform_int_distribution<std::size_t>(0, pop.size() - 1)(rng);
      if (best == pop.size() || penalised[j] < penalised[best]) best = j;
    }
    return best;
  };
  const Individual& parent = pop[tournament()];
  const double method = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  double cumulative = settings_.p_crossover;
  Expression tree;
  if (method < cumulative) {
    tree = ops.crossover(parent.model.tree, pop[tournament()].model.tree, rng);
  } else if (method < (cumulative += settings_.p_subtree_mutation)) {
    tree = ops.subtree_mutation(parent.model.tree, rng);
  } else if (method < (cumulative += settings_.p_hoist_mutation)) {
    tree = ops.hoist_mutation(parent.model.tree, rng);
  } else if (method < (cumulative += settings_.p_point_mutation)) {
    tree = ops.point_mutation(parent.model.tree, rng);
  }
  const bool too_long = settings_.max_length > 0 && tree.size() > static_cast<std::size_t>(settings_.max_length);
  if (tree.empty() || too_long) {   // reproduction (also instead of an offspring over the length limit)
    Individual copy = parent;
    copy.evaluations = 0;
    return copy;
  }
  Individual child;
  child.model.tree = std::move(tree);
  child.loss = std::numeric_limits<double>::quiet_NaN();   // marks "to evaluate"
  return child;
}

void SymbolicRegressor::record(const std::vector<Individual>& pop, const DataView& x, std::span<const double> y,
                               double y_scale, ParetoFront& archive, SearchResult& result) const {
  // Only dimensionally consistent programs are recorded: the front and the best hold no inconsistent formula.
  std::size_t best = pop.size();
  std::vector<std::size_t> best_of_length(pop.size() + 1, pop.size());
  for (std::size_t i = 0; i < pop.size(); ++i) {
    if (!pop[i].consistent) continue;
    if (best == pop.size() || pop[i].loss < pop[best].loss) best = i;
    const std::size_t len = std::min(pop[i].model.tree.size(), pop.size());
    if (best_of_length[len] == pop.size() || pop[i].loss < pop[best_of_length[len]].loss) best_of_length[len] = i;
  }
  if (best < pop.size() && (result.best.empty() || pop[best].loss < result.best_loss)) {
    result.best_loss = pop[best].loss;
    result.best = materialize(pop[best].model, y_scale);
  }
  std::vector<double> f(x.rows);
  for (std::size_t i : best_of_length) {
    if (i == pop.size() || !std::isfinite(pop[i].loss)) continue;
    Expression e = materialize(pop[i].model, y_scale);
    CompiledProgram(e).evaluate(x, f);
    const double l = loss(settings_.metric, y, f);
    archive.offer({.complexity = e.size(), .loss = l, .expression = std::move(e)});
  }
}

SearchResult SymbolicRegressor::fit(const DataView& x, std::span<const double> y) const {
  const GeneticOperators ops(settings_, x.columns.size());
  std::vector<double> y_lm;
  const ColumnData lm_rows = strided_rows(x, static_cast<std::size_t>(settings_.lm_max_rows), y_lm, y);
  const DataView x_lm = lm_rows.view();
  double y_scale = 0.0;
  for (double v : y) y_scale += std::abs(v) / static_cast<double>(y.size());
  if (!(y_scale > 0.0)) y_scale = 1.0;
  const auto n = static_cast<std::size_t>(settings_.population_size);
  std::vector<Individual> pop(n);
  std::vector<Individual> next(n);
  ParetoFront archive;
  SearchResult result;
  const auto start = std::chrono::steady_clock::now();
  // With restarts, a fresh random population starts every `epoch` generations; the archive carries over.
  const int epoch = std::max(1, settings_.generations / std::max(1, settings_.restarts));
  for (int gen = 0; gen < settings_.generations; ++gen) {
    const bool fresh = gen % epoch == 0 && gen / epoch < std::max(1, settings_.restarts);
    std::vector<double> penalised(n);
    const double c = settings_.parsimony_coefficient < 0.0 && !fresh ? auto_parsimony(pop) : settings_.parsimony_coefficient;
    for (std::size_t i = 0; i < n && !fresh; ++i) {
      penalised[i] = pop[i].loss + c * static_cast<double>(pop[i].model.tree.size());
      if (!std::isfinite(penalised[i])) penalised[i] = std::numeric_limits<double>::infinity();
      // A dimensionally inconsistent program loses every tournament against a consistent one (PySR's penalty,
      // made absolute: it still breeds when a tournament draws nothing else).
      if (!pop[i].consistent) penalised[i] = std::numeric_limits<double>::max();
    }
    if (!fresh && settings_.penalise_duplicates) penalise_clones(pop, penalised);
    std::unique_ptr<LexicaseSelector> lexicase;
    if (!fresh && settings_.lexicase) {
      std::vector<const std::vector<double>*> errors;
      std::vector<bool> eligible;
      for (std::size_t i = 0; i < n; ++i) {
        errors.push_back(&pop[i].case_errors);
        eligible.push_back(std::isfinite(penalised[i]));
      }
      lexicase = std::make_unique<LexicaseSelector>(std::move(errors), eligible);
    }
#pragma omp parallel for schedule(dynamic, 8) num_threads(std::max(1, settings_.threads))
    for (std::size_t i = 0; i < n; ++i) {
      Rng rng = rng_for(settings_.seed, gen, i);
      if (fresh) {
        next[i] = Individual{};
        next[i].model.tree = ops.random_program(rng);
      } else {
        next[i] = offspring(pop, penalised, ops, lexicase.get(), rng);
      }
      if (fresh || std::isnan(next[i].loss)) evaluate(next[i], x, y, x_lm, y_lm);
    }
    pop.swap(next);
    for (const auto& ind : pop) result.evaluations += ind.evaluations;
    record(pop, x, y, y_scale, archive, result);
    result.generations_run = gen + 1;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!result.best.empty() && result.best_loss <= settings_.stopping_criteria) break;
    if (settings_.max_seconds > 0.0 && seconds > settings_.max_seconds) break;
  }
  result.front = archive.front();
  return result;
}

}  // namespace hs::regression
