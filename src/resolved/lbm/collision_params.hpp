// SPDX-License-Identifier: MIT
// Relaxation parameters of the BGK and TRT collision operators.
#pragma once

#include <stdexcept>
#include <string_view>

namespace hs::resolved {

/// bgk and trt: the classic operators. regularized: the even part regularised, the odd part TRT with its rate bounded
/// by odd_rate_max (regularized_guo_collision.hpp), with wall closures that keep TRT's wall location at Lambda = magic
/// (make_wall_link): for tau up to ~60.
enum class CollisionModel { bgk, trt, regularized };

/// The case-file names of the models (`[numerics] collision`).
inline constexpr std::string_view collision_model_name(CollisionModel m) {
  return m == CollisionModel::bgk ? "bgk" : (m == CollisionModel::trt ? "trt" : "regularized");
}
/// pre: `name` is one of the names collision_model_name gives (the case readers check it with one_of).
inline constexpr CollisionModel collision_model_from_name(std::string_view name) {
  return name == "bgk" ? CollisionModel::bgk : (name == "trt" ? CollisionModel::trt : CollisionModel::regularized);
}

/// TRT magic parameter Lambda = (tau+ - 1/2)(tau- - 1/2) = 3/16 puts the half-way bounce-back wall exactly
/// half way between nodes for Poiseuille flow, independently of tau (Ginzburg, Verhaeghe & d'Humieres 2008,
/// Commun. Comput. Phys. 3:427; Krueger et al. 2017, section 10.7.2).
inline constexpr double trt_magic_default = 3.0 / 16.0;

/// regularized: omega- <= 1.8, so the odd modes lose at least 20 % per step (TRT at Lambda = 3/16: 2.5 % at tau
/// 30.5, 1 % at tau 60). The bound sets Lambda = (tau - 1/2)(1/1.8 - 1/2) above tau = 3.9 (3.3 at tau 60), whose
/// wall error the shifted closure removes only to second order: measured, tube Poiseuille with Bouzidi walls, L2 error
/// at R = 10 within 22 % of TRT's up to tau 60 and equal to it at R = 20; a lower bound moves the walls more
/// (omega- = 1, Lambda = 30: +4.5 % at R = 10), a higher one damps less. (Our measurement, lbm tube tests.)
/// The immersed boundary has no such closure: its slip grows with Lambda (Seta et al. 2014, PRE 89:023307: the odd
/// relaxation time sets the IB-LBM's boundary slip). Measured, a capsule in shear: D the same within 1 % at tau 2.9,
/// 8.1 and 25.8 with TRT at Lambda = 3/16, but 5 % and 20 % lower at 8.1 and 25.8 with this bound
/// (docs/resolved-coupling.md, "The lattice's tau is Lambda"). [numerics] odd_rate_max raises it.
inline constexpr double regularized_odd_rate_max_default = 1.8;
/// regularized: the kernel regularises the even part where TRT's own odd rate exceeds this (tau > 3.9 at Lambda =
/// 3/16), whatever the bound on the odd rate: below, regularized is TRT bit for bit.
inline constexpr double regularized_from_odd_rate = 1.8;

struct CollisionParams {
  CollisionModel model = CollisionModel::trt;
  double tau = 1.0;                     // relaxation time of the symmetric (viscous) moments, > 1/2
  double magic = trt_magic_default;     // TRT; regularized: the Lambda whose walls its closures reproduce
  double odd_rate_max = regularized_odd_rate_max_default;   // regularized: bound on omega-

  /// Relaxation rate of the even (symmetric) part; sets nu_lu = c_s^2 (tau - 1/2).
  [[nodiscard]] double omega_plus() const { return 1.0 / tau; }
  /// Relaxation rate of the odd part: tau- = 1/2 + Lambda / (tau+ - 1/2) for TRT, = tau for BGK, and TRT's bounded
  /// by odd_rate_max for the regularised collision.
  [[nodiscard]] double omega_minus() const {
    if (model == CollisionModel::bgk) return 1.0 / tau;
    const double trt = 1.0 / (0.5 + magic / (tau - 0.5));
    if (model == CollisionModel::regularized) return trt < odd_rate_max ? trt : odd_rate_max;
    return trt;
  }
  /// The regularised kernel runs where TRT's odd rate exceeds regularized_from_odd_rate (tau > 3.9 at Lambda = 3/16),
  /// the odd rate itself bounded by odd_rate_max; below, regularized is TRT (bit for bit): there TRT damps every mode,
  /// and the even filtering alone changed the tube error at tau 0.6 (L2 3.51e-4 vs TRT's 3.30e-4 at R = 20, 2.18e-3
  /// vs 1.75e-3 at R = 10; measured, tube Poiseuille, Bouzidi walls).
  [[nodiscard]] bool regularizes() const {
    return model == CollisionModel::regularized && 1.0 / (0.5 + magic / (tau - 0.5)) > regularized_from_odd_rate;
  }
  /// The bulk's Lambda = (tau+ - 1/2)(tau- - 1/2): the TRT magic, (tau - 1/2)^2 for BGK, and above the odd bound the
  /// regularised collision's larger one. The immersed boundary's slip follows it (regularized_odd_rate_max_default).
  [[nodiscard]] double bulk_lambda() const { return (tau - 0.5) * (1.0 / omega_minus() - 0.5); }
  /// The Lambda whose wall location the interpolated closures reproduce: the operator's own, except for the
  /// regularised collision, whose closures carry TRT's at Lambda = magic (boundary_links.hpp).
  [[nodiscard]] double closure_lambda() const {
    return model == CollisionModel::regularized ? magic : bulk_lambda();
  }
  /// Lattice kinematic viscosity (D3Q19, c_s^2 = 1/3).
  [[nodiscard]] double viscosity_lu() const { return (tau - 0.5) / 3.0; }
  void validate() const {
    if (!(tau > 0.5)) throw std::invalid_argument("relaxation time tau must be > 1/2");
    if (model != CollisionModel::bgk && !(magic > 0.0)) throw std::invalid_argument("TRT magic parameter must be > 0");
    if (model == CollisionModel::regularized && !(odd_rate_max >= regularized_from_odd_rate && odd_rate_max < 2.0)) {
      throw std::invalid_argument("regularized: odd_rate_max must be in [1.8, 2)");
    }
  }
};

}  // namespace hs::resolved
