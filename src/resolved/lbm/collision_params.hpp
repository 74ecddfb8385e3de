// SPDX-License-Identifier: MIT
// Relaxation parameters of the BGK and TRT collision operators.
#pragma once

#include <stdexcept>

namespace hs::resolved {

enum class CollisionModel { bgk, trt };

/// TRT magic parameter Lambda = (tau+ - 1/2)(tau- - 1/2) = 3/16 puts the half-way bounce-back wall exactly
/// half way between nodes for Poiseuille flow, independently of tau (Ginzburg, Verhaeghe & d'Humieres 2008,
/// Commun. Comput. Phys. 3:427; Krueger et al. 2017, section 10.7.2).
inline constexpr double trt_magic_default = 3.0 / 16.0;

struct CollisionParams {
  CollisionModel model = CollisionModel::trt;
  double tau = 1.0;                     // relaxation time of the symmetric (viscous) moments, > 1/2
  double magic = trt_magic_default;     // TRT only

  /// Relaxation rate of the even (symmetric) part; sets nu_lu = c_s^2 (tau - 1/2).
  [[nodiscard]] double omega_plus() const { return 1.0 / tau; }
  /// Relaxation rate of the odd part: tau- = 1/2 + Lambda / (tau+ - 1/2) for TRT, = tau for BGK.
  [[nodiscard]] double omega_minus() const {
    return model == CollisionModel::bgk ? 1.0 / tau : 1.0 / (0.5 + magic / (tau - 0.5));
  }
  /// Lattice kinematic viscosity (D3Q19, c_s^2 = 1/3).
  [[nodiscard]] double viscosity_lu() const { return (tau - 0.5) / 3.0; }
  void validate() const {
    if (!(tau > 0.5)) throw std::invalid_argument("relaxation time tau must be > 1/2");
    if (model == CollisionModel::trt && !(magic > 0.0)) throw std::invalid_argument("TRT magic parameter must be > 0");
  }
};

}  // namespace hs::resolved
