// SPDX-License-Identifier: MIT
// Fitting a closure from a dataset and writing the closure file and its companions.
#include "closures/closure_fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <fstream>
#include <random>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "build_info.hpp"
#include "closures/sha256.hpp"
#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"
#include "common/peak_memory.hpp"
#include "common/run_folder.hpp"
#include "common/summary_schema.hpp"
#include "regression/bootstrap_constants.hpp"
#include "regression/cancellation.hpp"
#include "regression/compiled_program.hpp"
#include "regression/data_view.hpp"
#include "regression/infix.hpp"

namespace hs::closures {
namespace {

namespace hsr = hs::regression;
using hs::common::ConfigError;

struct Table {
  std::vector<std::vector<double>> x;
  std::vector<double> y;
};

Table load_dataset(const FitRequest& r) {
  const auto csv = hs::common::read_csv(r.dataset);
  auto column = [&](const std::string& name, const char* key) {
    if (csv.column_index(name) < 0) {
      std::string known;
      for (const auto& c : csv.columns) known += (known.empty() ? "" : ", ") + c;
      throw ConfigError(fmt::format("{}: [data] {} = \"{}\": no such column in {} (columns: {})", r.fit_file.string(),
                                    key, name, r.dataset.string(), known));
    }
    auto v = csv.column(name);
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!std::isfinite(v[i])) {
        throw ConfigError(fmt::format("{}: column \"{}\" row {} is not a finite number", r.dataset.string(), name, i + 1));
      }
    }
    return v;
  };
  // A derived feature: its expression evaluated on each row (variables: the dataset's columns).
  auto derived = [&](const std::string& name, const std::string& text) {
    hsr::Expression e;
    try {
      e = hsr::parse_infix(text, csv.columns);
    } catch (const std::exception& ex) {
      throw ConfigError(fmt::format("{}: [data.derived] {} = \"{}\": {} (variables: the columns of {})", r.fit_file.string(),
                                    name, text, ex.what(), r.dataset.string()));
    }
    if (csv.column_index(name) >= 0) {
      throw ConfigError(fmt::format("{}: [data.derived] {}: {} has a column of that name; name the derived feature "
                                    "otherwise", r.fit_file.string(), name, r.dataset.string()));
    }
    std::vector<double> v;
    for (std::size_t i = 0; i < csv.rows.size(); ++i) {
      // The operators are protected (a division by ~0 gives 1): a missing input must not slip through as a number.
      for (const std::size_t k : e.variables()) {
        if (!std::isfinite(csv.rows[i][k])) {
          throw ConfigError(fmt::format("{}: column \"{}\" row {} is not a finite number ([data.derived] {})",
                                        r.dataset.string(), csv.columns[k], i + 1, name));
        }
      }
      v.push_back(e.evaluate(csv.rows[i].data()));
      if (!std::isfinite(v.back())) {
        throw ConfigError(fmt::format("{}: [data.derived] {} is not a finite number in row {} of {}", r.fit_file.string(),
                                      name, i + 1, r.dataset.string()));
      }
    }
    return v;
  };
  Table t;
  for (const auto& f : r.features) {
    const auto d = std::find_if(r.derived.begin(), r.derived.end(), [&](const auto& p) { return p.first == f; });
    t.x.push_back(d != r.derived.end() ? derived(d->first, d->second) : column(f, "features"));
  }
  t.y = column(r.target, "target");
  if (t.y.size() < 10) throw ConfigError(fmt::format("{}: {} rows; at least 10 are needed", r.dataset.string(), t.y.size()));
  return t;
}

void add_scores(ClosureFile& c, const char* tag, const hsr::Scores& s) {
  c.fit[fmt::format("r2_{}", tag)] = s.r2;
  c.fit[fmt::format("rmse_{}", tag)] = s.rmse;
  c.fit[fmt::format("mae_{}", tag)] = s.mae;
}

/// Bootstrap replicates of the constants refitted on (pairs bootstrap, Efron & Tibshirani 1993).
constexpr int kBootstrapReplicates = 50;

/// [uncertainty] and the fit's summary of it: the 95% band's half-width relative to the prediction over 256 seeded
/// points of the validity box (median and max), and the cancellation ratio of the formula on its training rows.
void add_uncertainty(ClosureFile& c, const FitRequest& r, const Table& t, const hsr::ValidatedModel& m) {
  const hsr::ColumnData train = hsr::ColumnData::pick(t.x, m.split.train);
  std::vector<double> y_train;
  for (std::size_t i : m.split.train) y_train.push_back(t.y[i]);
  std::vector<std::vector<double>> x_train(t.x.size());
  for (std::size_t j = 0; j < t.x.size(); ++j) {
    for (std::size_t i : m.split.train) x_train[j].push_back(t.x[j][i]);
  }
  c.bootstrap_constants = hsr::bootstrap_constants(m.expression, x_train, y_train, kBootstrapReplicates,
                                                   r.search.seed + 7, r.validation.refit_iterations);
  c.residual_rmse = r.validation.folds > 1 ? m.cv.rmse : m.train.rmse;
  std::mt19937_64 rng(r.search.seed + 11);
  std::vector<double> relative, point(c.validity.size());
  for (int k = 0; k < 256; ++k) {
    for (std::size_t j = 0; j < point.size(); ++j) {
      point[j] = std::uniform_real_distribution<double>(c.validity[j].lo, c.validity[j].hi)(rng);
    }
    const auto band = c.prediction_interval(point);
    const double centre = hsr::CompiledProgram(m.expression).evaluate_point(point.data());
    if (band && std::abs(centre) > 0.0) relative.push_back((band->second - band->first) / 2.0 / std::abs(centre));
  }
  std::sort(relative.begin(), relative.end());
  if (!relative.empty()) {
    c.fit["pi95_relative_half_width_median"] = relative[relative.size() / 2];
    c.fit["pi95_relative_half_width_max"] = relative.back();
  }
  c.fit["cancellation_ratio"] = hsr::cancellation_ratio(m.expression, train.view());
}

ClosureFile make_closure(const FitRequest& r, const Table& t, const hsr::ValidatedModel& m) {
  ClosureFile c;
  c.name = r.name;
  c.kind = r.kind;
  c.output = r.output;
  c.reference_velocity = r.reference_velocity;
  c.expression = hsr::to_infix(m.expression, r.features);
  if (!(hsr::parse_infix(c.expression, r.features) == m.expression)) {
    throw std::logic_error("closure expression does not round-trip through the parser: " + c.expression);
  }
  c.variables = r.features;
  c.definitions = r.definitions;
  if (!r.target_unit.empty()) c.units[r.output] = r.target_unit;
  for (std::size_t j = 0; j < r.features.size(); ++j) {
    if (!r.feature_units[j].empty()) c.units[r.features[j]] = r.feature_units[j];
  }
  for (const auto& col : t.x) {
    Interval range{HUGE_VAL, -HUGE_VAL};
    for (std::size_t i : m.split.train) range = {std::min(range.lo, col[i]), std::max(range.hi, col[i])};
    c.validity.push_back(range);
  }
  add_uncertainty(c, r, t, m);
  add_scores(c, "train", m.train);
  add_scores(c, "cv", m.cv);
  add_scores(c, "test", m.test);
  c.fit["complexity"] = static_cast<double>(m.expression.size());
  c.fit["n_train"] = static_cast<double>(m.split.train.size());
  c.fit["n_test"] = static_cast<double>(m.split.test.size());
  c.fit["folds"] = r.validation.folds;
  c.fit["generations_run"] = m.search.generations_run;
  c.fit["evaluations"] = static_cast<double>(m.search.evaluations);
  for (const auto& p : m.front) {
    c.pareto.push_back({p.complexity, p.loss, p.cv_loss, hsr::to_infix(p.expression, r.features)});
  }
  c.dataset = r.dataset.lexically_normal().string();   // run_fit makes it relative to the closure file
  c.dataset_sha256 = sha256_file(r.dataset);
  c.seed = static_cast<std::int64_t>(r.search.seed);
  c.threads = r.search.threads;
  c.hemoscale_version = hs::common::build_info::version;
  c.git_commit = hs::common::build_info::git_commit;
  return c;
}

void write_tables(const std::filesystem::path& dir, const FitRequest& r, const Table& t, const hsr::ValidatedModel& m,
                  const ClosureFile& c) {
  std::vector<double> p(t.y.size());
  hsr::ColumnData data(t.x);
  hsr::CompiledProgram(m.expression).evaluate(data.view(), p);
  std::vector<std::string> cols{"is_test", r.target, "prediction"};
  cols.insert(cols.end(), r.features.begin(), r.features.end());
  hs::common::CsvWriter pred(dir / "predictions.csv", cols);
  std::vector<bool> is_test(t.y.size(), false);
  for (std::size_t i : m.split.test) is_test[i] = true;
  for (std::size_t i = 0; i < t.y.size(); ++i) {
    std::vector<double> row{is_test[i] ? 1.0 : 0.0, t.y[i], p[i]};
    for (const auto& col : t.x) row.push_back(col[i]);
    pred.row(row);
  }
  hs::common::CsvWriter pareto(dir / "pareto.csv", {"complexity", "loss", "cv_loss"});
  for (const auto& e : c.pareto) pareto.row({static_cast<double>(e.complexity), e.loss, e.cv_loss});
  std::ofstream ref(dir / (r.name + ".reference.csv"));
  for (const auto& f : r.features) ref << f << ",";
  ref << "expected,source\n";
  for (std::size_t i : m.split.test) {
    for (const auto& col : t.x) ref << fmt::format("{},", col[i]);
    ref << fmt::format("{},{}.toml\n", p[i], r.name);
  }
}

}  // namespace

ClosureFile run_fit(const FitRequest& request, const std::filesystem::path& out_dir, bool quiet) {
  const Table table = load_dataset(request);
  const auto t0 = std::chrono::steady_clock::now();
  const auto model = hsr::fit_validated(request.search, request.validation, table.x, table.y);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ClosureFile closure = make_closure(request, table, model);
  std::filesystem::create_directories(out_dir);
  closure.dataset = std::filesystem::relative(std::filesystem::absolute(request.dataset), std::filesystem::absolute(out_dir))
                        .lexically_normal()
                        .string();
  closure.write(out_dir / (request.name + ".toml"));
  write_tables(out_dir, request, table, model, closure);
  // summary.json in the layout of every run (common/summary_schema.hpp): the closure found, how it was searched.
  const nlohmann::json blocks{
      {"results", {{"name", closure.name}, {"kind", closure.kind}, {"expression", closure.expression}, {"fit", closure.fit}}},
      {"numerics", {{"dataset", closure.dataset}, {"dataset_sha256", closure.dataset_sha256}, {"seed", closure.seed},
                    {"threads", closure.threads}}},
      {"timings", {{"search", {{"seconds", seconds}, {"calls", 1}, {"share", 1.0}}}}}};
  hs::common::write_json(out_dir / "summary.json",
                         hs::common::assemble_summary(blocks, {}, {.case_type = "fit", .quick = false, .mpi_ranks = 1,
                                                                   .wall_time_s = seconds,
                                                                   .peak_memory_GiB = hs::common::peak_memory_gib(),
                                                                   .provenance = hs::common::provenance()}));
  if (!quiet) {
    fmt::print("{} = {}\n  R2 train {:.6f}, cv {:.6f}, test {:.6f}; {} generations, {:.1f} s\n", closure.output,
               closure.expression, model.train.r2, model.cv.r2, model.test.r2, model.search.generations_run, seconds);
    if (closure.fit.count("pi95_relative_half_width_median") != 0) {
      fmt::print("  95% prediction interval over the validity box: +-{:.1f}% (median), +-{:.1f}% (max)\n",
                 100.0 * closure.fit.at("pi95_relative_half_width_median"),
                 100.0 * closure.fit.at("pi95_relative_half_width_max"));
    }
  }
  if (closure.fit.at("cancellation_ratio") > hsr::cancellation_warning_ratio) {
    fmt::print(stderr, "warning: {} relies on a cancellation of large terms (they are {:.0f}x the result on the training "
               "rows, median): a small change of the data can change it a lot; prefer a simpler Pareto member\n",
               closure.name, closure.fit.at("cancellation_ratio"));
  }
  return closure;
}

bool render_fit_report(const std::filesystem::path& out_dir) {
  const std::filesystem::path python = "/usr/bin/python3";
  const std::filesystem::path script = std::filesystem::path(HS_TOOLS_DIR) / "plot_fit.py";
  if (!std::filesystem::exists(python) || !std::filesystem::exists(script)) return false;
  const std::string cmd = fmt::format("\"{}\" \"{}\" \"{}\" > /dev/null 2>&1", python.string(), script.string(),
                                      out_dir.string());
  return std::system(cmd.c_str()) == 0 && std::filesystem::exists(out_dir / "report.png");
}

}  // namespace hs::closures
