// SPDX-License-Identifier: MIT
// Effective viscosity laws of the suspension and the smoothed volume fraction they take.
#include "unresolved/coupling/suspension_viscosity.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "unresolved/coupling/bulk_blood_viscosity.hpp"

namespace hs::unresolved {

SuspensionViscosity suspension_viscosity_from_name(const std::string& name) {
  if (name == "none") return SuspensionViscosity::none;
  if (name == "einstein") return SuspensionViscosity::einstein;
  if (name == "pries_bulk") return SuspensionViscosity::pries_bulk;
  throw hs::common::ConfigError(fmt::format("unknown suspension viscosity \"{}\" (known: none, einstein, pries_bulk)", name));
}

std::string suspension_viscosity_name(SuspensionViscosity model) {
  switch (model) {
    case SuspensionViscosity::einstein: return "einstein";
    case SuspensionViscosity::pries_bulk: return "pries_bulk";
    case SuspensionViscosity::none: break;
  }
  return "none";
}

double relative_viscosity(SuspensionViscosity model, double phi) {
  phi = std::clamp(phi, 0.0, 0.9);   // eps_min clipping bounds phi below 0.9 anyway
  switch (model) {
    case SuspensionViscosity::einstein: return 1.0 + 2.5 * phi;
    case SuspensionViscosity::pries_bulk: return bulk_blood_relative_viscosity(phi);
    case SuspensionViscosity::none: break;
  }
  return 1.0;
}

void fill_viscosity_factor(const FvmGrid& grid, SuspensionViscosity model, const BlockField<double>& eps,
                           BlockField<double>& factor) {
  const auto& n = grid.cells();
  const BlockField<double>& ff = grid.fluid_fractions();
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        double solid = 0.0;
        double fluid = 0.0;
        for (int dk = -1; dk <= 1; ++dk) {
          for (int dj = -1; dj <= 1; ++dj) {
            for (int di = -1; di <= 1; ++di) {
              const std::size_t c = eps.index(i + di, j + dj, k + dk);
              solid += ff[c] * (1.0 - eps[c]);
              fluid += ff[c];
            }
          }
        }
        factor(i, j, k) = relative_viscosity(model, fluid > 0.0 ? solid / fluid : 0.0);
      }
    }
  }
}

}  // namespace hs::unresolved
