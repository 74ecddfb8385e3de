// SPDX-License-Identifier: MIT
// `hemoscale validate tank-treading`: the dataset of the campaign cases/campaign/shear-fischer-korzeniewski (one
// healthy cell in shear at the capillary numbers of Fischer & Korzeniewski's six shear-rate bins in a 28.9 mPa s medium,
// as their Stokes-flow analogue) against the frequencies they measured on 225 cells. Reads the dataset only: nothing is
// simulated (the campaign is resumable and archived). Per bin the run must exist, tank-tread, have settled (its last two
// whole revolutions within 2 %), turn under the Keller-Skalak bound of its measured axes, and give f / gamma_dot within
// the cells' scatter: mean +- 2 SD of the bin, the range that holds ~95 % of single cells (their SD, 12-22 % of the
// mean, is the spread between cells, far above the error of a bin's mean; one model cell is one typical cell, not the
// mean of many). Across the bins f / gamma_dot must fall from the lowest to the highest shear rate, as measured
// (0.0398 -> 0.0254, 7 standard errors apart). Exit 1 on any failure, naming it.
#include "validate/tank_treading_validation.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/check_list.hpp"
#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"
#include "common/run_folder.hpp"
#include "resolved/cases/plate_cell_config.hpp"
#include "resolved/membrane/membrane_parameters.hpp"

namespace hs::resolved {
namespace {

/// Bands of f / gamma_dot: the bin's mean +- this many of its cell-to-cell SDs.
constexpr double kScatterSds = 2.0;
/// A dataset row belongs to a bin when its Ca is the bin's within this share (the campaign writes Ca to 4 digits).
constexpr double kCaMatch = 0.01;

/// A CSV file as text cells under their column names ('#' lines skipped).
struct TextTable {
  std::vector<std::map<std::string, std::string>> rows;
};

TextTable read_text_table(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw common::ConfigError(fmt::format("{}: cannot read it", file.string()));
  TextTable t;
  std::vector<std::string> header;
  for (std::string line; std::getline(in, line);) {
    if (line.find_first_not_of(" \r") == std::string::npos || line[0] == '#') continue;
    const std::vector<std::string> cells = common::split_csv_line(line);
    if (header.empty()) {
      header = cells;
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t c = 0; c < header.size() && c < cells.size(); ++c) row[header[c]] = cells[c];
    t.rows.push_back(std::move(row));
  }
  return t;
}

double number(const std::map<std::string, std::string>& row, const std::string& column, const std::filesystem::path& file) {
  const auto it = row.find(column);
  if (it == row.end() || it->second.empty()) {
    throw common::ConfigError(fmt::format("{}: a row has no value in column '{}'", file.string(), column));
  }
  return std::strtod(it->second.c_str(), nullptr);
}

std::string text(const std::map<std::string, std::string>& row, const std::string& column) {
  const auto it = row.find(column);
  return it == row.end() ? std::string() : it->second;
}

struct Bin {
  double eta_o_Pa_s = 0.0;
  double shear_rate_1_s = 0.0;
  int cells = 0;
  double mean = 0.0;
  double sd = 0.0;
  double ca = 0.0;   // the model's capillary number at this bin: eta_o gamma_dot a / G_s
};

struct Measured {
  bool present = false;
  std::string flow_mode;
  bool settled = false;
  double f_over_gamma = 0.0;
  double inclination_deg = 0.0;
  double di = 0.0;
  double rate_rad_s = 0.0;     // settled rate 2 pi f
  double bound_rad_s = 0.0;    // Keller-Skalak bound of the measured axes
  double re_p = 0.0;
  double shear_rate_1_s = 0.0;
};

}  // namespace

int validate_tank_treading(const hs::common::TaskOptions& options) {
  const std::filesystem::path source(HS_SOURCE_DIR);
  const std::filesystem::path reference = source / "data" / "reference" / "fischer_korzeniewski2015_ttf_binned.csv";
  const std::filesystem::path csv =
      options.dataset ? *options.dataset : source / "data" / "resolved-shear" / "fischer-korzeniewski" / "dataset.csv";
  const double a = kCellRadius_m;
  const double g_s = MembraneParameters{}.shear_modulus_N_m;
  std::vector<Bin> bins;
  for (const auto& row : read_text_table(reference).rows) {
    Bin b;
    b.eta_o_Pa_s = 1e-3 * number(row, "eta_o_mPa_s", reference);
    b.shear_rate_1_s = number(row, "shear_rate_mean_per_s", reference);
    b.cells = static_cast<int>(number(row, "n_cells", reference));
    b.mean = number(row, "f_over_shear_rate_mean", reference);
    b.sd = number(row, "f_over_shear_rate_sd", reference);
    b.ca = b.eta_o_Pa_s * b.shear_rate_1_s * a / g_s;
    bins.push_back(b);
  }
  hs::common::CheckList checks;
  if (!std::filesystem::exists(csv)) {
    checks.expect("the campaign's dataset", false,
                  fmt::format("{} not found: run `hemoscale campaign cases/campaign/shear-fischer-korzeniewski`",
                              csv.string()));
    checks.print("tank-treading");
    return checks.exit_code();
  }
  const TextTable data = read_text_table(csv);
  std::vector<Measured> measured(bins.size());
  for (std::size_t i = 0; i < bins.size(); ++i) {
    for (const auto& row : data.rows) {
      const double ca = number(row, "ca", csv);
      if (std::abs(ca - bins[i].ca) > kCaMatch * bins[i].ca) continue;
      Measured& m = measured[i];
      m.present = true;
      m.flow_mode = text(row, "flow_mode");
      m.settled = text(row, "settled") == "true";
      m.f_over_gamma = number(row, "f_over_shear_rate", csv);
      m.inclination_deg = number(row, "inclination_deg", csv);
      m.di = number(row, "di", csv);
      m.shear_rate_1_s = number(row, "shear_rate_1_s", csv);
      m.rate_rad_s = 2.0 * std::numbers::pi * m.f_over_gamma * m.shear_rate_1_s;
      m.bound_rad_s = number(row, "keller_skalak_bound_rad_s", csv);
      m.re_p = number(row, "re_p", csv);
    }
  }
  fmt::print("tank-treading vs Fischer & Korzeniewski 2015 ({} mPa s medium; dataset {})\n", 1e3 * bins.front().eta_o_Pa_s,
             csv.string());
  fmt::print("  {:>8} {:>7} {:>14} {:>8} {:>9} {:>17} {:>6} {:>8} {:>6} {:>7}\n", "gamma/s", "Ca", "mode", "settled",
             "f/gamma", "data mean+-SD", "z", "incl deg", "DI", "Re_p");
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t i = 0; i < bins.size(); ++i) {
    const Bin& b = bins[i];
    const Measured& m = measured[i];
    const std::string name = fmt::format("{:g} 1/s (Ca {:.3g})", b.shear_rate_1_s, b.ca);
    if (!m.present) {
      checks.expect(name + ": run in the dataset", false, "no row with this Ca (the campaign has not finished it)");
      continue;
    }
    const double z = (m.f_over_gamma - b.mean) / b.sd;
    fmt::print("  {:>8g} {:>7.3f} {:>14} {:>8} {:>9.4f} {:>10.4f}+-{:.4f} {:>6.2f} {:>8.2f} {:>6.3f} {:>7.4f}\n",
               b.shear_rate_1_s, b.ca, m.flow_mode, m.settled ? "yes" : "no", m.f_over_gamma, b.mean, b.sd, z,
               m.inclination_deg, m.di, m.re_p);
    const bool tank_treading = m.flow_mode == "tank-treading";
    checks.expect(name + ": tank-treading, as every measured cell", tank_treading, fmt::format("measured {}", m.flow_mode));
    if (!tank_treading) continue;
    checks.expect(name + ": settled (last two whole revolutions within 2 %)", m.settled,
                  m.settled ? "yes" : "the revolutions still differ: a longer run (max_jeffery_periods) is needed");
    checks.expect(name + ": under the Keller-Skalak bound of the measured axes", m.rate_rad_s <= m.bound_rad_s,
                  fmt::format("{:.4g} rad/s, bound {:.4g} at DI {:.3f}", m.rate_rad_s, m.bound_rad_s, m.di));
    const double half = kScatterSds * b.sd / options.tighten;
    checks.expect(name + fmt::format(": f/gamma_dot within the cells' scatter (mean +- {:g} SD)", kScatterSds),
                  m.settled && std::abs(m.f_over_gamma - b.mean) <= half,
                  fmt::format("{:.4f} vs {:.4f} +- {:.4f} (z = {:+.2f}){}", m.f_over_gamma, b.mean, half, z,
                              m.settled ? "" : "; not settled: no agreement claimed"));
    rows.push_back({{"shear_rate_experiment_1_s", b.shear_rate_1_s}, {"ca", b.ca}, {"cells", b.cells},
                    {"f_over_shear_rate_data_mean", b.mean}, {"f_over_shear_rate_data_sd", b.sd},
                    {"f_over_shear_rate", m.f_over_gamma}, {"z", z}, {"flow_mode", m.flow_mode}, {"settled", m.settled},
                    {"inclination_deg", m.inclination_deg}, {"di", m.di}, {"rate_rad_s", m.rate_rad_s},
                    {"keller_skalak_bound_rad_s", m.bound_rad_s}, {"re_p", m.re_p},
                    {"shear_rate_analogue_1_s", m.shear_rate_1_s}});
  }
  const Measured& low = measured.front();
  const Measured& high = measured.back();
  if (low.present && high.present && low.settled && high.settled) {
    checks.expect("f/gamma_dot falls from the lowest to the highest shear rate, as measured",
                  high.f_over_gamma < low.f_over_gamma,
                  fmt::format("{:.4f} -> {:.4f} (data {:.4f} -> {:.4f})", low.f_over_gamma, high.f_over_gamma,
                              bins.front().mean, bins.back().mean));
  } else {
    checks.expect("f/gamma_dot falls from the lowest to the highest shear rate, as measured", false,
                  "needs settled runs at both ends");
  }
  checks.print("tank-treading");
  if (options.json_file) {
    nlohmann::json result = {{"validation", "tank-treading"},
                             {"dataset", csv.string()},
                             {"reference", reference.string()},
                             {"band_sds", kScatterSds / options.tighten},
                             {"model_cell_radius_m", a},
                             {"model_shear_modulus_N_m", g_s},
                             {"bins", rows},
                             {"provenance", hs::common::provenance()}};
    checks.write_to(result);
    hs::common::write_json(*options.json_file, result);
  }
  return checks.exit_code();
}

}  // namespace hs::resolved
