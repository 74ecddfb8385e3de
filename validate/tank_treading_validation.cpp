// SPDX-License-Identifier: MIT
// `hemoscale validate tank-treading`: one healthy RBC in shear against Fischer & Korzeniewski 2015 (Biophys J 108:1352),
// from the datasets of three campaigns that run their experiment as its Stokes-flow analogue
// (cases/resolved/shear/fischer-korzeniewski: what is kept and what differs):
//  - frequency (cases/campaign/shear-fischer-korzeniewski): the capillary numbers of their six shear-rate bins in a
//    28.9 mPa s medium against the frequencies of 225 cells. Band: the bin's mean +- 2 SD, the range that holds ~95 %
//    of single cells (their SD, 12-22 % of the mean, is the spread between cells, far above the error of a bin's mean;
//    one model cell is one typical cell, not the mean of many). Across the bins f / gamma_dot must fall from the lowest
//    to the highest shear rate, as measured (0.0398 -> 0.0254, 7 standard errors apart). The same campaign with the
//    cytoplasm as viscous as the medium (...-ratio-1) is printed beside it, unchecked (a sensitivity study);
//  - inclination (...-10.7 and ...-104): three measured shear rates in each medium against the donors' digitised
//    angles. Band: the donors' range at that shear rate widened by the digitising error (+-0.3 deg); and the angle
//    larger in the more viscous medium, as measured.
// Every run must exist, tank-tread (or swing: the membrane revolves about a body that does not tumble), have settled
// (its last two whole revolutions as long as the two before within 2 %) and turn under the Keller-Skalak bound of its
// measured axes. Reads the datasets only: nothing is simulated (the campaigns are resumable
// and archived). Exit 1 on any failure, naming it. --dataset DIR reads DIR/<campaign>/dataset.csv instead of
// data/resolved-shear/<campaign>/dataset.csv. With --json FILE it also writes FILE.png (tools/plot_tank_treading.py).
#include "validate/tank_treading_validation.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/check_list.hpp"
#include "common/run_folder.hpp"
#include "resolved/cases/plate_cell_config.hpp"
#include "resolved/membrane/membrane_parameters.hpp"
#include "validate/plot_beside_json.hpp"
#include "validate/text_table.hpp"

namespace hs::resolved {
namespace {

namespace fs = std::filesystem;
using hs::validate::number;
using hs::validate::read_text_table;
using hs::validate::text;
using hs::validate::TextRow;

/// Bands of f / gamma_dot: the bin's mean +- this many of its cell-to-cell SDs.
constexpr double kScatterSds = 2.0;
/// Digitising error of the inclination data (shared validation/wave2 README: about +-0.3 deg).
constexpr double kDigitisingDeg = 0.3;
/// A dataset row belongs to a measured point when its Ca is the point's within this share (campaigns write 4-5 digits).
constexpr double kCaMatch = 0.01;
/// The media of the inclination series (mPa s) and their campaigns' dataset folders.
constexpr double kInclinationMedia[] = {10.7, 104.0};

/// The model's capillary number at a measured point: eta_o gamma_dot a / G_s with its own a and G_s.
double model_ca(double eta_o_Pa_s, double shear_rate_1_s) {
  return eta_o_Pa_s * shear_rate_1_s * kCellRadius_m / MembraneParameters{}.shear_modulus_N_m;
}

/// One run of a campaign's dataset, as the checks need it.
struct Measured {
  bool present = false;
  std::string flow_mode;
  bool tank_treads = false;        // tank-treading or swinging: the membrane revolves, the body does not tumble
  double swinging_deg = 0.0;       // half the range of the outline's angle over the settled revolutions
  bool settled = false;
  double f_over_gamma = 0.0;
  double inclination_deg = 0.0;
  double di = 0.0;
  double rate_rad_s = 0.0;     // settled rate 2 pi f
  double bound_rad_s = 0.0;    // Keller-Skalak bound of the measured axes
  double re_p = 0.0;
  double shear_rate_1_s = 0.0;   // the analogue's
};

/// The row of `rows` at capillary number `ca` (within kCaMatch), or an absent one.
Measured find_run(const std::vector<TextRow>& rows, double ca, const fs::path& csv) {
  Measured m;
  for (const TextRow& row : rows) {
    if (std::abs(number(row, "ca", csv) - ca) > kCaMatch * ca) continue;
    m.present = true;
    m.flow_mode = text(row, "flow_mode");
    m.tank_treads = text(row, "membrane_tank_treads") == "true";
    m.swinging_deg = number(row, "swinging_amplitude_deg", csv);
    m.settled = text(row, "settled") == "true";
    m.f_over_gamma = number(row, "f_over_shear_rate", csv);
    m.inclination_deg = number(row, "inclination_deg", csv);
    m.di = number(row, "di", csv);
    m.shear_rate_1_s = number(row, "shear_rate_1_s", csv);
    m.rate_rad_s = 2.0 * std::numbers::pi * m.f_over_gamma * m.shear_rate_1_s;
    m.bound_rad_s = number(row, "keller_skalak_bound_rad_s", csv);
    m.re_p = number(row, "re_p", csv);
  }
  return m;
}

/// The checks every run shares: present, tank-treading, settled, under the bound. False when the run cannot be
/// compared (absent or not tank-treading).
bool check_run(const std::string& name, const Measured& m, hs::common::CheckList& checks) {
  if (!m.present) {
    checks.expect(name + ": run in the dataset", false, "no row with this Ca (its campaign has not finished it)");
    return false;
  }
  checks.expect(name + ": the membrane tank-treads (tank-treading or swinging), as in every measured cell", m.tank_treads,
                fmt::format("measured {}{}", m.flow_mode,
                            m.tank_treads ? fmt::format(", swinging +-{:.1f} deg", m.swinging_deg) : ""));
  if (!m.tank_treads) return false;
  checks.expect(name + ": settled (last two whole revolutions as long as the two before, 2 %)", m.settled,
                m.settled ? "yes" : "the revolutions still differ: a longer run (max_jeffery_periods) is needed");
  checks.expect(name + ": under the Keller-Skalak bound of the measured axes", m.rate_rad_s <= m.bound_rad_s,
                fmt::format("{:.4g} rad/s, bound {:.4g} at DI {:.3f}", m.rate_rad_s, m.bound_rad_s, m.di));
  return true;
}

struct FrequencyBin {
  double eta_o_Pa_s = 0.0;
  double shear_rate_1_s = 0.0;
  int cells = 0;
  double mean = 0.0;
  double sd = 0.0;
};

/// The shear-rate bins of the frequency data (fischer_korzeniewski2015_ttf_binned.csv).
std::vector<FrequencyBin> read_frequency_bins(const fs::path& reference) {
  std::vector<FrequencyBin> bins;
  for (const TextRow& row : read_text_table(reference)) {
    bins.push_back({.eta_o_Pa_s = 1e-3 * number(row, "eta_o_mPa_s", reference),
                    .shear_rate_1_s = number(row, "shear_rate_mean_per_s", reference),
                    .cells = static_cast<int>(number(row, "n_cells", reference)),
                    .mean = number(row, "f_over_shear_rate_mean", reference),
                    .sd = number(row, "f_over_shear_rate_sd", reference)});
  }
  return bins;
}

nlohmann::json check_frequency(const fs::path& reference, const fs::path& csv, double tighten,
                               hs::common::CheckList& checks) {
  const std::vector<FrequencyBin> bins = read_frequency_bins(reference);
  nlohmann::json out = nlohmann::json::array();
  const std::vector<TextRow> rows = fs::exists(csv) ? read_text_table(csv) : std::vector<TextRow>{};
  fmt::print("frequency, {:g} mPa s medium ({})\n", 1e3 * bins.front().eta_o_Pa_s, fs::exists(csv) ? csv.string() : "no dataset");
  fmt::print("  {:>8} {:>7} {:>14} {:>8} {:>9} {:>17} {:>6} {:>8} {:>6} {:>6} {:>7}\n", "gamma/s", "Ca", "mode", "settled",
             "f/gamma", "data mean+-SD", "z", "incl deg", "swing", "DI", "Re_p");
  std::vector<Measured> measured;
  for (const FrequencyBin& b : bins) {
    const double ca = model_ca(b.eta_o_Pa_s, b.shear_rate_1_s);
    const Measured m = find_run(rows, ca, csv);
    measured.push_back(m);
    const std::string name = fmt::format("f at {:g} 1/s (Ca {:.3g})", b.shear_rate_1_s, ca);
    const double z = (m.f_over_gamma - b.mean) / b.sd;
    if (m.present) {
      fmt::print("  {:>8g} {:>7.3f} {:>14} {:>8} {:>9.4f} {:>10.4f}+-{:.4f} {:>6.2f} {:>8.2f} {:>6.1f} {:>6.3f} {:>7.4f}\n",
                 b.shear_rate_1_s, ca, m.flow_mode, m.settled ? "yes" : "no", m.f_over_gamma, b.mean, b.sd, z,
                 m.inclination_deg, m.swinging_deg, m.di, m.re_p);
    }
    if (!check_run(name, m, checks)) continue;
    const double half = kScatterSds * b.sd / tighten;
    checks.expect(name + fmt::format(": f/gamma_dot within the cells' scatter (mean +- {:g} SD)", kScatterSds),
                  m.settled && std::abs(m.f_over_gamma - b.mean) <= half,
                  fmt::format("{:.4f} vs {:.4f} +- {:.4f} (z = {:+.2f}){}", m.f_over_gamma, b.mean, half, z,
                              m.settled ? "" : "; not settled: no agreement claimed"));
    out.push_back({{"shear_rate_experiment_1_s", b.shear_rate_1_s}, {"ca", ca}, {"cells", b.cells},
                   {"f_over_shear_rate_data_mean", b.mean}, {"f_over_shear_rate_data_sd", b.sd},
                   {"f_over_shear_rate", m.f_over_gamma}, {"z", z}, {"flow_mode", m.flow_mode}, {"settled", m.settled},
                   {"membrane_tank_treads", m.tank_treads}, {"swinging_amplitude_deg", m.swinging_deg},
                   {"inclination_deg", m.inclination_deg}, {"di", m.di}, {"rate_rad_s", m.rate_rad_s},
                   {"keller_skalak_bound_rad_s", m.bound_rad_s}, {"re_p", m.re_p},
                   {"shear_rate_analogue_1_s", m.shear_rate_1_s}});
  }
  const std::string trend = "f/gamma_dot falls from the lowest to the highest shear rate, as measured";
  const Measured& low = measured.front();
  const Measured& high = measured.back();
  if (low.settled && high.settled) {
    checks.expect(trend, high.f_over_gamma < low.f_over_gamma,
                  fmt::format("{:.4f} -> {:.4f} (data {:.4f} -> {:.4f})", low.f_over_gamma, high.f_over_gamma,
                              bins.front().mean, bins.back().mean));
  } else {
    checks.expect(trend, false, "needs settled runs at both ends");
  }
  return out;
}

/// The frequency campaign rerun with the cytoplasm as viscous as the medium (ratio 1): printed beside the healthy cell,
/// never checked against the data (a sensitivity study: the cytoplasm's share of the frequency).
nlohmann::json report_ratio_1(const fs::path& reference, const fs::path& csv) {
  nlohmann::json out = nlohmann::json::array();
  if (!fs::exists(csv)) {
    fmt::print("sensitivity, viscosity ratio 1 (not a validation): no dataset ({})\n", csv.string());
    return out;
  }
  const std::vector<TextRow> rows = read_text_table(csv);
  fmt::print("sensitivity, viscosity ratio 1 (not a validation; {})\n", csv.string());
  fmt::print("  {:>8} {:>7} {:>14} {:>8} {:>9} {:>8} {:>6} {:>6}\n", "gamma/s", "Ca", "mode", "settled", "f/gamma",
             "incl deg", "swing", "DI");
  for (const FrequencyBin& b : read_frequency_bins(reference)) {
    const double rate = b.shear_rate_1_s;
    const double ca = model_ca(b.eta_o_Pa_s, rate);
    const Measured m = find_run(rows, ca, csv);
    if (!m.present) continue;
    fmt::print("  {:>8g} {:>7.3f} {:>14} {:>8} {:>9.4f} {:>8.2f} {:>6.1f} {:>6.3f}\n", rate, ca, m.flow_mode,
               m.settled ? "yes" : "no", m.f_over_gamma, m.inclination_deg, m.swinging_deg, m.di);
    out.push_back({{"shear_rate_experiment_1_s", rate}, {"ca", ca}, {"flow_mode", m.flow_mode}, {"settled", m.settled},
                   {"membrane_tank_treads", m.tank_treads}, {"f_over_shear_rate", m.f_over_gamma},
                   {"inclination_deg", m.inclination_deg}, {"swinging_amplitude_deg", m.swinging_deg}, {"di", m.di}});
  }
  return out;
}

struct InclinationPoint {
  double shear_rate_1_s = 0.0;
  int donors = 0;
  double min_deg = 0.0;
  double max_deg = 0.0;
  double mean_deg = 0.0;
};

/// The donors' angles at each digitised shear rate of one medium.
std::vector<InclinationPoint> inclination_points(const fs::path& reference, double eta_o_mPa_s) {
  std::map<std::string, std::vector<double>> by_rate;   // the digitised rate's text: shared by the donors of a panel
  for (const TextRow& row : read_text_table(reference)) {
    if (std::abs(number(row, "eta_o_mPa_s", reference) - eta_o_mPa_s) > 1e-9) continue;
    by_rate[text(row, "shear_rate_per_s")].push_back(number(row, "angle_deg", reference));
  }
  std::vector<InclinationPoint> points;
  for (const auto& [rate, angles] : by_rate) {
    double sum = 0.0;
    for (const double a : angles) sum += a;
    points.push_back({.shear_rate_1_s = std::strtod(rate.c_str(), nullptr),
                      .donors = static_cast<int>(angles.size()),
                      .min_deg = *std::min_element(angles.begin(), angles.end()),
                      .max_deg = *std::max_element(angles.begin(), angles.end()),
                      .mean_deg = sum / static_cast<double>(angles.size())});
  }
  return points;
}

/// The inclination series of one medium; `mean_deg` gets the mean of the model's settled angles (0 with none).
nlohmann::json check_inclination(const fs::path& reference, double eta_o_mPa_s, const fs::path& csv, double tighten,
                                 hs::common::CheckList& checks, double& model_mean_deg, double& data_mean_deg) {
  const std::vector<InclinationPoint> points = inclination_points(reference, eta_o_mPa_s);
  nlohmann::json out = nlohmann::json::array();
  fmt::print("inclination, {:g} mPa s medium ({})\n", eta_o_mPa_s, fs::exists(csv) ? csv.string() : "no dataset");
  if (!fs::exists(csv)) {
    checks.expect(fmt::format("inclination at {:g} mPa s: the campaign's dataset", eta_o_mPa_s), false,
                  fmt::format("{} not found: run its campaign", csv.string()));
    return out;
  }
  const std::vector<TextRow> rows = read_text_table(csv);
  fmt::print("  {:>8} {:>7} {:>14} {:>8} {:>9} {:>19} {:>6} {:>6} {:>7}\n", "gamma/s", "Ca", "mode", "settled",
             "incl deg", "donors [min, max]", "swing", "DI", "Re_p");
  double sum_model = 0.0, sum_data = 0.0;
  int n = 0;
  for (const TextRow& row : rows) {
    const double ca = number(row, "ca", csv);
    // The measured point this run was set up at: its Ca within kCaMatch.
    const auto p = std::find_if(points.begin(), points.end(), [&](const InclinationPoint& q) {
      return std::abs(model_ca(1e-3 * eta_o_mPa_s, q.shear_rate_1_s) - ca) <= kCaMatch * ca;
    });
    const std::string name = fmt::format("inclination at {:g} mPa s, Ca {:.3g}", eta_o_mPa_s, ca);
    if (p == points.end()) {
      checks.expect(name + ": a measured shear rate", false, "no digitised point at this Ca");
      continue;
    }
    const Measured m = find_run(rows, ca, csv);
    fmt::print("  {:>8g} {:>7.3f} {:>14} {:>8} {:>9.2f} {:>3} [{:>5.2f}, {:>5.2f}] {:>6.1f} {:>6.3f} {:>7.4f}\n",
               p->shear_rate_1_s, ca, m.flow_mode, m.settled ? "yes" : "no", m.inclination_deg, p->donors, p->min_deg,
               p->max_deg, m.swinging_deg, m.di, m.re_p);
    if (!check_run(name, m, checks)) continue;
    const double centre = 0.5 * (p->min_deg + p->max_deg);
    const double half = (0.5 * (p->max_deg - p->min_deg) + kDigitisingDeg) / tighten;
    checks.expect(name + ": inside the donors' range (+-0.3 deg digitising)",
                  m.settled && std::abs(m.inclination_deg - centre) <= half,
                  fmt::format("{:.2f} deg vs [{:.2f}, {:.2f}] ({} donors at {:g} 1/s){}", m.inclination_deg,
                              centre - half, centre + half, p->donors, p->shear_rate_1_s,
                              m.settled ? "" : "; not settled: no agreement claimed"));
    if (m.settled) {
      sum_model += m.inclination_deg;
      sum_data += p->mean_deg;
      ++n;
    }
    out.push_back({{"eta_o_mPa_s", eta_o_mPa_s}, {"shear_rate_experiment_1_s", p->shear_rate_1_s}, {"ca", ca},
                   {"donors", p->donors}, {"angle_data_min_deg", p->min_deg}, {"angle_data_max_deg", p->max_deg},
                   {"angle_data_mean_deg", p->mean_deg}, {"inclination_deg", m.inclination_deg},
                   {"flow_mode", m.flow_mode}, {"settled", m.settled}, {"membrane_tank_treads", m.tank_treads},
                   {"swinging_amplitude_deg", m.swinging_deg}, {"di", m.di}, {"re_p", m.re_p},
                   {"f_over_shear_rate", m.f_over_gamma}});
  }
  model_mean_deg = n > 0 ? sum_model / n : 0.0;
  data_mean_deg = n > 0 ? sum_data / n : 0.0;
  return out;
}

}  // namespace

int validate_tank_treading(const hs::common::TaskOptions& options) {
  const fs::path source(HS_SOURCE_DIR);
  const fs::path reference = source / "data" / "reference";
  const fs::path datasets = options.dataset ? *options.dataset : source / "data" / "resolved-shear";
  hs::common::CheckList checks;
  fmt::print("tank-treading vs Fischer & Korzeniewski 2015 (model a {:g} m, G_s {:g} N/m; datasets under {})\n",
             kCellRadius_m, MembraneParameters{}.shear_modulus_N_m, datasets.string());
  const fs::path frequency_csv = datasets / "fischer-korzeniewski" / "dataset.csv";
  if (!fs::exists(frequency_csv)) {
    checks.expect("frequency: the campaign's dataset", false,
                  fmt::format("{} not found: run `hemoscale campaign cases/campaign/shear-fischer-korzeniewski`",
                              frequency_csv.string()));
  }
  nlohmann::json result = {{"validation", "tank-treading"}, {"datasets", datasets.string()}};
  result["frequency"] = check_frequency(reference / "fischer_korzeniewski2015_ttf_binned.csv", frequency_csv,
                                        options.tighten, checks);
  result["frequency_viscosity_ratio_1"] = report_ratio_1(reference / "fischer_korzeniewski2015_ttf_binned.csv",
                                                        datasets / "fischer-korzeniewski-ratio-1" / "dataset.csv");
  std::vector<double> model_means, data_means;
  nlohmann::json inclination = nlohmann::json::array();
  for (const double eta : kInclinationMedia) {
    double model_mean = 0.0, data_mean = 0.0;
    const fs::path csv = datasets / fmt::format("fischer-korzeniewski-{:g}", eta) / "dataset.csv";
    for (auto& row : check_inclination(reference / "fischer_korzeniewski2015_inclination.csv", eta, csv,
                                       options.tighten, checks, model_mean, data_mean)) {
      inclination.push_back(row);
    }
    model_means.push_back(model_mean);
    data_means.push_back(data_mean);
  }
  result["inclination"] = inclination;
  const std::string trend = "inclination larger in the more viscous medium, as measured";
  if (model_means.front() > 0.0 && model_means.back() > 0.0) {
    checks.expect(trend, model_means.back() > model_means.front(),
                  fmt::format("mean {:.2f} deg at {:g} mPa s, {:.2f} at {:g} (data {:.2f}, {:.2f})", model_means.front(),
                              kInclinationMedia[0], model_means.back(), kInclinationMedia[1], data_means.front(),
                              data_means.back()));
  } else {
    checks.expect(trend, false, "needs settled runs in both media");
  }
  checks.print("tank-treading");
  if (options.json_file) {
    result["frequency_band_sds"] = kScatterSds / options.tighten;
    result["model_cell_radius_m"] = kCellRadius_m;
    result["model_shear_modulus_N_m"] = MembraneParameters{}.shear_modulus_N_m;
    result["provenance"] = hs::common::provenance();
    checks.write_to(result);
    hs::common::write_json(*options.json_file, result);
    hs::validate::plot_beside_json("plot_tank_treading.py", *options.json_file, reference);
  }
  return checks.exit_code();
}

}  // namespace hs::resolved
