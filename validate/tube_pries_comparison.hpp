// SPDX-License-Identifier: MIT
// The Pries et al. 1992 comparison of a tube-pries run, on the validation side: the solver-side case measures
// Ht_d and mu_rel, and analysis/pries1992 (which no solver reads) gives the reference values.
#pragma once

#include "unresolved/cases/tube_pries.hpp"

namespace hs::unresolved {

/// Fills r's Pries fields from the law at this tube's diameter and the insertion's achieved tube hematocrit Ht_T
/// (summary "tube_hematocrit"), and adds pries_discharge_hematocrit, pries_relative_apparent_viscosity,
/// ht_d_error_pct and mu_rel_error_pct to r.summary.
void add_pries_comparison(const TubePriesConfig& c, TubePriesResult& r);

}  // namespace hs::unresolved
