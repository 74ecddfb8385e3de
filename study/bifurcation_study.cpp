// SPDX-License-Identifier: MIT
// `hemoscale study bifurcation`: the three angles, their table and figures.
#include "study/bifurcation_study.hpp"

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/check_list.hpp"
#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"
#include "common/run_folder.hpp"
#include "study/bifurcation_statistics.hpp"
#include "study/csv_table.hpp"
#include "unresolved/cases/open_geometry.hpp"

namespace hs::study {
namespace {

namespace fs = std::filesystem;

constexpr double kAngles[] = {30.0, 60.0, 90.0};

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw hs::common::ConfigError(fmt::format("{}: cannot read", file.string()));
  return nlohmann::json::parse(in);
}

/// Runs one angle unless its run folder holds a finished run of the same kind; returns what it did.
std::string run_angle(const fs::path& case_dir, const fs::path& run_dir, bool quick) {
  const fs::path summary = run_dir / "summary.json";
  if (fs::exists(summary)) {
    if (read_json(summary).value("quick", false) != quick) {
      throw hs::common::ConfigError(fmt::format("{}: holds a {} run; give another --output", run_dir.string(), quick ? "full" : "--quick"));
    }
    return "finished run kept";
  }
  const bool resume = fs::exists(run_dir / "checkpoint");
  if (fs::exists(run_dir) && !resume) {
    throw hs::common::ConfigError(fmt::format("{}: neither finished nor resumable (no checkpoint); remove it to rerun", run_dir.string()));
  }
  auto config = hs::common::ConfigFile::load(case_dir / "case.toml");
  if (config->root().section("case").string("type") != "open-geometry") {
    throw hs::common::ConfigError(fmt::format("{}: the study expects case type open-geometry", (case_dir / "case.toml").string()));
  }
  const hs::common::CaseRequest request{.case_dir = case_dir, .config = config.get(), .output_dir = run_dir,
                                        .resume = resume, .quiet = true, .quick = quick};
  const int rc = hs::unresolved::run_open_geometry(request);
  return fmt::format("{} (exit {})", resume ? "resumed" : "ran", rc);
}

/// The CSV's columns: the table row's keys in this order.
const std::vector<std::string>& table_columns() {
  static const std::vector<std::string> cols{
      "angle_deg", "s_h_daughter", "s_h_daughter_se", "s_h_outlet", "s_h_outlet_se", "di_av", "di_av_se", "di_fraction_above",
      "di_av_parent", "di_av_outlet", "di_av_daughter", "blood_flux_fraction_daughter", "blood_flux_fraction_daughter_se",
      "rbc_flux_fraction_daughter", "rbc_flux_fraction_daughter_se", "blood_flux_fraction_outlet", "rbc_flux_fraction_outlet",
      "cut_hematocrit_daughter", "cut_hematocrit_outlet", "steady_start_s", "window_steps", "cells_injected", "wall_time_s"};
  return cols;
}

/// Runs (or keeps) one case folder and returns its table row with the statistics; adds its checks.
nlohmann::json run_and_measure(const fs::path& cases, const fs::path& out, const std::string& name, double angle, bool quick,
                               hs::common::CheckList& checks) {
  const fs::path run_dir = out / name;
  fmt::print("study bifurcation: {}: {}\n", name, run_angle(cases / name, run_dir, quick));
  std::fflush(stdout);
  const nlohmann::json summary = read_json(run_dir / "summary.json");
  const CsvTable series = read_csv_table(run_dir / "timeseries.csv");
  const nlohmann::json stats = bifurcation_statistics(summary["results"]["study_layout"], series.columns, series.rows);
  checks.expect(name + ": the run's own checks (open-geometry)", summary["passed"].get<bool>(),
                fmt::format("{} failed, {} skipped", summary["checks_failed"].get<int>(), summary["checks_skipped"].get<int>()));
  check_bifurcation_study(stats, quick, name + ": ", checks);
  if (stats.contains("too_short")) return {};
  nlohmann::json row = bifurcation_table_row(angle, summary, stats);
  row["statistics"] = stats;
  row["run_folder"] = fs::absolute(run_dir).string();
  row["paraview"] = {(fs::absolute(run_dir) / "particles.pvd").string(), (fs::absolute(run_dir) / "fields.pvd").string()};
  return row;
}

/// The mesh check: angle-90 against angle-90-coarse (dx 3 vs 3.75 um): both values and their difference.
nlohmann::json mesh_check(const nlohmann::json& fine, const nlohmann::json& coarse) {
  nlohmann::json j{{"fine_dx_m", 3e-6}, {"coarse_dx_m", 3.75e-6}};
  for (const char* k : {"s_h_daughter", "s_h_outlet", "di_av", "rbc_flux_fraction_daughter", "blood_flux_fraction_daughter"}) {
    j[k] = {{"fine", fine[k]}, {"coarse", coarse[k]}, {"coarse_minus_fine", coarse[k].get<double>() - fine[k].get<double>()}};
  }
  return j;
}

void draw_figures(const fs::path& json, const fs::path& dir) {
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}' '{}'", (fs::path(HS_SOURCE_DIR) / "tools/plot_bifurcation.py").string(),
                                      json.string(), dir.string());
  if (std::system(cmd.c_str()) != 0) fmt::print("study bifurcation: the figures were not drawn ({})\n", cmd);
}

}  // namespace

nlohmann::json bifurcation_table_row(double angle_deg, const nlohmann::json& summary, const nlohmann::json& s) {
  const auto& d = s["branches"]["daughter"];
  const auto& o = s["branches"]["outlet"];
  const auto& di = s["di"];
  return {{"angle_deg", angle_deg}, {"s_h_daughter", d["s_h"]}, {"s_h_daughter_se", d["s_h_se"]}, {"s_h_outlet", o["s_h"]},
          {"s_h_outlet_se", o["s_h_se"]}, {"di_av", di["all"]["di_av"]}, {"di_av_se", di["all"]["di_av_se"]},
          {"di_fraction_above", di["all"]["fraction_above"]}, {"di_av_parent", di["parent"]["di_av"]},
          {"di_av_outlet", di["outlet"]["di_av"]}, {"di_av_daughter", di["daughter"]["di_av"]},
          {"blood_flux_fraction_daughter", d.value("blood_flux_fraction", 0.0)},
          {"blood_flux_fraction_daughter_se", d.value("blood_flux_fraction_se", 0.0)},
          {"rbc_flux_fraction_daughter", d.value("rbc_flux_fraction", 0.0)},
          {"rbc_flux_fraction_daughter_se", d.value("rbc_flux_fraction_se", 0.0)},
          {"blood_flux_fraction_outlet", o.value("blood_flux_fraction", 0.0)}, {"rbc_flux_fraction_outlet", o.value("rbc_flux_fraction", 0.0)},
          {"cut_hematocrit_daughter", d["cut_hematocrit"]}, {"cut_hematocrit_outlet", o["cut_hematocrit"]},
          {"steady_start_s", s["window_start_time_s"]}, {"window_steps", static_cast<double>(s["steady"]["window_steps"].get<long>())},
          {"cells_injected", static_cast<double>(summary["results"]["cells_injected"].get<long>())},
          {"wall_time_s", summary.value("wall_time_s", 0.0)}};
}

int study_bifurcation(const hs::common::StudyOptions& options) {
  const fs::path cases = fs::path(HS_SOURCE_DIR) / "cases/unresolved/bifurcation";
  const fs::path out = options.output_dir ? *options.output_dir : cases / "runs" / (options.quick ? "study-quick" : "study");
  fs::create_directories(out);
  hs::common::CheckList checks;
  nlohmann::json table{{"study", "bifurcation"}, {"quick", options.quick}};
  hs::common::CsvWriter csv(out / "bifurcation_table.csv", table_columns());
  for (const double a : kAngles) {
    const std::string name = fmt::format("angle-{:.0f}", a);
    nlohmann::json row = run_and_measure(cases, out, name, a, options.quick, checks);
    if (row.is_null()) continue;
    std::vector<double> values;
    for (const auto& c : table_columns()) values.push_back(row[c].get<double>());
    csv.row(values);
    table[fmt::format("angle_{:.0f}", a)] = row;
  }
  // The mesh check (not --quick): the 90 deg device again at dx = 3.75 um.
  if (!options.quick && fs::exists(cases / "angle-90-coarse") && table.contains("angle_90")) {
    const nlohmann::json coarse = run_and_measure(cases, out, "angle-90-coarse", 90.0, false, checks);
    if (!coarse.is_null()) {
      table["angle_90_coarse"] = coarse;
      table["mesh_check_90"] = mesh_check(table["angle_90"], coarse);
    }
  }
  checks.write_to(table);
  table["provenance"] = hs::common::provenance();
  const fs::path json = out / "bifurcation_table.json";
  hs::common::write_json(json, table);
  if (!options.quick) draw_figures(json, out);
  fmt::print("study bifurcation: table {} and {}{}\n", (out / "bifurcation_table.csv").string(), json.string(),
             options.quick ? " (--quick: 20 steps per angle, no steady-state checks, no figures)" : "");
  checks.print("study bifurcation");
  return checks.exit_code();
}

}  // namespace hs::study
