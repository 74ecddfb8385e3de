// SPDX-License-Identifier: MIT
// The DEM time-step criterion dt <= 0.1 min(t_Rayleigh, t_Hertz) and its error message.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "dem_test_helpers.hpp"
#include "unresolved/dem/dem_system.hpp"

namespace hs::unresolved {
namespace {

TEST(TimeStepCheck, RayleighTimeOfTheLiggghtsAnchor) {
  // Hand value: R = 3.91e-6, G = 1e5 / 2.9 = 34483 Pa, sqrt(1100 / G) = 0.17861, 0.1631*0.45 + 0.8766 = 0.94999:
  // t_R = pi * 3.91e-6 * 0.17861 / 0.94999 = 2.3095e-6 s.
  EXPECT_NEAR(rayleigh_time_s(test::rbcpack_params()), 2.3095e-6, 1e-9);
}

TEST(TimeStepCheck, HertzTimeHandValue) {
  // m* = 1100 pi/6 d^3 / 2 = 1.3771e-13 kg, R* = 1.955e-6 m, Y* = 1e5 / (2 (1 - 0.45^2)) = 62696 Pa, v = 0.02 m/s:
  // t_H = 2.87 (m*^2 / (R* Y*^2 v))^(1/5) = 7.5187e-6 s.
  ParticleParams p = test::rbcpack_params();
  EXPECT_NEAR(hertz_time_s(p, 0.02) / 7.5187e-6, 1.0, 1e-4);
}

TEST(TimeStepCheck, LiggghtsAnchorStepPassesAndALargerOneFails) {
  const ParticleParams p = test::rbcpack_params();
  EXPECT_NO_THROW(check_time_step(p, 2e-7));   // in.rbcpack's dt: 0.087 t_R
  try {
    check_time_step(p, 3e-7);
    FAIL() << "no error";
  } catch (const hs::common::ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("3e-07 s"), std::string::npos) << m;
    EXPECT_NE(m.find("Rayleigh time 2.309e-06 s"), std::string::npos) << m;
    EXPECT_NE(m.find("youngs_modulus_Pa"), std::string::npos) << m;
  }
}

TEST(TimeStepCheck, DemSystemRefusesAViolatingStep) {
  EXPECT_THROW(DemSystem({.params = test::rbcpack_params(), .domain = test::cube(1e-4, true), .time_step_s = 1e-6}, nullptr),
               hs::common::ConfigError);
}

TEST(TimeStepCheck, MeasuredSpeedCheckIsANumericalError) {
  const DemSystem dem({.params = test::rbcpack_params(), .domain = test::cube(1e-4, true), .time_step_s = 2e-7}, nullptr);
  EXPECT_NO_THROW(dem.check_time_step_at(0.02));
  EXPECT_THROW(dem.check_time_step_at(1e3), hs::common::NumericalError);
}

TEST(TimeStepCheck, ShortPeriodicBoxIsAConfigError) {
  EXPECT_THROW(DemSystem({.params = test::rbcpack_params(), .domain = test::cube(8e-6, true), .time_step_s = 2e-7}, nullptr),
               hs::common::ConfigError);
}

}  // namespace
}  // namespace hs::unresolved
