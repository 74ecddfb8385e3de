// SPDX-License-Identifier: MIT
// The one immutable converter between SI and lattice/grid units (DESIGN.md "Units").
#pragma once

#include <filesystem>
#include <string>

namespace hs::common {

/// The three scales that fix a lattice unit system. Every field must be > 0 (checked).
struct LatticeScales {
  double dx_m;
  double dt_s;
  double rho_kg_m3;
};

/// Converts SI <-> lattice units. Lattice units: dx = dt = 1, reference density = 1.
/// Immutable; built once per run and passed by const reference (STYLE R4).
class UnitConverter {
 public:
  explicit UnitConverter(const LatticeScales& scales);

  /// dt from dx, tau and nu: nu_lu = c_s^2 (tau - 1/2) with c_s^2 = 1/3 (D3Q19),
  /// so dt = (tau - 1/2) dx^2 / (3 nu). The time step is derived, never given too.
  static UnitConverter from_relaxation_time(double dx_m, double tau, double nu_m2_s, double rho_kg_m3);

  [[nodiscard]] double dx_m() const { return dx_m_; }
  [[nodiscard]] double dt_s() const { return dt_s_; }
  [[nodiscard]] double rho_kg_m3() const { return rho_kg_m3_; }

  [[nodiscard]] double to_lattice_length(double m) const { return m / dx_m_; }
  [[nodiscard]] double to_si_length(double lu) const { return lu * dx_m_; }
  [[nodiscard]] double to_lattice_time(double s) const { return s / dt_s_; }
  [[nodiscard]] double to_si_time(double lu) const { return lu * dt_s_; }
  /// Number of whole lattice steps covering a duration (rounded to nearest, at least 1).
  [[nodiscard]] long to_lattice_steps(double s) const;
  [[nodiscard]] double to_lattice_velocity(double m_s) const { return m_s * dt_s_ / dx_m_; }
  [[nodiscard]] double to_si_velocity(double lu) const { return lu * dx_m_ / dt_s_; }
  [[nodiscard]] double to_lattice_viscosity(double m2_s) const { return m2_s * dt_s_ / (dx_m_ * dx_m_); }
  [[nodiscard]] double to_si_viscosity(double lu) const { return lu * dx_m_ * dx_m_ / dt_s_; }
  [[nodiscard]] double to_lattice_density(double kg_m3) const { return kg_m3 / rho_kg_m3_; }
  [[nodiscard]] double to_si_density(double lu) const { return lu * rho_kg_m3_; }
  [[nodiscard]] double to_lattice_acceleration(double m_s2) const { return m_s2 * dt_s_ * dt_s_ / dx_m_; }
  [[nodiscard]] double to_si_acceleration(double lu) const { return lu * dx_m_ / (dt_s_ * dt_s_); }
  /// A point force converts with rho dx^4 / dt^2 (resolved-methods.md section 8, item 1).
  [[nodiscard]] double to_lattice_force(double N) const { return N / force_scale(); }
  [[nodiscard]] double to_si_force(double lu) const { return lu * force_scale(); }
  /// A force density (per volume) converts with rho dx / dt^2.
  [[nodiscard]] double to_lattice_force_density(double N_m3) const { return N_m3 / force_density_scale(); }
  [[nodiscard]] double to_si_force_density(double lu) const { return lu * force_density_scale(); }
  /// A pressure or stress converts with rho dx^2 / dt^2.
  [[nodiscard]] double to_lattice_pressure(double Pa) const { return Pa / pressure_scale(); }
  [[nodiscard]] double to_si_pressure(double lu) const { return lu * pressure_scale(); }

  /// Writes the scales and the derived factors as text (`units.txt` in every run folder).
  void write(const std::filesystem::path& file) const;
  [[nodiscard]] std::string describe() const;

 private:
  [[nodiscard]] double force_scale() const { return rho_kg_m3_ * dx_m_ * dx_m_ * dx_m_ * dx_m_ / (dt_s_ * dt_s_); }
  [[nodiscard]] double force_density_scale() const { return rho_kg_m3_ * dx_m_ / (dt_s_ * dt_s_); }
  [[nodiscard]] double pressure_scale() const { return rho_kg_m3_ * dx_m_ * dx_m_ / (dt_s_ * dt_s_); }

  double dx_m_;
  double dt_s_;
  double rho_kg_m3_;
};

}  // namespace hs::common
