// SPDX-License-Identifier: MIT
// Saffman-Mei lift coefficient.
#include "closures/saffman_mei_lift.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace hs::closures {

SaffmanMeiLift::SaffmanMeiLift()
    : LiftClosure("saffman_mei", {{*find_input("re_p"), {1e-6, 100.0}}, {*find_input("re_shear"), {0.0, 1.0}}}) {}

double SaffmanMeiLift::mei_factor(double re_p, double re_shear) {
  const double beta = re_shear / (2.0 * re_p);
  if (re_p <= 40.0) {
    const double s = 0.3314 * std::sqrt(beta);
    return (1.0 - s) * std::exp(-re_p / 10.0) + s;
  }
  return 0.0524 * std::sqrt(beta * re_p);
}

double SaffmanMeiLift::compute_lift_coefficient(const LiftInputs& in) const {
  if (!(in.re_p > 0.0)) return std::numeric_limits<double>::max();
  const double saffman = 8.0 * 1.615 / std::numbers::pi * std::sqrt(in.re_shear) / in.re_p;
  return saffman * mei_factor(in.re_p, in.re_shear);
}

}  // namespace hs::closures
