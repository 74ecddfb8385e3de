// SPDX-License-Identifier: MIT
// What one tube-pries run must show, for `hemoscale run` and `hemoscale validate pries` alike: the plasma-only
// reference on Poiseuille, finite results, and (only in a run long enough to claim it) a steady state with Ht_d and
// mu_rel within the seed paper's 5% of Pries et al. 1992. A --quick run skips the last two and says why.
#pragma once

#include <string>

#include "common/check_list.hpp"
#include "unresolved/cases/tube_pries.hpp"

namespace hs::unresolved {

/// The seed paper's target for the Fahraeus-Lindqvist tubes: Ht_d and mu_rel within 5% of Pries et al. 1992.
inline constexpr double kPriesBandPct = 5.0;

struct TubePriesCheckOptions {
  bool quick = false;     // too short for the cell-free layer: the steady and Pries checks are skipped
  double tighten = 1.0;   // every band divided by this (tests of the failure path)
};

/// Everything one run must show: check_tube_pries_run, then (not --quick) check_pries_band on its own errors.
void check_tube_pries(const TubePriesConfig& c, const TubePriesResult& r, const TubePriesCheckOptions& options,
                      hs::common::CheckList& checks);

/// One run (`label` names it, e.g. the tube and its seed): the plasma reference on Poiseuille, finite results, the
/// sensitivity-study label (pries_bulk) and, unless --quick, the steady state. Returns whether it was steady.
bool check_tube_pries_run(const std::string& label, const TubePriesConfig& c, const TubePriesResult& r,
                          const TubePriesCheckOptions& options, hs::common::CheckList& checks);

/// The seed paper's band on an entry's Ht_d and mu_rel errors (one run's, or the mean over seeds), in percent.
void check_pries_band(const std::string& label, double ht_d_error_pct, double mu_rel_error_pct, bool steady,
                      const TubePriesCheckOptions& options, hs::common::CheckList& checks);

}  // namespace hs::unresolved
