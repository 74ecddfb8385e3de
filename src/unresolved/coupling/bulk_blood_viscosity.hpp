// SPDX-License-Identifier: MIT
// The "pries_bulk" suspension viscosity law: blood's bulk relative viscosity at a local volume fraction.
#pragma once

namespace hs::unresolved {

/// Relative viscosity (to plasma) of blood at hematocrit phi in [0, 1), in vitro at high shear, in the wide-tube
/// limit (D -> infinity) of Pries, Neuhaus & Gaehtgens 1992 (Am J Physiol 263:H1770), where no
/// Fahraeus-Lindqvist effect is left: mu_0.45 = 3.2 and shape exponent C = -0.8, so
///   mu_rel(phi) = 1 + (3.2 - 1) ((1 - phi)^-0.8 - 1) / (0.55^-0.8 - 1)   (2.87 phi for small phi, 3.2 at 0.45).
/// pre: 0 <= phi < 1 (std::invalid_argument otherwise).
///
/// A sensitivity choice, not an independent model: this law is the large-diameter end of the same fit of
/// Pries 1992 that `validate pries` compares with (analysis/pries1992.hpp), so with it part of the reference enters
/// the model's input. It carries no diameter (the tube's Fahraeus-Lindqvist drop must still come from the cell-free
/// layer), but a run with it is not a blind prediction of mu_rel; `none` and `einstein` (rigid spheres) are the
/// reference-free alternatives. Kept as it was (the shipped tube-pries case and `validate pries` use it) so that
/// results do not change; docs/cfd-dem.md gives the table for each law.
[[nodiscard]] double bulk_blood_relative_viscosity(double phi);

}  // namespace hs::unresolved
