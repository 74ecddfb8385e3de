// SPDX-License-Identifier: MIT
// `hemoscale validate tumbling-threshold`: the dataset of cases/campaign/shear-threshold-23.9 (one healthy cell released
// edge-on at capillary numbers a factor 2 apart, and 0.3 inside the first bracket, as the Stokes-flow analogue of
// Fischer & Korzeniewski's 23.9 mPa s medium: cases/resolved/shear/fischer-korzeniewski) against the shear stresses at
// which their tumbling cells started to tank-tread (Fischer & Korzeniewski 2013, JFM 736:351; three digitised points,
// 0.063-0.23 Pa). The model's transition lies between its highest tumbling Ca and its lowest tank-treading (or
// swinging) Ca; every run must be long enough to read its mode (4 Jeffery periods), the transition one step (no
// tumbling run above a tank-treading one), inside the swept range, and overlap
// the measured thresholds widened by their digitising error (+-10 %: points read off a logarithmic stress axis). Reads
// the dataset only: nothing is simulated. Exit 1 on any failure, naming it. --dataset DIR reads
// DIR/threshold-23.9/dataset.csv.
#include "validate/tumbling_threshold_validation.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/check_list.hpp"
#include "common/run_folder.hpp"
#include "resolved/cases/plate_cell_config.hpp"
#include "resolved/measure/flow_mode.hpp"
#include "resolved/membrane/membrane_parameters.hpp"
#include "validate/text_table.hpp"

namespace hs::resolved {
namespace {

namespace fs = std::filesystem;
using hs::validate::number;
using hs::validate::read_text_table;
using hs::validate::text;

/// The medium of the threshold campaign (mPa s) and the digitising error of the measured stresses.
constexpr double kMedium_mPa_s = 23.9;
constexpr double kDigitising = 0.10;

/// A run's mode is read over its second half, which must span two Jeffery periods (plate_cell_checks): four in all.
constexpr double kJefferyPeriodsForMode = 4.0;

struct Run {
  double ca = 0.0;
  double jeffery_periods = 0.0;   // simulated time / Jeffery's period at the run's shear rate
  std::string flow_mode;
  bool tank_treads = false;   // tank-treading or swinging
  bool tumbles = false;
};

}  // namespace

int validate_tumbling_threshold(const hs::common::TaskOptions& options) {
  const fs::path source(HS_SOURCE_DIR);
  const fs::path reference = source / "data" / "reference" / "tumbling_tank_treading_threshold_stress.csv";
  const fs::path datasets = options.dataset ? *options.dataset : source / "data" / "resolved-shear";
  const fs::path csv = datasets / fmt::format("threshold-{:g}", kMedium_mPa_s) / "dataset.csv";
  const double stress_per_ca = MembraneParameters{}.shear_modulus_N_m / kCellRadius_m;   // eta_o gamma_dot = Ca G_s / a
  std::vector<double> measured_Pa;
  for (const auto& row : read_text_table(reference)) {
    if (std::abs(number(row, "eta_o_mPa_s", reference) - kMedium_mPa_s) < 1e-9) {
      measured_Pa.push_back(number(row, "tau_threshold_Pa", reference));
    }
  }
  const auto [lo_it, hi_it] = std::minmax_element(measured_Pa.begin(), measured_Pa.end());
  const double widen = 1.0 + kDigitising / options.tighten;
  const double data_lo = *lo_it / widen / stress_per_ca;   // in Ca
  const double data_hi = *hi_it * widen / stress_per_ca;
  hs::common::CheckList checks;
  fmt::print("tumbling-threshold vs Fischer & Korzeniewski 2013 ({:g} mPa s medium: {} points, {:.3g}-{:.3g} Pa = Ca "
             "{:.3g}-{:.3g} with the model's a and G_s; dataset {})\n",
             kMedium_mPa_s, measured_Pa.size(), *lo_it, *hi_it, *lo_it / stress_per_ca, *hi_it / stress_per_ca,
             csv.string());
  nlohmann::json result = {{"validation", "tumbling-threshold"}, {"dataset", csv.string()},
                           {"medium_mPa_s", kMedium_mPa_s}, {"measured_threshold_Pa", measured_Pa}};
  if (!fs::exists(csv)) {
    checks.expect("the campaign's dataset", false,
                  fmt::format("{} not found: run `hemoscale campaign cases/campaign/shear-threshold-23.9`", csv.string()));
    checks.print("tumbling-threshold");
    return checks.exit_code();
  }
  std::vector<Run> runs;
  for (const auto& row : read_text_table(csv)) {
    Run r;
    r.ca = number(row, "ca", csv);
    r.flow_mode = text(row, "flow_mode");
    r.tank_treads = text(row, "membrane_tank_treads") == "true";
    r.tumbles = r.flow_mode == "tumbling";
    r.jeffery_periods = number(row, "simulated_time_s", csv) / jeffery_period(number(row, "shear_rate_1_s", csv));
    runs.push_back(r);
  }
  std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.ca < b.ca; });
  fmt::print("  {:>7} {:>10} {:>14} {:>12}\n", "Ca", "stress Pa", "mode", "tank-treads");
  nlohmann::json rows = nlohmann::json::array();
  double highest_tumbling = 0.0, lowest_tank_treading = 0.0;
  bool one_step = true;
  for (const Run& r : runs) {
    fmt::print("  {:>7.3f} {:>10.4f} {:>14} {:>12}\n", r.ca, r.ca * stress_per_ca, r.flow_mode, r.tank_treads ? "yes" : "no");
    if (r.tumbles) {
      highest_tumbling = r.ca;
      one_step = one_step && lowest_tank_treading == 0.0;   // a tumbling run above a tank-treading one
    }
    if (r.tank_treads && lowest_tank_treading == 0.0) lowest_tank_treading = r.ca;
    rows.push_back({{"ca", r.ca}, {"stress_Pa", r.ca * stress_per_ca}, {"flow_mode", r.flow_mode},
                    {"membrane_tank_treads", r.tank_treads}});
  }
  result["runs"] = rows;
  const auto shortest = std::min_element(runs.begin(), runs.end(), [](const Run& a, const Run& b) {
    return a.jeffery_periods < b.jeffery_periods;
  });
  checks.expect(fmt::format("every run long enough to read its mode (>= {:g} Jeffery periods)", kJefferyPeriodsForMode),
                shortest != runs.end() && shortest->jeffery_periods >= kJefferyPeriodsForMode,
                shortest == runs.end() ? "no runs"
                                       : fmt::format("shortest {:.2f} periods (Ca {:.3g})", shortest->jeffery_periods,
                                                     shortest->ca));
  checks.expect("one transition: no tumbling run above a tank-treading one", one_step,
                one_step ? "yes" : "tumbling above tank-treading: hysteresis or intermittency, no single threshold");
  const bool bracketed = highest_tumbling > 0.0 && lowest_tank_treading > 0.0;
  checks.expect("the transition inside the swept range", bracketed,
                highest_tumbling == 0.0 ? "no run tumbles: the threshold is below the lowest Ca"
                : lowest_tank_treading == 0.0 ? "no run tank-treads: the threshold is above the highest Ca" : "yes");
  if (bracketed && one_step) {
    const bool overlaps = highest_tumbling <= data_hi && lowest_tank_treading >= data_lo;
    checks.expect(fmt::format("the transition Ca overlaps the measured thresholds (+-{:g} % digitising)", 100.0 * kDigitising / options.tighten),
                  overlaps,
                  fmt::format("model between Ca {:.3g} and {:.3g} ({:.3g}-{:.3g} Pa); measured Ca {:.3g}-{:.3g}",
                              highest_tumbling, lowest_tank_treading, highest_tumbling * stress_per_ca,
                              lowest_tank_treading * stress_per_ca, data_lo, data_hi));
    result["model_transition_ca"] = {highest_tumbling, lowest_tank_treading};
    result["model_transition_Pa"] = {highest_tumbling * stress_per_ca, lowest_tank_treading * stress_per_ca};
  }
  result["measured_threshold_ca_band"] = {data_lo, data_hi};
  checks.print("tumbling-threshold");
  if (options.json_file) {
    result["provenance"] = hs::common::provenance();
    checks.write_to(result);
    hs::common::write_json(*options.json_file, result);
  }
  return checks.exit_code();
}

}  // namespace hs::resolved
