// SPDX-License-Identifier: MIT
// The Evans–Fung biconcave red-blood-cell surface: thickness profile, implicit form and projection onto it.
#pragma once

#include "common/vec3.hpp"

namespace hs::resolved {

/// Evans & Fung 1972 (Microvasc Res 4:335) in the form of Fedosov, Caswell & Karniadakis 2010 (Biophys J 98:2215):
///   z(r) = ± D0 sqrt(1 - 4 r^2/D0^2) (a0 + a1 r^2/D0^2 + a2 r^4/D0^4),  r^2 = x^2 + y^2,
/// with a0 = 0.0518, a1 = 2.0026, a2 = -4.491 (shared/reference/resolved-methods.md §4.1).
/// The exact surface encloses 94.1 um^3 with area 134.1 um^2 at D0 = 7.82 um.
class EvansFungShape {
 public:
  /// Human RBC mean diameter, Evans & Fung 1972 (reference/validation/rbc_blood_properties.csv).
  static constexpr double default_diameter_m = 7.82e-6;

  explicit EvansFungShape(double diameter_m = default_diameter_m);

  [[nodiscard]] double diameter_m() const { return d0_m_; }
  /// Half thickness z(r) >= 0 in metres; 0 for r >= D0/2.
  [[nodiscard]] double half_thickness_m(double r_m) const;
  /// Implicit function Phi(p) = (z/D0)^2 - (1 - 4s) P(s)^2, s = r^2/D0^2: zero on the surface, < 0 inside.
  [[nodiscard]] double implicit(const hs::common::Vec3& p_m) const;
  /// Closest-point projection onto the surface by Newton steps along grad Phi (converges from nearby points).
  [[nodiscard]] hs::common::Vec3 project(const hs::common::Vec3& p_m) const;

 private:
  [[nodiscard]] hs::common::Vec3 implicit_gradient(const hs::common::Vec3& p_m) const;

  double d0_m_;
  static constexpr double a0_ = 0.0518;
  static constexpr double a1_ = 2.0026;
  static constexpr double a2_ = -4.491;
};

}  // namespace hs::resolved
