// SPDX-License-Identifier: MIT
// Strict reading and writing of closure TOML files.
#include "closures/closure_file.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "common/io/atomic_file.hpp"
#include "regression/compiled_program.hpp"
#include "regression/dimension.hpp"
#include "regression/infix.hpp"

namespace hs::closures {
namespace {

using hs::common::ConfigError;
using hs::common::ConfigSection;

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";   // keep it a TOML float
  return s;
}

void read_variables(ConfigSection root, ClosureFile& c) {
  auto vars = root.section("variables");
  for (const auto& name : vars.keys()) {
    if (c.kind != "generic" && !find_input(name)) {
      std::string known;
      for (const auto& v : input_variables) known += (known.empty() ? "" : ", ") + std::string(v.name);
      vars.fail(name, fmt::format("is not a closure input (allowed: {}; kind = \"generic\" allows any name)", known));
    }
    c.variables.push_back(name);
    c.definitions.push_back(vars.string(name));
  }
  if (c.variables.empty()) root.fail("variables", "declares no variable");
}

void read_units(ConfigSection root, ClosureFile& c) {
  auto units = root.section_or_empty("units");
  for (const auto& key : units.keys()) {
    if (key != c.output && std::find(c.variables.begin(), c.variables.end(), key) == c.variables.end()) {
      units.fail(key, fmt::format("is neither the output \"{}\" nor a variable", c.output));
    }
    const std::string text = units.string(key);
    try {
      (void)hs::regression::parse_unit(text);
    } catch (const std::invalid_argument& e) {
      units.fail(key, e.what());
    }
    c.units[key] = text;
  }
}

void read_uncertainty(ConfigSection root, ClosureFile& c) {
  if (!root.has("uncertainty")) return;
  auto u = root.section("uncertainty");
  const auto replicates = static_cast<std::size_t>(u.integer_in("replicates", 1, 100000));
  c.residual_rmse = u.number_in("residual_rmse", 0.0, HUGE_VAL);
  const std::size_t k = c.parsed().constant_positions().size();
  const auto flat = u.has("constants") ? u.numbers_in("constants", -HUGE_VAL, HUGE_VAL, 0) : std::vector<double>{};
  if (flat.size() != replicates * k) {
    u.fail("constants", fmt::format("holds {} numbers; {} replicates x {} constants of the expression need {}",
                                    flat.size(), replicates, k, replicates * k));
  }
  for (std::size_t b = 0; b < replicates; ++b) {
    c.bootstrap_constants.emplace_back(flat.begin() + static_cast<long>(b * k), flat.begin() + static_cast<long>((b + 1) * k));
  }
}

void read_validity(ConfigSection root, ClosureFile& c) {
  if (!root.has("validity")) root.fail("validity", "missing section: every variable needs its validity range [lo, hi]");
  auto validity = root.section("validity");
  for (const auto& name : c.variables) {
    if (!validity.has(name)) validity.fail(name, "missing: every variable needs a validity range [lo, hi]");
    const auto r = validity.numbers_in(name, -HUGE_VAL, HUGE_VAL, 2);
    if (r.size() != 2 || r[0] > r[1]) validity.fail(name, "must be [lo, hi] with lo <= hi");
    c.validity.push_back({r[0], r[1]});
  }
}

void read_pareto(ConfigSection root, ClosureFile& c) {
  auto p = root.section_or_empty("pareto");
  if (!p.has("complexity")) return;
  const auto complexity = p.numbers_in("complexity", 1.0, 1e9);
  const auto loss = p.numbers_in("loss", -HUGE_VAL, HUGE_VAL);
  const auto cv = p.numbers_in("cv_loss", -HUGE_VAL, HUGE_VAL);
  const auto expr = p.strings("expressions");
  if (loss.size() != complexity.size() || cv.size() != complexity.size() || expr.size() != complexity.size()) {
    p.fail("expressions", "complexity, loss, cv_loss and expressions must have the same length");
  }
  for (std::size_t i = 0; i < complexity.size(); ++i) {
    c.pareto.push_back({static_cast<std::size_t>(complexity[i]), loss[i], cv[i], expr[i]});
  }
}

void read_provenance(ConfigSection root, ClosureFile& c) {
  auto p = root.section_or_empty("provenance");
  c.dataset = p.string_or("dataset", "");
  c.dataset_sha256 = p.string_or("dataset_sha256", "");
  c.seed = p.integer_in_or("seed", 0, std::numeric_limits<long>::max(), 0);
  c.threads = p.integer_in_or("threads", 1, 1 << 20, 1);
  c.hemoscale_version = p.string_or("hemoscale_version", "");
  c.git_commit = p.string_or("git_commit", "");
}

}  // namespace

ClosureFile ClosureFile::load(const std::filesystem::path& file) {
  auto config = hs::common::ConfigFile::load(file, "closure file");
  auto root = config->root();
  ClosureFile c;
  c.name = root.string("name");
  c.kind = root.one_of("kind", {"drag", "lift", "deformation", "generic"});
  c.output = root.string("output");
  if (c.kind == "lift") c.reference_velocity = root.one_of_or("reference_velocity", {"slip", "flow"}, "slip");
  c.expression = root.string("expression");
  read_variables(root, c);
  try {
    (void)c.parsed();
  } catch (const hs::regression::ParseError& e) {
    root.fail("expression", e.what());
  }
  read_validity(root, c);
  read_units(root, c);
  read_uncertainty(root, c);
  auto fit = root.section_or_empty("fit");
  for (const auto& key : fit.keys()) c.fit[key] = fit.number_in(key, -HUGE_VAL, HUGE_VAL);
  read_pareto(root, c);
  read_provenance(root, c);
  config->finish();
  return c;
}

hs::regression::Expression ClosureFile::parsed() const { return hs::regression::parse_infix(expression, variables); }

std::optional<std::pair<double, double>> ClosureFile::prediction_interval(std::span<const double> inputs) const {
  if (bootstrap_constants.empty()) return std::nullopt;
  hs::regression::CompiledProgram program(parsed());
  const double centre = program.evaluate_point(inputs.data());
  std::vector<double> p;
  for (const auto& set : bootstrap_constants) {
    program.set_constants(set);
    p.push_back(program.evaluate_point(inputs.data()));
  }
  std::sort(p.begin(), p.end());
  auto quantile = [&](double q) {   // linear interpolation between order statistics
    const double pos = q * static_cast<double>(p.size() - 1);
    const auto i = static_cast<std::size_t>(pos);
    return i + 1 < p.size() ? p[i] + (pos - static_cast<double>(i)) * (p[i + 1] - p[i]) : p.back();
  };
  const double noise = 1.96 * residual_rmse;
  const double below = std::max(0.0, centre - quantile(0.025)), above = std::max(0.0, quantile(0.975) - centre);
  return std::pair{centre - std::hypot(below, noise), centre + std::hypot(above, noise)};
}

void ClosureFile::write(const std::filesystem::path& file) const {
  std::ostringstream s;
  s << "# Learned closure written by `hemoscale fit`. Protected functions (src/regression/op.hpp): `/` gives 1 where "
       "|denominator| <= 0.001;\n# sqrt(x) is sqrt(|x|), log(x) is log(|x|) (0 where |x| <= 0.001), `^` is |a|^b; exp "
       "and `^` saturate at 1e100.\n";
  s << "name       = " << quoted(name) << "\nkind       = " << quoted(kind) << "\noutput     = " << quoted(output)
    << "\nexpression = " << quoted(expression) << "\n";
  if (kind == "lift") {
    s << "reference_velocity = " << quoted(reference_velocity)
      << "   # F_l = (pi/8) rho d_p^2 C_l |u|^2: u = u_f - u_p (slip) or u_f (flow, relative to the walls)\n";
  }
  s << "\n[variables]\n";
  for (std::size_t j = 0; j < variables.size(); ++j) s << variables[j] << " = " << quoted(definitions[j]) << "\n";
  s << "\n[validity]   # min and max of the training inputs\n";
  for (std::size_t j = 0; j < variables.size(); ++j) {
    s << variables[j] << " = [" << number(validity[j].lo) << ", " << number(validity[j].hi) << "]\n";
  }
  if (!units.empty()) {
    s << "\n[units]   # SI; \"1\" = dimensionless\n";
    for (const auto& [k, v] : units) s << k << " = " << quoted(v) << "\n";
  }
  if (!bootstrap_constants.empty()) {
    s << "\n[uncertainty]   # pairs bootstrap of the training rows, the constants refitted per replicate; "
         "ClosureFile::prediction_interval\nreplicates    = " << bootstrap_constants.size()
      << "\nresidual_rmse = " << number(residual_rmse) << "\nconstants     = [";
    for (std::size_t b = 0; b < bootstrap_constants.size(); ++b) {
      s << "\n ";
      for (double v : bootstrap_constants[b]) s << " " << number(v) << ",";
    }
    s << "\n]\n";
  }
  s << "\n[fit]\n";
  for (const auto& [k, v] : fit) s << k << " = " << number(v) << "\n";
  if (!pareto.empty()) {
    std::string cx, loss, cv, ex;
    for (const auto& p : pareto) {
      cx += (cx.empty() ? "" : ", ") + number(static_cast<double>(p.complexity));
      loss += (loss.empty() ? "" : ", ") + number(p.loss);
      cv += (cv.empty() ? "" : ", ") + number(p.cv_loss);
      ex += (ex.empty() ? "\n  " : ",\n  ") + quoted(p.expression);
    }
    s << "\n[pareto]   # complexity (nodes) vs training and cross-validated loss\ncomplexity  = [" << cx
      << "]\nloss        = [" << loss << "]\ncv_loss     = [" << cv << "]\nexpressions = [" << ex << ",\n]\n";
  }
  s << "\n[provenance]\ndataset           = " << quoted(dataset) << "\ndataset_sha256    = " << quoted(dataset_sha256)
    << "\nseed              = " << seed << "\nthreads           = " << threads
    << "\nhemoscale_version = " << quoted(hemoscale_version) << "\ngit_commit        = " << quoted(git_commit) << "\n";
  hs::common::write_file_atomic(file, s.str());
}

}  // namespace hs::closures
