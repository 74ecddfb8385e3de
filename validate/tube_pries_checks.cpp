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

void check_tube_pries(const TubePriesConfig& c, const TubePriesResult& r, const TubePriesCheckOptions& options,
                      hs::common::CheckList& checks) {
  const std::string tube = fmt::format("D = {:.0f} um, Ht_c {:.2f}", c.diameter_m * 1e6, c.tube_hematocrit);
  const double mu = c.fluid.density_kg_m3 * c.fluid.kinematic_viscosity_m2_s;
  const double radius = 0.5 * c.diameter_m;
  const double q_poiseuille = std::numbers::pi * std::pow(radius, 4) * std::abs(c.pressure_gradient_Pa_m) / (8.0 * mu);
  const double q_plasma = r.summary["results"]["flow_rate_plasma_only_m3_s"].get<double>();
  const double plasma_err = 100.0 * (q_plasma - q_poiseuille) / q_poiseuille;
  const double plasma_band = plasma_band_pct(c.cells_across) / options.tighten;
  checks.expect(tube + ": plasma flow vs Poiseuille", std::abs(plasma_err) <= plasma_band,
                fmt::format("{:+.2f}% (band +-{:.2g}%)", plasma_err, plasma_band));
  const bool finite = std::isfinite(r.ht_d) && std::isfinite(r.mu_rel) && r.ht_d > 0.0 && r.ht_d < 1.0;
  checks.expect(tube + ": Ht_d and mu_rel finite, 0 < Ht_d < 1", finite, fmt::format("Ht_d {}, mu_rel {}", r.ht_d, r.mu_rel));
  if (c.suspension_viscosity == SuspensionViscosity::pries_bulk) {   // the brief: a sensitivity study is labelled
    checks.skip(tube + ": a validation", "suspension_viscosity = pries_bulk puts Pries 1992's own wide-tube law into the "
                                         "model: a sensitivity study, its agreement with Pries is no evidence");
  }
  if (options.quick) {
    checks.skip(tube + ": steady, Ht_d and mu_rel vs Pries", "--quick: a run far shorter than the ~1 s the cell-free layer needs");
    return;
  }
  const bool steady = r.summary["results"]["steady"].get<bool>();
  checks.expect(tube + ": steady", steady,
                fmt::format("Ht_d moved {:+.4f} between the averaging window's halves (tolerance {:.0f}%)",
                            r.summary["results"]["ht_d_change_between_averaging_halves"].get<double>(), 100.0 * c.steady_tolerance));
  const double band = kPriesBandPct / options.tighten;
  checks.expect(tube + ": Ht_d vs Pries", std::abs(r.ht_d_error_pct) <= band,
                fmt::format("{:+.1f}% (band +-{:.2g}%){}", r.ht_d_error_pct, band, steady ? "" : ", not steady"));
  checks.expect(tube + ": mu_rel vs Pries", std::abs(r.mu_rel_error_pct) <= band,
                fmt::format("{:+.1f}% (band +-{:.2g}%){}", r.mu_rel_error_pct, band, steady ? "" : ", not steady"));
}


}  // namespace hs::unresolved
