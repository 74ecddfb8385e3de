// SPDX-License-Identifier: MIT
// One sphere pulled along the axis of the CFD-DEM tube through plasma at rest: the coupled drag against
// Haberman & Sayre (1958) at the same confinement d_p / D, and the sphere's own disturbance of the fluid
// velocity the closure is given in two-way coupling, without and with the exchange smoothed over a length l.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "closures/register_builtin.hpp"
#include "closures/stokes_drag.hpp"
#include "closures/wall_correction.hpp"
#include "common/errors.hpp"
#include "common/geometry/tube.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"
#include "unresolved/dem/particle_params.hpp"
#include "periodic_tube.hpp"

namespace {

using hs::common::Vec3;
using namespace hs::unresolved;
using hs::closures::WallCorrection;

constexpr double kRho = 1025.0;   // plasma, rbc_blood_properties.csv
constexpr double kNu = 1.2e-6;
constexpr int kSteps = 50;
constexpr int kAveraged = 20;     // the last 20 steps: the two-way run keeps a few-% step-to-step wobble

/// Haberman & Sayre 1958 (David Taylor Model Basin report 1143), eq. for a sphere on the axis of a long tube,
/// lambda = d / D: K = (1 - 0.75857 lambda^5) / (1 - 2.1050 lambda + 2.0865 lambda^3 - 1.7068 lambda^5 + 0.72603 lambda^6),
/// written out here from the paper (validation README), independent of closures/wall_correction.cpp.
double haberman_sayre_1958(double lambda) {
  const double num = 1.0 - 0.75857 * std::pow(lambda, 5);
  const double den = 1.0 - 2.1050 * lambda + 2.0865 * std::pow(lambda, 3) - 1.7068 * std::pow(lambda, 5) +
                     0.72603 * std::pow(lambda, 6);
  return num / den;
}

/// A deliberately wrong drag closure for the negative control: Stokes drag times `factor` (1.5: the issue's
/// perturbation), so a check that only compares the code with itself would still pass.
class ScaledStokesDrag final : public hs::closures::DragClosure {
 public:
  explicit ScaledStokesDrag(double factor) : DragClosure("stokes_scaled", stokes().validity()), factor_(factor) {}

 private:
  static const hs::closures::StokesDrag& stokes() {
    static const hs::closures::StokesDrag law;
    return law;
  }
  [[nodiscard]] double compute_drag_coefficient(const hs::closures::DragInputs& in) const override {
    return factor_ * stokes().drag_coefficient(in);
  }
  [[nodiscard]] double compute_correction(const hs::closures::DragInputs& in) const override {
    return factor_ * stokes().correction(in);
  }
  double factor_;
};

struct DragRun {
  double force_ratio;   // coupled drag beta_p (u_f - U) over -3 pi mu d_p U K_HS(d_p / D), mean of the last steps
  double fluid_ratio;   // u_f / U: the fluid velocity interpolated at the sphere centre over the sphere's velocity
  double velocity_m_s;  // the terminal velocity U reached
};

/// Tube of diameter D (10 cells across), periodic length 2 D, flow rate held at zero: the fluid is at rest far
/// from the sphere with no net flux through a cross-section, as in Haberman & Sayre's sphere moving in a long
/// closed tube. The sphere (RBC volume, d_p = 5.64 um, RBC density) starts on the axis at U0 and is pulled along
/// it by a constant force F = 3 pi mu d_p U0 K_HS (their falling ball, with the pull for U0): it moves at the
/// terminal velocity U where the drag the coupling computes, beta_p (u_f - U) with beta_p = 3 pi mu d_p K_HS
/// from the Stokes closure and u_f interpolated at its centre, balances F. Pressure-gradient and viscous forces
/// are off: they are separate terms of the split, the drag is what is compared. Re_p = d U / nu ~ 5e-4: Stokes
/// drag (Schiller-Naumann would add 0.08%). No d(eps)/dt source: without a smoothing model its marker-crossing
/// spikes make this single-sphere run oscillate (CouplingSettings::void_fraction_rate).
/// `closure_factor` != 1 replaces the Stokes closure by ScaledStokesDrag (negative control only).
DragRun drag_on_axis(double diameter_m, bool two_way, bool corrected = false, int cells_across = 10,
                     double closure_factor = 1.0, double smoothing_length_m = 0.0) {
  const double u0 = 1e-4;
  const double length = 2.0 * diameter_m;
  const double r = 0.5 * diameter_m;
  const hs::common::Tube tube = test::tube_along_z(diameter_m, length);
  const FvmGrid grid = test::periodic_tube_grid(tube, diameter_m, length, cells_across);
  // dt = 1e-5 s (1/20 of R^2 / nu at D = 30 um, above the particle relaxation time m / beta = 1.2 us, which the
  // DEM integrates exactly); 50 steps = 2.6 R^2 / nu at D = 30 um: the disturbance near the sphere (dx^2 / nu =
  // 7.5 us) is settled.
  const double dt = 1e-5;
  FvmSolver fluid = test::tube_plasma(grid, kRho, kNu, dt, 0.0);
  const ParticleParams params = default_particle_params();
  DemSystem dem({.params = params, .domain = {.box = {{-r, -r, 0.0}, {r, r, length}}, .periodic = {false, false, true}},
                 .time_step_s = dt / 100},   // 0.1 us < 0.1 x Rayleigh time 1.67 us of the default (stiff) spheres
                &tube);
  dem.add_particle({0.0, 0.0, 0.5 * length}, {0.0, 0.0, u0});
  const double mu = kRho * kNu;
  const double d = params.diameter_m;
  const double stokes_hs = 3.0 * std::numbers::pi * mu * d * haberman_sayre_1958(d / diameter_m);
  const double pull = stokes_hs * u0;
  dem.set_force_hook([pull](ParticleStore& p) { p.force_N()[2][0] += pull; });
  CouplingClosures closures;
  if (closure_factor == 1.0) {
    closures.drag = hs::closures::make_drag_closure({.model = "stokes", .file = {}});
  } else {
    closures.drag = std::make_unique<ScaledStokesDrag>(closure_factor);
  }
  CfdDemCoupling coupling(fluid, dem,
                          {.n_coupling = 100, .void_fraction_feedback = two_way, .two_way = two_way, .void_fraction_rate = false,
                           .pressure_force = false, .viscous_force = false, .axis = 2, .axis_point_m = {0, 0, 0},
                           .tube_radius_m = r, .wall_correction = WallCorrection::haberman_sayre,
                           .self_induced_correction = corrected, .smoothing_length_m = smoothing_length_m},
                          std::move(closures));
  const ParticleStore& p = dem.particles();
  DragRun mean{};
  for (int s = 0; s < kSteps; ++s) {
    coupling.step();
    if (s < kSteps - kAveraged) continue;
    // After step() the coupling has evaluated the closure for the next step: beta_p and u_f at the current state.
    const double u = p.velocity_m_s()[2][0];
    const double uf = p.fluid_velocity_m_s()[2][0];
    mean.force_ratio += p.drag_coefficient_N_s_m()[0] * (uf - u) / (-stokes_hs * u) / kAveraged;
    mean.fluid_ratio += uf / u / kAveraged;
    mean.velocity_m_s += u / kAveraged;
  }
  std::printf("D = %3.0f um, %2d cells, l = %.2f um, %s coupling: U = %.5e m/s (U0 = %.0e), drag / (3 pi mu d_p U K_HS) = %.5f, u_f / U = %.4f\n",
              diameter_m * 1e6, cells_across, smoothing_length_m * 1e6,
              two_way ? (corrected ? "two-way corrected" : "two-way") : "one-way", mean.velocity_m_s, u0,
              mean.force_ratio, mean.fluid_ratio);
  return mean;
}

/// The one-way check against Haberman & Sayre: drag / (3 pi mu d_p U K_HS) = 1 and the terminal velocity U0 = 1e-4 m/s,
/// both to 1e-9 (the DEM's relaxation exp(-t / 1.2 us) after 0.5 ms and round-off). Shared by the test and its
/// negative control so that the control fails exactly this band.
bool meets_haberman_sayre(const DragRun& run) {
  return run.fluid_ratio == 0.0 && std::abs(run.force_ratio - 1.0) <= 1e-9 &&
         std::abs(run.velocity_m_s - 1e-4) <= 1e-9 * 1e-4;
}

TEST(SphereInTube, DragLawWithWallCorrectionMatchesHabermanSayre) {
  // The unresolved drag law at the confinement of the tube: closure x K(d_p / D), evaluated by the coupling with the
  // interpolated fluid velocity, integrated by the DEM's exact drag step, in one-way coupling. The pull is the law's
  // 3 pi mu d_p U0 K_HS with K_HS from the formula above, so the sphere must settle at U0 and its drag must be the law.
  // In one-way coupling the fluid stays at rest (u_f = 0 exactly): what is tested is the closure and wall-factor chain
  // and the DEM's drag step, not the fluid (the two-way tests below). The remaining error is the DEM's relaxation,
  // exp(-t / 1.2 us) after 0.5 ms, and round-off: 1e-9. A constant of the code's K off in its fourth digit fails.
  for (const double d : {30e-6, 100e-6}) {
    const DragRun run = drag_on_axis(d, false);
    EXPECT_EQ(run.fluid_ratio, 0.0) << "D = " << d;
    EXPECT_NEAR(run.force_ratio, 1.0, 1e-9) << "D = " << d;
    EXPECT_NEAR(run.velocity_m_s, 1e-4, 1e-9 * 1e-4) << "D = " << d;   // terminal velocity F / (3 pi mu d_p K_HS)
    EXPECT_TRUE(meets_haberman_sayre(run)) << "D = " << d;
  }
}

TEST(SphereInTube, NegativeControlADragClosureTimesOneAndAHalfFailsTheCheck) {
  // Issue #30's negative control: the same one-way run with a drag closure 1.5x Stokes. The pull is still the law's,
  // so the sphere settles at U0 / 1.5 and the drag per unit velocity is 1.5x Haberman & Sayre's: the check above
  // must reject it (it is computed from the independently written K, not from the code's own wall factor).
  const DragRun run = drag_on_axis(30e-6, false, false, 10, 1.5);
  EXPECT_FALSE(meets_haberman_sayre(run));
  EXPECT_NEAR(run.force_ratio, 1.5, 1e-6);             // the closure's factor, seen by the comparison with the law
  EXPECT_NEAR(run.velocity_m_s, 1e-4 / 1.5, 1e-10);    // terminal velocity F / (1.5 x 3 pi mu d_p K_HS)
}

TEST(SphereInTube, TwoWayDragIsTheLawAtTheDisturbedVelocity) {
  // Without the self-induced correction the two-way drag is NOT the law: the sphere's own drag, given to the cells it
  // sits in (divided map, Ksl), drags the fluid there along, and the closure is evaluated with that disturbed u_f. The
  // drag is then the law times 1 - u_f / U exactly (the closure is linear in the slip at Re_p ~ 5e-4), and u_f / U is
  // not small: a point particle's self-induced velocity grows with d_p / dx (Horwitz & Mani 2016, J Comput Phys 318:85);
  // here d_p / dx = 1.88 at D = 30 um (the grid of `validate pries`) and 0.56 at D = 100 um, both with 10 cells across.
  // This test pins that relation and that the deficit exceeds the 3% drag-law band at both; the configuration that
  // meets the law in two-way coupling is the corrected one (next test), which refuses d_p > dx.
  const DragRun fine = drag_on_axis(30e-6, true);
  const DragRun coarse = drag_on_axis(100e-6, true);
  for (const DragRun* run : {&fine, &coarse}) {
    EXPECT_NEAR(run->force_ratio, 1.0 - run->fluid_ratio, 1e-6);   // the law, applied to the disturbed slip U - u_f
    EXPECT_GT(run->fluid_ratio, 0.03);                               // outside the drag-law band: not the law
    EXPECT_LT(run->fluid_ratio, 1.0);                                // the fluid is slower than the sphere
  }
  EXPECT_GT(fine.fluid_ratio, coarse.fluid_ratio);                   // more disturbance for the larger d_p / dx
}

TEST(SphereInTube, SelfInducedCorrectionRestoresTheDragLawInTwoWayCoupling) {
  // With the correction the closure gets u_f - M F, F the force the sphere gave the fluid in the last step and M the
  // grid's measured self-mobility: the sphere's own disturbance is taken out, so the two-way drag must match the
  // Haberman-Sayre law (formula above) again. Band 3%, issue 7's acceptance of the drag law; what is left is
  // M measured at one position in a cell (it varies up to +-30% with the sphere's position in the cell). D = 100 um,
  // 10 cells across: d_p / dx = 0.56 (at d_p / dx = 0.94, D = 30 um with 5 cells across, it over-corrects by 13%).
  const DragRun run = drag_on_axis(100e-6, true, true);
  EXPECT_NEAR(run.force_ratio, 1.0, 0.03);
  EXPECT_NEAR(run.velocity_m_s, 1e-4, 0.03 * 1e-4);
  EXPECT_LT(std::abs(run.fluid_ratio), 0.03);   // the estimate of the undisturbed velocity, 0 here
}

TEST(SphereInTube, SelfInducedCorrectionRefusesAGridFinerThanTheSphere) {
  // D = 30 um, 10 cells across: d_p / dx = 1.9, beta M = 1.2-4.6 with the sphere's own void fraction: the lagged
  // correction runs away with the fluid it drags (measured without the check: U = 60 U0 after 50 steps).
  EXPECT_THROW((void)drag_on_axis(30e-6, true, true), hs::common::ConfigError);
}

/// Upper bound on u_f / U for a sphere whose reaction is smoothed over l, from the continuum: the implicit diffusion
/// step q - l^2 lap q = source spreads a point force F with the kernel exp(-r / l) / (4 pi l^2 r), whose Stokes flow
/// in unbounded fluid has u(0) = F / (6 pi mu l) at its centre (the Oseen tensor's angular mean 4/3 over 8 pi mu r,
/// integrated against the kernel). With F = 3 pi mu d_p K_HS (U - u_f): u_f / U = a / (1 + a), a = K_HS d_p / (2 l).
/// The tube's wall and its zero net flux only hold the fluid back, so the coupled value must lie below it.
double unbounded_smoothed_self_disturbance(double d_p, double diameter_m, double l) {
  const double a = haberman_sayre_1958(d_p / diameter_m) * d_p / (2.0 * l);
  return a / (1.0 + a);
}

TEST(SphereInTube, SmoothingOverTheSphereSizeLowersTheSelfDisturbanceButDoesNotRemoveIt) {
  // D = 30 um, 10 cells across: d_p / dx = 1.88, the grid of `validate pries`, where the unsmoothed two-way drag is
  // 0.29 of the law (test above). Smoothing the exchange over l = d_p / 2 and d_p spreads the sphere's reaction
  // over a physical length, so the fluid it drags at its centre is slower (measured u_f / U = 0.71 / 0.34 / 0.16 for
  // l = 0 / d_p / 2 / d_p; 0.44 / 0.21 at 15 cells and 0.41 / 0.19 at 20, where l = 0 runs away: docs/closures.md).
  const double d = default_particle_params().diameter_m;
  const double diameter = 30e-6;
  const DragRun none = drag_on_axis(diameter, true);
  const DragRun half = drag_on_axis(diameter, true, false, 10, 1.0, 0.5 * d);
  const DragRun full = drag_on_axis(diameter, true, false, 10, 1.0, d);
  for (const DragRun* run : {&half, &full}) {
    // Still the law at the disturbed slip (Stokes closure, linear at Re_p ~ 5e-4): exact up to round-off.
    EXPECT_NEAR(run->force_ratio, 1.0 - run->fluid_ratio, 1e-6);
    // The pulled state: the drag balances the pull, U (1 - u_f / U) = U0. The mean of the product and the product of
    // the means of the last 20 steps differ by the covariance of their few-% step-to-step wobble: 1e-3.
    EXPECT_NEAR(run->velocity_m_s * run->force_ratio, 1e-4, 1e-3 * 1e-4);
  }
  // Smoothing lowers the self-disturbance, more for the longer length, and stays below the continuum bound.
  EXPECT_LT(half.fluid_ratio, none.fluid_ratio);
  EXPECT_LT(full.fluid_ratio, half.fluid_ratio);
  EXPECT_GT(full.fluid_ratio, 0.0);
  EXPECT_LT(half.fluid_ratio, unbounded_smoothed_self_disturbance(d, diameter, 0.5 * d));   // 0.62
  EXPECT_LT(full.fluid_ratio, unbounded_smoothed_self_disturbance(d, diameter, d));         // 0.45
  // ...but it does not restore the drag law: at l = d_p the drag is still outside issue 7's 3% drag-law band (the
  // discretisation's spread over 10-20 cells is 0.16-0.21, far from 0.03). The law needs the undisturbed velocity.
  EXPECT_GT(full.fluid_ratio, 0.03);
}

TEST(SphereInTube, SmoothedSelfInducedCorrectionRestoresTheDragLawOnCoarseAndFineGrids) {
  // With the exchange smoothed over l = d_p, M is measured with the same smoothing and the corrected two-way drag is
  // the Haberman-Sayre law again on grids where the unsmoothed correction is refused (d_p / dx 1.88 and 2.82; without
  // the correction 0.840 and 0.794 of the law, test above and docs/closures.md). Band 3%: issue 7's drag-law band, as
  // for the point-particle correction above. Measured: 0.992 at 10 cells, 0.984 at 15, 0.998 at 20 (and at l = d_p / 2:
  // 0.970, 0.937, 0.973: the +-30% variation of M with the sphere's place in a cell is not yet smoothed away there).
  const double d = default_particle_params().diameter_m;
  for (const int cells : {10, 15}) {
    const DragRun run = drag_on_axis(30e-6, true, true, cells, 1.0, d);
    EXPECT_NEAR(run.force_ratio, 1.0, 0.03) << cells << " cells across";
    EXPECT_NEAR(run.velocity_m_s, 1e-4, 0.03 * 1e-4) << cells << " cells across";
    EXPECT_LT(std::abs(run.fluid_ratio), 0.03) << cells << " cells across";   // the undisturbed estimate: 0 here
  }
}

TEST(SphereInTube, SmoothedSelfInducedCorrectionRefusesALengthTooShortForTheSphere) {
  // l = d_p / 8 (0.7 um, a quarter of a cell at 10 cells across) barely spreads the force: beta M is about the
  // unsmoothed 1.2-4.6, where the lagged correction runs away; the coupling refuses it (beta M >= 1).
  const double d = default_particle_params().diameter_m;
  EXPECT_THROW((void)drag_on_axis(30e-6, true, true, 10, 1.0, d / 8.0), hs::common::ConfigError);
}

TEST(SphereInTube, SmoothingKeepsTheSelfDisturbanceBoundedOnAFinerGrid) {
  // D = 30 um, 15 cells across (d_p / dx = 2.8): without smoothing the sphere and the fluid it drags run away together
  // (measured U = -23 U0, u_f / U = 0.99 after 50 steps); with l = d_p the sphere's footprint is the physical length,
  // not the cell, and u_f / U stays below the continuum bound (measured 0.21, 0.16 at 10 cells).
  const double d = default_particle_params().diameter_m;
  const DragRun full = drag_on_axis(30e-6, true, false, 15, 1.0, d);
  EXPECT_NEAR(full.force_ratio, 1.0 - full.fluid_ratio, 1e-6);
  EXPECT_NEAR(full.velocity_m_s * full.force_ratio, 1e-4, 1e-3 * 1e-4);
  EXPECT_GT(full.fluid_ratio, 0.0);
  EXPECT_LT(full.fluid_ratio, unbounded_smoothed_self_disturbance(d, 30e-6, d));
}

}  // namespace

namespace {

TEST(SphereInTube, SmoothedVoidFractionKeepsTheWholeSphereOnAFineGrid) {
  // 20 cells across D = 30 um (dx 1.5 um, a cell 3.4 um^3; a marker carries 94.1 / 29 = 3.2 um^3): where markers crowd
  // a cell its raw solid fraction passes 1 - eps_min, and clipping before smoothing dropped that volume (11 % of the
  // cells' volume in the 15-across Pries tube). Smoothed first, then clipped, the sphere keeps its whole volume: sum
  // V_c (1 - eps_c) = V_p to the smoothing's residual 1e-13. Without smoothing the clipping still drops some (control).
  const double diameter = 30e-6;
  const hs::common::Tube tube = test::tube_along_z(diameter, 2.0 * diameter);
  const FvmGrid grid = test::periodic_tube_grid(tube, diameter, 2.0 * diameter, 20);
  const double r = 0.5 * diameter;
  for (const double l : {0.0, default_particle_params().diameter_m}) {
    FvmSolver fluid = test::tube_plasma(grid, kRho, kNu, 1e-5, 0.0);
    DemSystem dem({.params = default_particle_params(),
                   .domain = {.box = {{-r, -r, 0.0}, {r, r, 2.0 * diameter}}, .periodic = {false, false, true}},
                   .time_step_s = 1e-7},
                  &tube);
    dem.add_particle({0.3e-6, -0.2e-6, 0.77 * diameter}, {});
    CouplingClosures closures;
    closures.drag = hs::closures::make_drag_closure({.model = "stokes", .file = {}});
    CfdDemCoupling coupling(fluid, dem, {.n_coupling = 100, .void_fraction_rate = false, .tube_radius_m = r, .smoothing_length_m = l},
                            std::move(closures));
    coupling.step();
    double solid = 0.0;
    const auto& n = grid.cells();
    for (int k = 0; k < n[2]; ++k) {
      for (int j = 0; j < n[1]; ++j) {
        for (int i = 0; i < n[0]; ++i) {
          const std::size_t c = fluid.void_fraction().index(i, j, k);
          solid += (1.0 - fluid.void_fraction()[c]) * grid.fluid_fractions()[c] * std::pow(grid.dx_m(), 3);
        }
      }
    }
    const double vp = std::numbers::pi / 6.0 * std::pow(default_particle_params().diameter_m, 3);
    std::printf("l = %.2f um: solid volume on the grid %.6e m^3 (V_p %.6e), dropped %.3e\n", l * 1e6, solid, vp,
                coupling.exchange().lost_solid_volume_m3);
    if (l > 0.0) {
      EXPECT_EQ(coupling.exchange().lost_solid_volume_m3, 0.0);
      EXPECT_NEAR(solid, vp, 1e-12 * vp);
    } else {
      EXPECT_GT(coupling.exchange().lost_solid_volume_m3, 0.01 * vp);   // the control: the unsmoothed clip drops volume
    }
  }
}

}  // namespace
