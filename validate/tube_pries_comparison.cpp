// SPDX-License-Identifier: MIT
#include "validate/tube_pries_comparison.hpp"

#include <cmath>

#include "analysis/pries1992.hpp"
#include "common/io/csv_writer.hpp"

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

void write_pries_curves(const std::filesystem::path& csv, const std::vector<double>& tube_hematocrits) {
  hs::common::CsvWriter out(csv, {"diameter_um", "tube_hematocrit", "pries_discharge_hematocrit", "pries_ht_d_over_ht_t",
                                  "pries_relative_apparent_viscosity"});
  constexpr int kPoints = 61;
  for (const double ht_t : tube_hematocrits) {
    for (int i = 0; i < kPoints; ++i) {
      const double d_um = 10.0 * std::pow(30.0, static_cast<double>(i) / (kPoints - 1));
      const double ht_d = hs::analysis::discharge_from_tube_hematocrit(d_um, ht_t);
      out.row({d_um, ht_t, ht_d, ht_d / ht_t, hs::analysis::relative_apparent_viscosity(d_um, ht_d)});
    }
  }
}

}  // namespace hs::unresolved
