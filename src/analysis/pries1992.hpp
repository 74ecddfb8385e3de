// SPDX-License-Identifier: MIT
// The in-vitro blood rheology laws of Pries, Neuhaus & Gaehtgens 1992 (Am J Physiol 263:H1770), the
// reference of the Fahraeus–Lindqvist validation. Diameters in micrometres (as the fits were made),
// hematocrits as fractions.
#pragma once

namespace hs::analysis {

/// Tube-to-discharge hematocrit ratio Ht_T/Ht_D = Ht_D + (1 - Ht_D) X, X = 1 + 1.7 e^{-0.35 D} - 0.6 e^{-0.01 D}
/// (Pries 1992 eq. 9; the 1990 law uses 0.415 and 0.011 instead: not this one).
double fahraeus_ratio(double diameter_um, double discharge_hematocrit);

/// Discharge hematocrit from tube hematocrit: the root in [0, 1] of (1 - X) H_D^2 + X H_D - Ht_T = 0.
double discharge_from_tube_hematocrit(double diameter_um, double tube_hematocrit);

/// mu_0.45 = 220 e^{-1.3 D} + 3.2 - 2.44 e^{-0.06 D^0.645}: relative apparent viscosity at Ht_D = 0.45.
double relative_viscosity_at_045(double diameter_um);

/// Shape exponent C = (0.8 + e^{-0.075 D}) (-1 + 1/(1 + 1e-11 D^12)) + 1/(1 + 1e-11 D^12).
double viscosity_shape_exponent(double diameter_um);

/// Relative apparent viscosity (to plasma), high shear, in vitro:
/// eta_rel = 1 + (mu_0.45 - 1) ((1 - Ht_D)^C - 1) / ((1 - 0.45)^C - 1).
double relative_apparent_viscosity(double diameter_um, double discharge_hematocrit);

}  // namespace hs::analysis
