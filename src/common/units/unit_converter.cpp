// SPDX-License-Identifier: MIT
// The one immutable converter between SI and lattice/grid units.
#include "common/units/unit_converter.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

namespace hs::common {

UnitConverter::UnitConverter(const LatticeScales& scales)
    : dx_m_(scales.dx_m), dt_s_(scales.dt_s), rho_kg_m3_(scales.rho_kg_m3) {
  // A field left out of a designated initializer is 0: refuse it here (STYLE R2).
  if (!(dx_m_ > 0.0) || !(dt_s_ > 0.0) || !(rho_kg_m3_ > 0.0) || !std::isfinite(dx_m_) || !std::isfinite(dt_s_) ||
      !std::isfinite(rho_kg_m3_)) {
    throw std::invalid_argument(fmt::format("UnitConverter: every scale must be finite and > 0 (dx_m = {}, dt_s = {}, "
                                            "rho_kg_m3 = {})",
                                            dx_m_, dt_s_, rho_kg_m3_));
  }
}

UnitConverter UnitConverter::from_relaxation_time(double dx_m, double tau, double nu_m2_s, double rho_kg_m3) {
  if (!(tau > 0.5)) throw std::invalid_argument(fmt::format("UnitConverter: tau = {} must be > 0.5", tau));
  if (!(nu_m2_s > 0.0)) throw std::invalid_argument(fmt::format("UnitConverter: viscosity {} must be > 0", nu_m2_s));
  const double nu_lu = (tau - 0.5) / 3.0;
  return UnitConverter{LatticeScales{.dx_m = dx_m, .dt_s = nu_lu * dx_m * dx_m / nu_m2_s, .rho_kg_m3 = rho_kg_m3}};
}

long UnitConverter::to_lattice_steps(double s) const {
  const double steps = std::round(s / dt_s_);
  return steps < 1.0 ? 1L : static_cast<long>(steps);
}

std::string UnitConverter::describe() const {
  return fmt::format(
      "# hemoscale unit system: lattice units have dx = dt = 1 and reference density 1\n"
      "dx_m = {:.9e}\n"
      "dt_s = {:.9e}\n"
      "rho_kg_m3 = {:.9e}\n"
      "# multiply a lattice value by these factors to get SI\n"
      "velocity_m_s_per_lu = {:.9e}\n"
      "viscosity_m2_s_per_lu = {:.9e}\n"
      "force_N_per_lu = {:.9e}\n"
      "force_density_N_m3_per_lu = {:.9e}\n"
      "pressure_Pa_per_lu = {:.9e}\n",
      dx_m_, dt_s_, rho_kg_m3_, to_si_velocity(1.0), to_si_viscosity(1.0), to_si_force(1.0),
      to_si_force_density(1.0), to_si_pressure(1.0));
}

void UnitConverter::write(const std::filesystem::path& file) const {
  std::ofstream out(file);
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", file.string()));
  out << describe();
}

}  // namespace hs::common
