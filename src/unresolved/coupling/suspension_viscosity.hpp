// SPDX-License-Identifier: MIT
// The particle stress of the suspension as a local effective viscosity of the volume-averaged plasma.
#pragma once

#include <string>

#include "unresolved/fvm/block_field.hpp"
#include "unresolved/fvm/fvm_grid.hpp"

namespace hs::unresolved {

/// Why: model A carries the plasma's stress only. A sphere that follows the flow is force-free, so the drag
/// adds no stress either, and the mixture has the plasma's viscosity whatever the hematocrit (measured: mu_rel
/// 0.87-1.15 in the Pries tubes, where Pries has 1.09-1.41). The stress the cells add (their stresslets) is put
/// in as a viscosity factor of the local cell volume fraction phi:
///   none:       1
///   einstein:   1 + 2.5 phi (Einstein 1911, rigid spheres, dilute)
///   pries_bulk: blood's in-vitro high-shear viscosity in the wide-tube limit of Pries et al. 1992 (where no
///               Fahraeus-Lindqvist effect is left; bulk_blood_viscosity.hpp), 2.87 phi for small phi. A
///               sensitivity choice: it comes from the fit `validate pries` compares with (see that header).
/// With a cell-free layer near the wall, the tube's apparent viscosity then follows from the phi profile.
enum class SuspensionViscosity { none, einstein, pries_bulk };

[[nodiscard]] SuspensionViscosity suspension_viscosity_from_name(const std::string& name);   // ConfigError if unknown
[[nodiscard]] std::string suspension_viscosity_name(SuspensionViscosity model);
/// Viscosity over the plasma's at volume fraction phi in [0, 1).
[[nodiscard]] double relative_viscosity(SuspensionViscosity model, double phi);

/// The viscosity factor of every cell from the void fraction eps (ghosts filled): phi = 1 - eps averaged over
/// the cell and its 26 neighbours (fluid cells only, weighted by their fluid fraction), because an effective
/// viscosity is a mean-field notion and one sphere covers several cells (d_p / dx ~ 2) with eps from 0.1 to 1.
void fill_viscosity_factor(const FvmGrid& grid, SuspensionViscosity model, const BlockField<double>& eps,
                           BlockField<double>& factor);

}  // namespace hs::unresolved
