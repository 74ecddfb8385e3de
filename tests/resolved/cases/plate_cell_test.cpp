// SPDX-License-Identifier: MIT
// The plate cases' input and reduction: derived numerics of shear and migration against their formulas, bad input,
// and the tumbling period read from a synthetic Jeffery orbit.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "resolved/cases/case_text_helpers.hpp"
#include "resolved/cases/cell_simulation.hpp"
#include "resolved/cases/plate_cell_checks.hpp"
#include "resolved/cases/plate_cell_config.hpp"
#include "resolved/cases/plate_cell_series.hpp"
#include "resolved/cases/stokes_analogue.hpp"
#include "resolved/measure/flow_mode.hpp"
#include "resolved/measure/whole_revolutions.hpp"
#include "resolved/membrane/triangle_mesh.hpp"

namespace hs::resolved {
namespace {

std::string shipped(const std::string& folder) { return test::shipped_case_text(folder); }

std::string with(const std::string& text, const std::string& from, const std::string& to) {
  return test::replaced(text, from, to);
}

PlateCellConfig read(const std::string& toml, PlateFlow flow) {
  auto file = common::ConfigFile::parse(toml, "case.toml");
  // [case] type is read by the case dispatcher in the app.
  EXPECT_EQ(file->root().section("case").string("type"), flow == PlateFlow::shear ? "shear" : "migration");
  return read_plate_cell(*file, flow, false);
}

TEST(PlateCellConfig, ShearRateFixesTheWallSpeedAndTheGroups) {
  const PlateCellConfig c = read(shipped("shear"), PlateFlow::shear);
  // U/2 = gamma H / 2 = 400 * 12 um = 4.8 mm/s; dt = 0.04 dx / (U/2) = 8.33 us; tau = 1/2 + 3 nu dt / dx^2 = 25.5.
  EXPECT_NEAR(c.u_max_m_s, 4.8e-3, 1e-15);
  EXPECT_NEAR(c.numerics.dt_s, 0.04e-6 / 4.8e-3, 1e-18);
  EXPECT_NEAR(c.numerics.collision.tau, 0.5 + 3.0 * 0.04e-6 / 4.8e-3 / 1e-6, 1e-9);
  EXPECT_NEAR(c.reynolds, 400.0 * 24e-6 * 24e-6 / 1e-6, 1e-12);   // rho gamma H^2 / mu
  EXPECT_NEAR(c.max_time_s, 2.5 * jeffery_period(400.0), 1e-12);
  EXPECT_EQ(c.spin_up_steps, 0);   // started on the Couette profile
}

TEST(PlateCellConfig, CapillaryNumberGivesTheShearRate) {
  const PlateCellConfig c = read(shipped("shear/tank-treading"), PlateFlow::shear);
  // gamma = Ca k_s / (mu a) with Ca = 1, k_s = 2.5 uN/m (default), mu = 1.025 mPa s, a = 3.91 um.
  EXPECT_NEAR(c.shear_rate_1_s, 2.5e-6 / (1025.0 * 1e-6 * 3.91e-6), 1e-9);
  EXPECT_EQ(c.disc_axis, 1);
}

TEST(PlateCellConfig, TheSphereShapeIsReadAndADiscAxisBesideItRefused) {
  const std::string shear = shipped("shear");
  EXPECT_EQ(read(shear, PlateFlow::shear).shape, CellShapeKind::biconcave);   // the default
  const std::string sphere = with(shear, "disc_axis = \"y\"", "shape = \"sphere\"");
  EXPECT_EQ(read(sphere, PlateFlow::shear).shape, CellShapeKind::sphere);
  // A disc axis beside the sphere is a mistake the user should hear about, not silently ignored.
  EXPECT_THROW(read(with(shear, "disc_axis = \"y\"", "disc_axis = \"y\"\nshape = \"sphere\""), PlateFlow::shear),
               common::ConfigError);
  EXPECT_THROW(read(with(shear, "disc_axis = \"y\"", "shape = \"cube\""), PlateFlow::shear), common::ConfigError);
}

TEST(SphereCellMesh, HasTheMembraneMeshsVertexCountAndTheVolumeOfItsSphere) {
  const PlateCellConfig c = read(shipped("shear"), PlateFlow::shear);
  const double a = kCellRadius_m;
  const TriangleMesh sphere = sphere_cell_mesh(c.membrane, a);
  EXPECT_EQ(sphere.vertex_count(), build_membrane_mesh(c.membrane).vertex_count());
  const double volume = 4.0 / 3.0 * std::numbers::pi * a * a * a;
  EXPECT_NEAR(mesh_volume_m3(sphere), volume, 1e-12 * volume);   // scaled to it: round-off
  // Every vertex on one sphere about the origin, a little outside a: a polyhedron inscribed in a sphere holds less
  // volume than the sphere, so the one with the volume of radius a has its vertices further out (258 vertices: < 2 %).
  for (const auto& v : sphere.vertices_m) {
    EXPECT_GT(norm(v), a);
    EXPECT_LT(norm(v), 1.02 * a);
    EXPECT_NEAR(norm(v), norm(sphere.vertices_m[0]), 1e-12 * a);
  }
}

TEST(PlateCellConfig, ShearRateAndCapillaryTogetherAreRefused) {
  const std::string toml = with(shipped("shear"), "shear_rate_1_s = 400.0", "shear_rate_1_s = 400.0\ncapillary = 0.1");
  EXPECT_THROW(read(toml, PlateFlow::shear), common::ConfigError);
}

TEST(PlateCellConfig, MembraneForceDefaultsToTheSampledStress) {
  const PlateCellConfig c = read(shipped("shear/tank-treading"), PlateFlow::shear);
  EXPECT_EQ(c.numerics.membrane_force, MembraneForce::fluid_stress);
  EXPECT_TRUE(c.numerics.drive_on_enclosed_volume);
}

TEST(PlateCellConfig, MembraneForceIbmReactionIsReadAndDropsTheDriveShare) {
  const std::string toml = with(shipped("shear/tank-treading"), "ibm_iterations = 5",
                                "ibm_iterations = 5\nmembrane_force = \"ibm_reaction\"");
  const PlateCellConfig c = read(toml, PlateFlow::shear);
  EXPECT_EQ(c.numerics.membrane_force, MembraneForce::ibm_reaction);
  EXPECT_FALSE(c.numerics.drive_on_enclosed_volume);   // the reaction carries the drive on the cell's interior
}

TEST(PlateCellConfig, MembraneForceBadValueOrStressKeysAreRefusedByName) {
  const std::string base = shipped("shear/tank-treading");
  for (const std::string& extra : {std::string("membrane_force = \"reaction\""),
                                   std::string("membrane_force = \"ibm_reaction\"\ntraction_area = \"membrane\""),
                                   std::string("membrane_force = \"ibm_reaction\"\ndrive_on_enclosed_volume = true")}) {
    const std::string toml = with(base, "ibm_iterations = 5", "ibm_iterations = 5\n" + extra);
    try {
      (void)read(toml, PlateFlow::shear);
      ADD_FAILURE() << "accepted: " << extra;
    } catch (const common::ConfigError& e) {
      const std::string what = e.what();
      const std::string key = extra.find("traction_area") != std::string::npos ? "traction_area"
                              : extra.find("drive_on") != std::string::npos   ? "drive_on_enclosed_volume"
                                                                              : "membrane_force";
      EXPECT_NE(what.find(key), std::string::npos) << what;
    }
  }
}

TEST(PlateCellConfig, MigrationReynoldsFixesUmaxAndTheSpinUp) {
  const PlateCellConfig c = read(shipped("migration"), PlateFlow::poiseuille);
  const double u_max = 0.1 * 1e-6 / 24e-6;   // Re = rho H U_max / mu
  EXPECT_NEAR(c.u_max_m_s, u_max, 1e-15);
  EXPECT_NEAR(c.shear_rate_1_s, 4.0 * u_max / 24e-6, 1e-9);   // wall shear rate of plane Poiseuille flow
  EXPECT_NEAR(c.numerics.dt_s, 0.04e-6 / u_max, 1e-18);
  EXPECT_NEAR(c.numerics.collision.tau, 0.5 + 3.0 * 0.04e-6 / u_max / 1e-6, 1e-9);   // 29.3 < 30.5: no cap
  // Spin-up: max(H^2 / nu = 576 us = 60 steps, 10 tau = 293 steps).
  EXPECT_EQ(c.spin_up_steps, std::lround(10.0 * c.numerics.collision.tau));
}

TEST(PlateCellConfig, TheLatticeFluidsMemoryIsShortAgainstTheShearTimeByDefault) {
  // Regression guard for the drift of the Ca = 1 viscous cell to a wall (docs/resolved-coupling.md, "The lattice
  // fluid's memory"): at the Mach-based lattice velocity 0.04 this case ran at tau 16.5, Wi = gamma (tau - 1/2) dt =
  // 0.053, and its cell left the centreline after 0.5 s. Now tau is capped so that Wi = 0.005 (the default):
  // (tau - 1/2)^2 = 3 nu Wi / (gamma dx^2).
  const PlateCellConfig c = read(shipped("shear/membrane-viscosity"), PlateFlow::shear);
  const double gamma = c.shear_rate_1_s;
  const double tau = 0.5 + std::sqrt(3.0 * 1e-6 * 0.005 / (gamma * 1e-12));
  EXPECT_NEAR(c.numerics.collision.tau, tau, 1e-12);   // 5.40
  EXPECT_NEAR(c.numerics.dt_s, (tau - 0.5) * 1e-12 / 3e-6, 1e-20);
  EXPECT_NEAR(c.numerics.lattice_velocity, c.u_max_m_s * c.numerics.dt_s / 1e-6, 1e-14);   // lowered from 0.04
  EXPECT_LT(c.numerics.lattice_velocity, 0.04);
  EXPECT_NEAR(c.numerics.lattice_weissenberg, gamma * (c.numerics.collision.tau - 0.5) * c.numerics.dt_s, 1e-15);
  EXPECT_NEAR(c.numerics.lattice_weissenberg, 0.005, 1e-12);
}

TEST(PlateCellConfig, TheWeissenbergBoundIsReadAndOnlyLowersTau) {
  // The stiff shear case states max_lattice_weissenberg = 0.2 and runs at its Mach-based tau (Wi 0.083): unchanged.
  const PlateCellConfig stiff = read(shipped("shear"), PlateFlow::shear);
  EXPECT_NEAR(stiff.numerics.collision.tau, 25.5, 1e-9);
  EXPECT_NEAR(stiff.numerics.lattice_weissenberg, 400.0 * 25.0 * 0.04e-6 / 4.8e-3, 1e-12);
  // 0.01 there: tau - 1/2 = sqrt(3 nu 0.01 / (400 dx^2)) = 8.66.
  const std::string tight = with(shipped("shear"), "max_lattice_weissenberg = 0.2 ", "max_lattice_weissenberg = 0.01 ");
  const PlateCellConfig c = read(tight, PlateFlow::shear);
  EXPECT_NEAR(c.numerics.collision.tau, 0.5 + std::sqrt(3.0 * 1e-6 * 0.01 / (400.0 * 1e-12)), 1e-12);
  EXPECT_NEAR(c.numerics.lattice_weissenberg, 0.01, 1e-12);
  const std::string bad = with(shipped("shear"), "max_lattice_weissenberg = 0.2 ", "max_lattice_weissenberg = 0.0 ");
  EXPECT_THROW(read(bad, PlateFlow::shear), common::ConfigError);
}

TEST(PlateCellConfig, WithoutACytoplasmViscosityTheCellIsHealthy) {
  // Absent: kHealthyCytoplasmViscosity_Pa_s = 6 mPa s against the plasma's rho nu = 1.025e-3 Pa s (membrane-viscosity
  // states no value). The plasma's own value (shear/tank-treading states it): ratio exactly 1, the lattice keeps one
  // phase, and tau is the one-fluid case's.
  const PlateCellConfig absent = read(shipped("shear/membrane-viscosity"), PlateFlow::shear);
  EXPECT_NEAR(absent.numerics.viscosity_ratio, 6.0e-3 / (1025.0 * 1.0e-6), 1e-12);
  const PlateCellConfig plasma = read(shipped("shear/tank-treading"), PlateFlow::shear);
  EXPECT_EQ(plasma.numerics.viscosity_ratio, 1.0);
  const std::string inner_default = with(shipped("shear/tank-treading"), "cytoplasm_viscosity_Pa_s = 1.025e-3 ", "");
  EXPECT_NEAR(read(inner_default, PlateFlow::shear).numerics.viscosity_ratio, 6.0e-3 / 1.025e-3, 1e-12);
}

TEST(PlateCellConfig, HealthyCytoplasmGivesTheInnerTauWithinTheCap) {
  // 6 mPa s against 1.025 mPa s: ratio 5.854. membrane-viscosity runs at its Weissenberg tau 5.40, and the cytoplasm at
  // 1/2 + 5.854 (5.40 - 1/2) = 29.2, under max_tau 30.5: tau outside the same as with plasma inside.
  const PlateCellConfig plain = read(with(shipped("shear/membrane-viscosity"), "[cell]\n",
                                          "[cell]\ncytoplasm_viscosity_Pa_s = 1.025e-3\n"), PlateFlow::shear);
  const PlateCellConfig c = read(shipped("shear/membrane-viscosity"), PlateFlow::shear);   // the default: healthy
  const double ratio = 6.0e-3 / (1025.0 * 1.0e-6);
  EXPECT_EQ(plain.numerics.viscosity_ratio, 1.0);
  EXPECT_NEAR(c.numerics.viscosity_ratio, ratio, 1e-12);
  EXPECT_EQ(c.numerics.collision.tau, plain.numerics.collision.tau);
  EXPECT_NEAR(c.numerics.inner_collision.tau, 0.5 + ratio * (plain.numerics.collision.tau - 0.5), 1e-12);
  // The stiff case runs at tau 25.5 with plasma inside: with 6 mPa s the cap 30.5 holds inside, tau_out - 1/2 = 30 /
  // ratio (more steps).
  const PlateCellConfig stiff = read(with(shipped("shear"), "cytoplasm_viscosity_Pa_s = 1.025e-3 ",
                                          "cytoplasm_viscosity_Pa_s = 6.0e-3 "), PlateFlow::shear);
  EXPECT_NEAR(stiff.numerics.collision.tau, 0.5 + 30.0 / ratio, 1e-12);
  EXPECT_NEAR(stiff.numerics.inner_collision.tau, 30.5, 1e-12);
  EXPECT_EQ(stiff.numerics.inner_collision.model, stiff.numerics.collision.model);
}

TEST(PlateCellConfig, BadCytoplasmViscositiesAreRefusedByName) {
  for (const std::string value : {"0.0", "-6e-3", "2.0", "\"healthy\""}) {
    const std::string toml =
        with(shipped("shear/membrane-viscosity"), "[cell]\n", "[cell]\ncytoplasm_viscosity_Pa_s = " + value + "\n");
    try {
      (void)read(toml, PlateFlow::shear);
      ADD_FAILURE() << value << " accepted";
    } catch (const common::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("cytoplasm_viscosity_Pa_s"), std::string::npos) << e.what();
    }
  }
  // 1e-5 Pa s is in range, but puts the cytoplasm's tau at 1/2 + 0.00976 x 4.90 = 0.548 < 0.55.
  const std::string thin =
      with(shipped("shear/membrane-viscosity"), "[cell]\n", "[cell]\ncytoplasm_viscosity_Pa_s = 1.0e-5\n");
  EXPECT_THROW((void)read(thin, PlateFlow::shear), common::ConfigError);
}

TEST(PlateCellConfig, ReleaseTooCloseToAWallIsRefused) {
  // y0 = 0.1 H = 2.4 um < a = 3.91 um: the rim would cross the wall.
  const std::string toml = with(shipped("migration"), "initial_height = 0.3", "initial_height = 0.1");
  EXPECT_THROW(read(toml, PlateFlow::poiseuille), common::ConfigError);
}

TEST(TumblingPeriod, ReadsTheJefferyPeriodOfASyntheticOrbit) {
  // Jeffery orbit of the long axis: tan(phi) = -r_e tan(2 pi t / T) (phi against the flow, turning clockwise),
  // sampled at 200 points per period and folded to (-pi/2, pi/2] like the measured inclination.
  const double r_e = 0.37;
  const double period = jeffery_period(100.0, r_e);
  std::vector<double> t, phi;
  for (int i = 0; i <= 700; ++i) {
    const double time = period * i / 200.0;
    const double a = std::atan2(-r_e * std::sin(2.0 * std::numbers::pi * time / period),
                                std::cos(2.0 * std::numbers::pi * time / period));
    double folded = a;
    if (folded > std::numbers::pi / 2) folded -= std::numbers::pi;
    if (folded <= -std::numbers::pi / 2) folded += std::numbers::pi;
    t.push_back(time);
    phi.push_back(folded);
  }
  const TumblingPeriod p = tumbling_period(t, phi);
  EXPECT_EQ(p.half_turns, 6);   // 3.5 periods: 7 crossings of the across-flow direction
  // Linear interpolation of the crossing times is exact up to the curvature of phi(t) within one sample (1/200 T).
  EXPECT_NEAR(p.period_s, period, 1e-3 * period);
  EXPECT_EQ(to_string(classify_flow_mode(phi, phi)), "tumbling");
}

TEST(ShearResults, ASwingingCellTankTreadsAndSettlesOverWholeRevolutions) {
  // A swinging cell: the outline's angle oscillates 0.1 +- 0.25 rad at twice the membrane's rate (range 0.5 rad, over
  // the classifier's 0.35: "intermediate"), the marker turns clockwise at omega. Sampled like a run (folded angles).
  const PlateCellConfig c = read(shipped("shear/fischer-korzeniewski"), PlateFlow::shear);
  const double omega = 0.2 * c.shear_rate_1_s;   // 2 pi f / gamma_dot = 0.2: f / gamma_dot 0.0318
  PlateCellSeries series(c);
  const double end = 12.0 * 2.0 * std::numbers::pi / omega;   // 12 revolutions: 6 after the transient half
  for (int i = 0; i <= 6000; ++i) {
    PlateCellSample s;
    s.time_s = end * i / 6000.0;
    s.inclination_rad = 0.1 + 0.25 * std::sin(2.0 * omega * s.time_s);
    s.marker_phase_rad = std::atan2(std::sin(-omega * s.time_s), std::cos(-omega * s.time_s));
    s.di = 0.4 + 0.05 * std::cos(2.0 * omega * s.time_s);
    series.add(s);
  }
  const nlohmann::json r = series.results();
  EXPECT_EQ(r["flow_mode"], "intermediate");
  EXPECT_TRUE(r["membrane_tank_treads"]);
  EXPECT_TRUE(r["tank_treading_settled"]);
  // Whole revolutions: the rate, the mean angle and DI of a periodic motion exactly (sampling: 500 samples a turn).
  EXPECT_NEAR(r["tank_treading_frequency_over_shear_rate"].get<double>(), 0.2 / (2.0 * std::numbers::pi), 1e-6);
  EXPECT_NEAR(r["mean_inclination_settled_deg"].get<double>(), 0.1 * 180.0 / std::numbers::pi, 0.01);
  EXPECT_NEAR(r["swinging_amplitude_deg"].get<double>(), 0.25 * 180.0 / std::numbers::pi, 0.01);
  EXPECT_NEAR(r["di_settled"].get<double>(), 0.4, 1e-3);
  EXPECT_TRUE(series.tank_treading_settled());   // what stops a run with [run] stop_when_settled
  const double bound = keller_skalak_bound(c.shear_rate_1_s, 0.4);   // from the window's DI, 0.4 within 1e-4
  EXPECT_NEAR(r["keller_skalak_bound_rad_s"].get<double>(), bound, 2e-4 * bound);
}

TEST(ShearResults, ATumblingCellDoesNotTankTread) {
  const PlateCellConfig c = read(shipped("shear/fischer-korzeniewski"), PlateFlow::shear);
  const double omega = 0.3 * c.shear_rate_1_s;
  PlateCellSeries series(c);
  for (int i = 0; i <= 3000; ++i) {   // the body and the marker turn together
    PlateCellSample s;
    s.time_s = 1e-4 * i;
    const double a = std::atan2(std::sin(-omega * s.time_s), std::cos(-omega * s.time_s));
    s.marker_phase_rad = a;
    s.inclination_rad = a > std::numbers::pi / 2 ? a - std::numbers::pi : (a <= -std::numbers::pi / 2 ? a + std::numbers::pi : a);
    series.add(s);
  }
  const nlohmann::json r = series.results();
  EXPECT_EQ(r["flow_mode"], "tumbling");
  EXPECT_FALSE(r["membrane_tank_treads"]);
  EXPECT_FALSE(r["tank_treading_settled"]);
  EXPECT_EQ(r["tank_treading_frequency_settled_hz"].get<double>(), 0.0);
  EXPECT_FALSE(series.tank_treading_settled());
}

TEST(ShearResults, TheCapsulesTaylorDeformationIsAveragedAndItsDriftReported) {
  // A capsule's D relaxing as 0.2 (1 - e^{-t/T}) over 8 T: the second half's mean is the integral's, and the last quarter
  // against the third is (q4 / q3 - 1), both in closed form; the packed series keeps D (checkpoint round trip).
  const PlateCellConfig c = read(shipped("shear/capsule"), PlateFlow::shear);
  PlateCellSeries series(c);
  const double t_relax = 0.01;
  const int n = 8000;
  for (int i = 0; i < n; ++i) {
    PlateCellSample s;
    s.time_s = 8.0 * t_relax * (i + 0.5) / n;   // midpoints: the sample means are the integrals' to O(1/n^2)
    s.taylor_deformation = 0.2 * (1.0 - std::exp(-s.time_s / t_relax));
    series.add(s);
  }
  const auto mean = [&](double a, double b) {   // mean of 0.2 (1 - e^{-t/T}) over [a T, b T]
    return 0.2 * (1.0 - (std::exp(-a) - std::exp(-b)) / (b - a));
  };
  const nlohmann::json r = series.results();
  EXPECT_NEAR(r["taylor_deformation_mean"].get<double>(), mean(4.0, 8.0), 1e-9);
  EXPECT_NEAR(r["taylor_deformation_last_quarter_change"].get<double>(), mean(6.0, 8.0) / mean(4.0, 6.0) - 1.0, 1e-9);
  PlateCellSeries restored(c);
  restored.unpack(series.pack());
  EXPECT_EQ(restored.samples().back().taylor_deformation, series.samples().back().taylor_deformation);
}

TEST(PlateCellConfig, StopWhenSettledIsReadForShearOnly) {
  EXPECT_TRUE(read(shipped("shear/fischer-korzeniewski"), PlateFlow::shear).stop_when_settled);
  EXPECT_FALSE(read(shipped("shear/membrane-viscosity"), PlateFlow::shear).stop_when_settled);   // absent: off
}

TEST(StokesAnalogue, TheSmallestPowerOfTwoBringsBothNumbersUnderTheirCaps) {
  // Re_p = gamma a^2 / nu and St = m gamma / (6 pi mu a) both fall as factor^2 at fixed Ca (gamma ~ 1 / factor).
  const double a = 4e-6;
  const double nu = 1e-6;
  const double rho = 1000.0;
  auto input = [&](double re_p, double stokes) {
    const double gamma = re_p * nu / (a * a);
    return StokesAnalogueInput{.kinematic_viscosity_m2_s = nu, .density_kg_m3 = rho, .shear_rate_1_s = gamma,
                               .cell_mass_kg = stokes * 6.0 * std::numbers::pi * rho * nu * a / gamma,
                               .cell_radius_m = a};
  };
  EXPECT_EQ(stokes_analogue_viscosity_factor(input(0.004, 0.04)), 1.0);
  EXPECT_EQ(stokes_analogue_viscosity_factor(input(0.016, 0.01)), 2.0);   // Re_p 0.016 / 4 = 0.004 <= 0.005
  EXPECT_EQ(stokes_analogue_viscosity_factor(input(0.001, 0.21)), 4.0);   // St 0.21 / 4 = 0.0525 > 0.05; / 16 = 0.013
  EXPECT_EQ(stokes_analogue_viscosity_factor(input(0.1, 0.01)), 8.0);     // Re_p 0.1 / 16 = 0.0063 > 0.005; / 64 = 0.0016
}

TEST(PlateCellConfig, TheStokesAnalogueRaisesEveryViscosityAndKeepsTheGroups) {
  const std::string base = shipped("shear/fischer-korzeniewski/medium-10.7");   // with stokes_analogue = true
  const PlateCellConfig plain = read(with(base, "stokes_analogue = true", "stokes_analogue = false"), PlateFlow::shear);
  const PlateCellConfig c = read(base, PlateFlow::shear);
  EXPECT_EQ(plain.analogue_viscosity_factor, 1.0);
  const double f = c.analogue_viscosity_factor;
  ASSERT_GT(f, 1.0);   // the shipped Ca 2.04 runs at St ~0.18 with the plasma's viscosity
  EXPECT_DOUBLE_EQ(c.kinematic_viscosity_m2_s, f * plain.kinematic_viscosity_m2_s);
  EXPECT_DOUBLE_EQ(c.shear_rate_1_s, plain.shear_rate_1_s / f);   // Ca = mu gamma a / G_s kept
  EXPECT_DOUBLE_EQ(c.numerics.viscosity_ratio, plain.numerics.viscosity_ratio);
  EXPECT_DOUBLE_EQ(c.membrane.material.viscosity_N_s_m, f * plain.membrane.material.viscosity_N_s_m);   // Bq kept
  EXPECT_DOUBLE_EQ(c.u_max_m_s, 0.5 * c.shear_rate_1_s * c.gap_m);
  EXPECT_DOUBLE_EQ(c.max_time_s, f * plain.max_time_s);   // the same number of Jeffery periods
  // The factor is the smallest power of two with Re_p <= 0.005 and St <= 0.05 (the cell's mass as npFEM lumps it).
  const double mass_kg = c.membrane.material.density_kg_m3 * c.numerics.membrane_mass_factor *
                         mesh_volume_m3(build_membrane_mesh(c.membrane));
  auto stokes = [&](const PlateCellConfig& k) {
    return mass_kg * k.shear_rate_1_s / (6.0 * std::numbers::pi * k.density_kg_m3 * k.kinematic_viscosity_m2_s * kCellRadius_m);
  };
  auto re_p = [](const PlateCellConfig& k) { return k.shear_rate_1_s * kCellRadius_m * kCellRadius_m / k.kinematic_viscosity_m2_s; };
  EXPECT_LE(stokes(c), kAnalogueMaxCellStokes);
  EXPECT_LE(re_p(c), kAnalogueMaxParticleReynolds);
  EXPECT_TRUE(4.0 * stokes(c) > kAnalogueMaxCellStokes || 4.0 * re_p(c) > kAnalogueMaxParticleReynolds);
}

TEST(PlateCellConfig, TheStokesAnalogueNeedsTheCapillaryNumberAndAGivenMassFactor) {
  const std::string analogue = shipped("shear/fischer-korzeniewski/medium-10.7");   // with stokes_analogue = true
  EXPECT_THROW(read(with(analogue, "membrane_mass_factor = 100", "#"), PlateFlow::shear), common::ConfigError);
  EXPECT_THROW(read(with(shipped("shear"), "[flow]\n", "[flow]\nstokes_analogue = true\n"), PlateFlow::shear),
               common::ConfigError);   // shear_rate_1_s: the analogue would change Ca
  EXPECT_THROW(read(with(shipped("migration"), "[flow]\n", "[flow]\nstokes_analogue = true\n"), PlateFlow::poiseuille),
               common::ConfigError);
}

/// The shipped migration case's checks on a synthetic centroid track y(t) / H (samples every 1 ms from the release,
/// the first after the spin-up); returns {failed, skipped}.
std::pair<int, int> migration_verdict(const std::vector<double>& y_over_h) {
  const PlateCellConfig c = read(shipped("migration"), PlateFlow::poiseuille);
  const double spin_up_s = static_cast<double>(c.spin_up_steps) * c.numerics.dt_s;
  std::vector<PlateCellSample> samples;
  for (std::size_t i = 0; i < y_over_h.size(); ++i) {
    PlateCellSample s;
    s.time_s = spin_up_s + 1e-3 * static_cast<double>(i);
    s.centroid_m = {0.0, y_over_h[i] * c.gap_m, 0.0};
    samples.push_back(s);
  }
  const auto checks = plate_cell_checks(c, nlohmann::json::object(), samples);
  return {checks.failed(), checks.skipped()};
}

TEST(MigrationCheck, PassesAMonotoneApproachAndFailsEveryOtherTrack) {
  // The shipped case releases the cell at y0 = 0.3 H; dx = 1 um, H = 24 um: the jitter allowance is 0.1 dx = 0.0042 H.
  const PlateCellConfig c = read(shipped("migration"), PlateFlow::poiseuille);
  ASSERT_NEAR(c.initial_height, 0.3, 1e-12);
  const double jitter = 0.1 * c.numerics.dx_m / c.gap_m;
  // Shi et al. 2014: a deformable cell moves to the centreline without turning back (the --quick run: 0.30 -> 0.42 H).
  EXPECT_EQ(migration_verdict({0.30, 0.33, 0.36, 0.39, 0.42}), std::make_pair(0, 0));
  // Jitter inside the allowance on the way is not a turn back.
  EXPECT_EQ(migration_verdict({0.30, 0.34, 0.34 - 0.5 * jitter, 0.38, 0.42}), std::make_pair(0, 0));
  // Negative controls, each must fail: a cell that does not migrate (its centroid moved by its shape only), one that
  // drifts to the wall, and one that turns back by more than the jitter before ending closer.
  EXPECT_EQ(migration_verdict({0.30, 0.30 + 0.5 * jitter, 0.30 + 0.8 * jitter}).first, 1);
  EXPECT_EQ(migration_verdict({0.30, 0.28, 0.26, 0.24}).first, 2);
  EXPECT_EQ(migration_verdict({0.30, 0.36, 0.36 - 3.0 * jitter, 0.40}).first, 1);
}

}  // namespace
}  // namespace hs::resolved
