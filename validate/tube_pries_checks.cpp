// SPDX-License-Identifier: MIT
#include "validate/tube_pries_checks.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

namespace hs::unresolved {
namespace {


/// The plasma-only reference run against Poiseuille, Q = pi R^4 |G| / (8 mu): 2% at 10 cells across the diameter (the
/// cut-cell FVM's verification band, tests/unresolved/fvm/tube_poiseuille_test), second order in dx, so
/// 2% (10 / n)^2 at n cells across (5.6% for --quick's 6).
double plasma_band_pct(int cells_across) { return 2.0 * std::pow(10.0 / cells_across, 2); }

}  // namespace

bool check_tube_pries_run(const std::string& label, const TubePriesConfig& c, const TubePriesResult& r,
                          const TubePriesCheckOptions& options, hs::common::CheckList& checks) {
  const double mu = c.fluid.density_kg_m3 * c.fluid.kinematic_viscosity_m2_s;
  const double radius = 0.5 * c.diameter_m;
  const double q_poiseuille = std::numbers::pi * std::pow(radius, 4) * std::abs(c.pressure_gradient_Pa_m) / (8.0 * mu);
  const double q_plasma = r.summary["results"]["flow_rate_plasma_only_m3_s"].get<double>();
  const double plasma_err = 100.0 * (q_plasma - q_poiseuille) / q_poiseuille;
  const double plasma_band = plasma_band_pct(c.cells_across) / options.tighten;
  checks.expect(label + ": plasma flow vs Poiseuille", std::abs(plasma_err) <= plasma_band,
                fmt::format("{:+.2f}% (band +-{:.2g}%)", plasma_err, plasma_band));
  const bool finite = std::isfinite(r.ht_d) && std::isfinite(r.mu_rel) && r.ht_d > 0.0 && r.ht_d < 1.0;
  checks.expect(label + ": Ht_d and mu_rel finite, 0 < Ht_d < 1", finite, fmt::format("Ht_d {}, mu_rel {}", r.ht_d, r.mu_rel));
  if (c.suspension_viscosity == SuspensionViscosity::pries_bulk) {   // the brief: a sensitivity study is labelled
    checks.skip(label + ": a validation", "suspension_viscosity = pries_bulk puts Pries 1992's own wide-tube law into the "
                                          "model: a sensitivity study, its agreement with Pries is no evidence");
  }
  if (options.quick) {
    checks.skip(label + ": steady, Ht_d and mu_rel vs Pries", "--quick: a run far shorter than the ~1 s the cell-free layer needs");
    return false;
  }
  const nlohmann::json& res = r.summary["results"];
  const bool steady = res["steady"].get<bool>();
  // Older archived summaries (before max_end_time_s) have no end_time_s: they ran their fixed length.
  const std::string length = res.contains("end_time_s")
                                 ? fmt::format("; ran {:.3g} s{}", res["end_time_s"].get<double>(),
                                               res["stopped_when_steady"].get<bool>() ? ", stopped when steady" : " (the cap)")
                                 : std::string();
  checks.expect(label + ": steady", steady,
                fmt::format("trend over the averaging window: Ht_d {:+.2f}%, mu_rel {:+.2f}% (tolerance {:.0f}%){}",
                            100.0 * res["ht_d_trend_over_window"].get<double>(),
                            100.0 * res["mu_rel_trend_over_window"].get<double>(), 100.0 * c.steady_tolerance, length));
  return steady;
}

void check_pries_band(const std::string& label, double ht_d_error_pct, double mu_rel_error_pct, bool steady,
                      const TubePriesCheckOptions& options, hs::common::CheckList& checks) {
  const double band = kPriesBandPct / options.tighten;
  checks.expect(label + ": Ht_d vs Pries", std::abs(ht_d_error_pct) <= band,
                fmt::format("{:+.1f}% (band +-{:.2g}%){}", ht_d_error_pct, band, steady ? "" : ", not steady"));
  checks.expect(label + ": mu_rel vs Pries", std::abs(mu_rel_error_pct) <= band,
                fmt::format("{:+.1f}% (band +-{:.2g}%){}", mu_rel_error_pct, band, steady ? "" : ", not steady"));
}

void check_tube_pries(const TubePriesConfig& c, const TubePriesResult& r, const TubePriesCheckOptions& options,
                      hs::common::CheckList& checks) {
  const std::string tube = fmt::format("D = {:.0f} um, Ht_c {:.2f}", c.diameter_m * 1e6, c.tube_hematocrit);
  const bool steady = check_tube_pries_run(tube, c, r, options, checks);
  if (!options.quick) check_pries_band(tube, r.ht_d_error_pct, r.mu_rel_error_pct, steady, options, checks);
}

}  // namespace hs::unresolved
