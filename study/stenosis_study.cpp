// SPDX-License-Identifier: MIT
// `hemoscale study stenosis`: both throats, their table, the plasma checks and the figures.
#include "study/stenosis_study.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/check_list.hpp"
#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"
#include "common/run_folder.hpp"
#include "study/csv_table.hpp"
#include "study/stenosis_statistics.hpp"
#include "unresolved/cases/open_geometry.hpp"
#include "unresolved/cases/stenosis_plasma_check.hpp"

namespace hs::study {
namespace {

namespace fs = std::filesystem;

struct Throat {
  const char* folder;
  const char* key;
};
constexpr Throat kThroats[] = {{"throat-85um", "throat_85um"}, {"throat-55um", "throat_55um"}};

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw hs::common::ConfigError(fmt::format("{}: cannot read", file.string()));
  return nlohmann::json::parse(in);
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// What decides a run's result: the case file's values with every default filled in (its resolved table: a comment
/// edited does not count), the closure files' text and --quick (the build's solver is not in it: a rebuilt binary
/// keeps an archived run, as the Pries archive does).
std::string fingerprint(const hs::common::ConfigFile& file, const hs::unresolved::OpenGeometryConfig& c, bool quick) {
  std::ostringstream values;
  values << file.resolved();
  std::string text = values.str();
  for (const auto* spec : {&c.model.drag, &c.model.lift, &c.model.deformation}) {
    if (spec->model == "expression") text += read_text(spec->file);
  }
  return fmt::format("{:016x}{}", std::hash<std::string>{}(text), quick ? "-quick" : "");
}

/// The case file of a throat, its [case] type read (open-geometry, else ConfigError).
std::unique_ptr<hs::common::ConfigFile> load_case(const fs::path& case_dir) {
  auto config = hs::common::ConfigFile::load(case_dir / "case.toml");
  if (config->root().section("case").string("type") != "open-geometry") {
    throw hs::common::ConfigError(fmt::format("{}: the study expects case type open-geometry", (case_dir / "case.toml").string()));
  }
  return config;
}

/// Runs one throat unless its folder holds a finished run with this fingerprint; returns what it did.
std::string run_throat(const fs::path& case_dir, const fs::path& run_dir, bool quick) {
  const auto parsed = load_case(case_dir);
  const std::string key = fingerprint(*parsed, hs::unresolved::parse_open_geometry(*parsed, quick), quick);
  const auto config = load_case(case_dir);   // parse_open_geometry finished the first one
  const fs::path stamp = fs::path(run_dir.string() + ".fingerprint");
  const bool exists = fs::exists(run_dir);
  if (exists && (!fs::exists(stamp) || read_text(stamp) != key)) {
    throw hs::common::ConfigError(fmt::format("{}: holds a run of another case file, closure set or --quick (fingerprint {} "
                                              "!= {}); remove it to rerun", run_dir.string(),
                                              fs::exists(stamp) ? read_text(stamp) : "missing", key));
  }
  if (fs::exists(run_dir / "summary.json")) return fmt::format("finished run kept (fingerprint {})", key);
  const bool resume = fs::exists(run_dir / "checkpoint");
  if (exists && !resume) {
    throw hs::common::ConfigError(fmt::format("{}: neither finished nor resumable (no checkpoint); remove it to rerun", run_dir.string()));
  }
  std::ofstream(stamp) << key;
  const hs::common::CaseRequest request{.case_dir = case_dir, .config = config.get(), .output_dir = run_dir,
                                        .resume = resume, .quiet = true, .quick = quick};
  const int rc = hs::unresolved::run_open_geometry(request);
  return fmt::format("{} (exit {})", resume ? "resumed" : "ran", rc);
}

/// The CSV's columns: the table row's keys in this order.
const std::vector<std::string>& table_columns() {
  static const std::vector<std::string> cols{
      "throat_m", "di_max", "di_max_se", "di_max_sd", "x_di_max_m", "x_di_max_from_throat_m", "di_upstream", "di_upstream_se",
      "di_downstream", "di_downstream_se", "outside_share_upstream", "outside_share_downstream", "outside_share_max",
      "x_outside_share_max_m", "hemolysis_median_percent", "hemolysis_p99_percent", "hemolysis_max_percent", "cells_left",
      "steady_start_s", "window_steps", "cells_injected", "fluid_balance_pct", "wall_time_s"};
  return cols;
}

/// Runs (or keeps) one throat and returns its table row with the statistics; adds its checks.
nlohmann::json run_and_measure(const fs::path& cases, const fs::path& out, const std::string& name, bool quick,
                               hs::common::CheckList& checks) {
  const fs::path run_dir = out / name;
  fmt::print("study stenosis: {}: {}\n", name, run_throat(cases / name, run_dir, quick));
  std::fflush(stdout);
  const nlohmann::json summary = read_json(run_dir / "summary.json");
  const CsvTable series = read_csv_table(run_dir / "timeseries.csv");
  const nlohmann::json& layout = summary["results"]["study_layout"];
  const nlohmann::json stats = stenosis_statistics(layout, series.columns, series.rows);
  checks.expect(name + ": the run's own checks (open-geometry)", summary["passed"].get<bool>(),
                fmt::format("{} failed, {} skipped", summary["checks_failed"].get<int>(), summary["checks_skipped"].get<int>()));
  check_stenosis_study(stats, quick, name + ": ", checks);
  if (stats.contains("too_short") || stats["di_max"].is_null()) return {};
  nlohmann::json row = stenosis_table_row(layout["throat_radius_m"].get<double>() * 2.0, summary, stats);
  row["statistics"] = stats;
  row["hemolysis"] = summary["results"]["hemolysis"];
  row["closure_validity"] = summary["results"]["closure_validity"];
  row["layout"] = layout;
  row["run_folder"] = fs::absolute(run_dir).string();
  row["paraview"] = {(fs::absolute(run_dir) / "particles.pvd").string(), (fs::absolute(run_dir) / "fields.pvd").string()};
  return row;
}

/// The plasma-only check of one throat: the case's dx and dx / 2; the grid error of the pressure drop is the
/// difference over the fine value, and Richardson's second-order extrapolation gives the converged estimate.
nlohmann::json plasma_check(const fs::path& case_dir, bool quick, const std::string& name, hs::common::CheckList& checks) {
  const hs::unresolved::OpenGeometryConfig c = hs::unresolved::parse_open_geometry(*load_case(case_dir), false);
  const long max_steps = quick ? 5 : 4000;   // --quick: the pipeline only (Stokes flow settles in ~20 steps)
  const auto coarse = hs::unresolved::run_stenosis_plasma(c, c.dx_m, max_steps);
  const auto fine = hs::unresolved::run_stenosis_plasma(c, 0.5 * c.dx_m, max_steps);
  const double extrapolated = fine.pressure_drop_Pa + (fine.pressure_drop_Pa - coarse.pressure_drop_Pa) / 3.0;
  nlohmann::json j{{"coarse", coarse.to_json()}, {"fine", fine.to_json()},
                   {"grid_error_coarse_pct", 100.0 * (coarse.pressure_drop_Pa / fine.pressure_drop_Pa - 1.0)},
                   {"richardson_drop_Pa", extrapolated},
                   {"fine_error_vs_richardson_pct", 100.0 * (fine.pressure_drop_Pa / extrapolated - 1.0)},
                   {"coarse_error_vs_richardson_pct", 100.0 * (coarse.pressure_drop_Pa / extrapolated - 1.0)}};
  if (quick) {
    checks.skip(name + ": plasma check", "--quick: 5 steps, not steady");
    return j;
  }
  // The flow is steady Stokes flow (Re < 0.3): the pressure drop must have converged in time.
  checks.expect(name + ": plasma runs reached their steady state", coarse.steps < max_steps && fine.steps < max_steps,
                fmt::format("{} and {} steps (limit {})", coarse.steps, fine.steps, max_steps));
  return j;
}

void draw_figures(const fs::path& json, const fs::path& dir) {
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}' '{}'", (fs::path(HS_SOURCE_DIR) / "tools/plot_stenosis_study.py").string(),
                                      json.string(), dir.string());
  if (std::system(cmd.c_str()) != 0) fmt::print("study stenosis: the figures were not drawn ({})\n", cmd);
}

}  // namespace

nlohmann::json stenosis_table_row(double throat_m, const nlohmann::json& summary, const nlohmann::json& s) {
  const auto& best = s["di_max"];
  double out_max = 0.0;
  double x_out_max = 0.0;
  for (const auto& b : s["profile"]) {
    if (b["outside_any_share"].get<double>() > out_max) {
      out_max = b["outside_any_share"].get<double>();
      x_out_max = b["x_m"].get<double>();
    }
  }
  const auto& hemo = summary["results"]["hemolysis"]["index_percent"];
  return {{"throat_m", throat_m}, {"di_max", best["value"]}, {"di_max_se", best["se"]}, {"di_max_sd", best["sd"]},
          {"x_di_max_m", best["x_m"]}, {"x_di_max_from_throat_m", best["from_throat_m"]},
          {"di_upstream", s["di_upstream"]["mean"]}, {"di_upstream_se", s["di_upstream"]["se"]},
          {"di_downstream", s["di_downstream"]["mean"]}, {"di_downstream_se", s["di_downstream"]["se"]},
          {"outside_share_upstream", s["di_upstream"]["outside_any_share"]},
          {"outside_share_downstream", s["di_downstream"]["outside_any_share"]}, {"outside_share_max", out_max},
          {"x_outside_share_max_m", x_out_max}, {"hemolysis_median_percent", hemo["median"]},
          {"hemolysis_p99_percent", hemo["p99"]}, {"hemolysis_max_percent", hemo["max"]},
          {"cells_left", static_cast<double>(hemo["count"].get<long>())}, {"steady_start_s", s["window_start_time_s"]},
          {"window_steps", static_cast<double>(s["steady"]["window_steps"].get<long>())},
          {"cells_injected", static_cast<double>(summary["results"]["cells_injected"].get<long>())},
          {"fluid_balance_pct", s["conservation"]["fluid_balance_pct"]}, {"wall_time_s", summary.value("wall_time_s", 0.0)}};
}

int study_stenosis(const hs::common::StudyOptions& options) {
  const fs::path cases = fs::path(HS_SOURCE_DIR) / "cases/unresolved/stenosis";
  const fs::path out = options.output_dir ? *options.output_dir : cases / "runs" / (options.quick ? "study-quick" : "study");
  fs::create_directories(out);
  hs::common::CheckList checks;
  nlohmann::json table{{"study", "stenosis"}, {"quick", options.quick}};
  hs::common::CsvWriter csv(out / "stenosis_table.csv", table_columns());
  for (const Throat& t : kThroats) {
    nlohmann::json row = run_and_measure(cases, out, t.folder, options.quick, checks);
    if (row.is_null()) continue;
    row["plasma_check"] = plasma_check(cases / t.folder, options.quick, t.folder, checks);
    std::vector<double> values;
    for (const auto& c : table_columns()) values.push_back(row[c].get<double>());
    csv.row(values);
    table[t.key] = row;
  }
  // The mesh check (not --quick): throat-55um-fine, the 55 um case on a finer grid.
  if (!options.quick && fs::exists(cases / "throat-55um-fine") && table.contains("throat_55um")) {
    const nlohmann::json fine = run_and_measure(cases, out, "throat-55um-fine", false, checks);
    if (!fine.is_null()) {
      table["throat_55um_fine"] = fine;
      const nlohmann::json& coarse = table["throat_55um"];
      nlohmann::json m{{"coarse_dx_m", coarse["layout"]["dx_m"]}, {"fine_dx_m", fine["layout"]["dx_m"]}};
      for (const char* k : {"di_max", "x_di_max_m", "di_upstream", "di_downstream"}) {
        const double f = fine[k].get<double>();
        const double g = coarse[k].get<double>();
        m[k] = {{"fine", f}, {"coarse", g}, {"coarse_minus_fine", g - f}};
      }
      // <DI>(x) bin by bin (the same bins): the largest difference and where.
      double worst = 0.0;
      double x_worst = 0.0;
      const auto& pf = fine["statistics"]["profile"];
      const auto& pc = coarse["statistics"]["profile"];
      for (std::size_t i = 0; i < pf.size() && i < pc.size(); ++i) {
        if (pf[i]["cell_samples"].get<double>() < kMinBinSamples || pc[i]["cell_samples"].get<double>() < kMinBinSamples) continue;
        const double d = pc[i]["di_mean"].get<double>() - pf[i]["di_mean"].get<double>();
        if (std::abs(d) > std::abs(worst)) {
          worst = d;
          x_worst = pf[i]["x_m"].get<double>();
        }
      }
      m["di_profile_max_coarse_minus_fine"] = worst;
      m["di_profile_x_of_max_m"] = x_worst;
      table["mesh_check_55um"] = m;
    }
  }
  checks.write_to(table);
  table["provenance"] = hs::common::provenance();
  const fs::path json = out / "stenosis_table.json";
  hs::common::write_json(json, table);
  if (!options.quick) draw_figures(json, out);
  fmt::print("study stenosis: table {} and {}{}\n", (out / "stenosis_table.csv").string(), json.string(),
             options.quick ? " (--quick: 20 steps per throat, no steady-state checks, no figures)" : "");
  checks.print("study stenosis");
  return checks.exit_code();
}

}  // namespace hs::study
