// SPDX-License-Identifier: MIT
// The Pries et al. 1992 comparison of a tube-pries run, on the validation side: the solver-side case measures
// Ht_d and mu_rel, and analysis/pries1992 (which no solver reads) gives the reference values.
#pragma once

#include <filesystem>
#include <vector>

#include "unresolved/cases/tube_pries.hpp"

namespace hs::unresolved {

/// Fills r's Pries fields from the law at this tube's diameter and the insertion's achieved tube hematocrit Ht_T
/// (summary "tube_hematocrit"), and adds pries_discharge_hematocrit, pries_relative_apparent_viscosity,
/// ht_d_error_pct and mu_rel_error_pct to r.summary.
void add_pries_comparison(const TubePriesConfig& c, TubePriesResult& r);

/// Pries 1992's curves for the plot (as the seed paper's Figs. 12-13 draw them): for each tube hematocrit, Ht_d / Ht_t
/// and mu_rel at 61 diameters log-spaced over 10-300 um (the law's fitted range is 3.3-1978 um), one CSV row each.
void write_pries_curves(const std::filesystem::path& csv, const std::vector<double>& tube_hematocrits);

}  // namespace hs::unresolved
