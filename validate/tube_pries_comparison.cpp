// SPDX-License-Identifier: MIT
#include "validate/tube_pries_comparison.hpp"

#include "analysis/pries1992.hpp"

namespace hs::unresolved {

void add_pries_comparison(const TubePriesConfig& c, TubePriesResult& r) {
  const double d_um = c.diameter_m * 1e6;
  r.ht_d_pries = hs::analysis::discharge_from_tube_hematocrit(d_um, r.summary.at("results").at("tube_hematocrit").get<double>());
  r.mu_rel_pries = hs::analysis::relative_apparent_viscosity(d_um, r.ht_d_pries);
  r.ht_d_error_pct = 100.0 * (r.ht_d - r.ht_d_pries) / r.ht_d_pries;
  r.mu_rel_error_pct = 100.0 * (r.mu_rel - r.mu_rel_pries) / r.mu_rel_pries;
  r.summary["results"]["pries_discharge_hematocrit"] = r.ht_d_pries;
  r.summary["results"]["pries_relative_apparent_viscosity"] = r.mu_rel_pries;
  r.summary["results"]["ht_d_error_pct"] = r.ht_d_error_pct;
  r.summary["results"]["mu_rel_error_pct"] = r.mu_rel_error_pct;
}

}  // namespace hs::unresolved
