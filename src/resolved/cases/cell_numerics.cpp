// SPDX-License-Identifier: MIT
// Strict reading of [numerics] of the single-RBC coupled cases and the choice of lattice units from the Mach limit.
#include "resolved/cases/cell_numerics.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace hs::resolved {
namespace {

/// Reference lattice velocity: compressibility errors grow as Ma^2; Palabos-npFEM keeps u_lb <= 0.04 (resolved-methods
/// 1.3, citing Krueger et al. 2017 table 7.2: 0.03-0.1). 0.04 is the default: at 0.05 the start-up transient at
/// tau ~ 15 overshoots U_max by ~15 % and trips the Mach watchdog (0.1).
constexpr double kLatticeVelocityDefault = 0.04;
constexpr double kLatticeVelocityMax = 0.1;
/// The membrane takes the fluid force explicitly (at x_n). Read 2 lu outside, that force acts like a drag
/// c ~ mu A / d on the vertex velocity, and the explicit update is stable only while h c / m stays small, i.e.
/// h nu_lu / m_lu is bounded: at tau = 12.5 (nu_lu = 4, k = 2) the 1125 kg/m^3 membrane diverged within 30
/// steps, 3x heavier after 280 steps, 5x was noisy, 10x stayed smooth (measured, docs/resolved-coupling.md). The
/// default factor is 1.25 nu_lu k (10 there). The cell's Stokes number stays < 0.01 (summary: cell_stokes_number).
constexpr double kMassFactorPerViscosityStep = 1.25;
/// Largest relaxation time: one RBC at r* = 0.2 in the campaign tube ran stably at tau = 30.5 (Re 0.2) and diverged
/// near the cell after ~540 steps at tau = 60.5 (Re 0.1, lattice velocity 0.04), measured; docs/resolved-coupling.md.
constexpr double kMaxTauDefault = 30.5;
/// Largest lattice Weissenberg number Wi = gamma_ref (tau - 1/2) dt: the lattice fluid's stress relaxes over
/// (tau - 1/2) dt, and against the flow's time 1 / gamma_ref that memory makes it measurably non-Newtonian. Measured
/// (docs/resolved-coupling.md, "The lattice fluid's memory"): a Ca = 1 cell released at y/H = 0.35 in the shear case
/// (TRT, 2-point kernel, ibm_reaction) moves toward the wall by 0.081 H in 30 ms at Wi 0.053 (tau 16.5), 0.019 at
/// 0.013 (tau 8.5), 0.005 at 0.0033 (tau 4.5): in proportion to Wi, while the centre is stable in Stokes flow. At 0.005
/// (tau 5.40, 3.3x the steps of 0.04) it moves 0.006 H (measured), and the centreline's growth rate scales to ~1.8 / s
/// (18.6 / s measured at 0.053). A smaller cap costs steps as 1 / sqrt(Wi).
constexpr double kMaxLatticeWeissenbergDefault = 0.005;

/// Half the thickness of the Evans-Fung biconcave disc at its thickest (2.6 um; resolved-methods.md 8.6).
constexpr double kCellHalfThickness_m = 1.3e-6;

}  // namespace

CellNumerics read_cell_numerics(hs::common::ConfigSection n) {
  if (n.has("tau")) n.fail("tau", "is derived from dx_m and lattice_velocity (tau = 1/2 + 3 nu dt / dx^2); remove it");
  if (n.has("time_step_s")) n.fail("time_step_s", "is derived (dt = lattice_velocity dx / U_ref); remove it");
  CellNumerics c;
  c.dx_m = n.positive("dx_m");
  c.lattice_velocity = n.number_in_or("lattice_velocity", 1e-4, kLatticeVelocityMax, kLatticeVelocityDefault);
  c.max_tau = n.number_in_or("max_tau", 0.51, 1000.0, kMaxTauDefault);
  c.max_lattice_weissenberg = n.number_in_or("max_lattice_weissenberg", 1e-4, 10.0, kMaxLatticeWeissenbergDefault);
  c.collision.model = collision_model_from_name(n.one_of_or("collision", {"trt", "bgk", "regularized"}, "trt"));
  c.collision.magic = n.greater_than_or("trt_magic", 0.0, trt_magic_default);
  // collision_params.hpp: above the bound the regularised collision's Lambda, and with it the IBM's slip, grows with tau.
  c.collision.odd_rate_max = n.number_in_or("odd_rate_max", regularized_from_odd_rate, 1.999, regularized_odd_rate_max_default);
  if (c.collision.model != CollisionModel::regularized && n.has("odd_rate_max")) {
    n.fail("odd_rate_max", "bounds the odd relaxation rate of collision = \"regularized\" only: remove it");
  }
  c.wall = n.one_of_or("wall", {"bouzidi", "half_way"}, "bouzidi") == "bouzidi" ? WallRule::bouzidi : WallRule::half_way;
  c.membrane_every = static_cast<int>(n.integer_in_or("membrane_every", 1, 100, 2));   // Palabos timestep_ShapeOp
  c.membrane_mass_factor = n.number_in_or("membrane_mass_factor", 1.0, 1.0e4, 0.0);
  c.ibm.kernel = delta_kernel_from_points(static_cast<int>(n.integer_in_or("ibm_kernel_points", 2, 4, 4)));
  c.ibm.iterations = static_cast<int>(n.integer_in_or("ibm_iterations", 1, 50, 1));   // Palabos inamuro_iT = 1
  // fluid_traction.hpp: why the whole-cell scaled membrane areas are the default.
  // The AA pattern saves the write-allocate third of the memory traffic (hemoscale bench lbm); results equal two_buffer
  // to round-off (tests/resolved/lbm/aa_pattern_test.cpp).
  c.streaming = n.one_of_or("streaming", {"two_buffer", "aa"}, "two_buffer") == "aa" ? Streaming::aa : Streaming::two_buffer;
  const std::string area = n.one_of_or("traction_area", {"scaled_membrane", "sampled_surface", "membrane"}, "scaled_membrane");
  c.traction_area = area == "membrane"          ? TractionArea::membrane
                    : area == "sampled_surface" ? TractionArea::sampled_surface
                                                : TractionArea::scaled_membrane;
  c.drive_on_enclosed_volume = n.boolean_or("drive_on_enclosed_volume", true);   // coupled_cell.hpp; off only to diagnose
  // coupled_cell.hpp MembraneForce; docs/resolved-coupling.md "Momentum-consistent coupling".
  const bool reaction = n.one_of_or("membrane_force", {"fluid_stress", "ibm_reaction"}, "fluid_stress") == "ibm_reaction";
  c.membrane_force = reaction ? MembraneForce::ibm_reaction : MembraneForce::fluid_stress;
  if (reaction && n.has("traction_area")) {
    n.fail("traction_area", "applies only to membrane_force = \"fluid_stress\" (the sampled stress); with "
                            "\"ibm_reaction\" the membrane takes minus the IBM force: remove it");
  }
  if (reaction && c.drive_on_enclosed_volume && n.has("drive_on_enclosed_volume")) {
    n.fail("drive_on_enclosed_volume", "would count the drive twice with membrane_force = \"ibm_reaction\" "
                                       "(the reaction already carries the drive on the fluid inside the cell): remove it");
  }
  if (reaction) c.drive_on_enclosed_volume = false;
  return c;
}

namespace {

/// The largest tau the case allows: max_tau, and with a reference shear rate also the Weissenberg bound. With
/// dt = (tau - 1/2) dx^2 / (3 nu), Wi = gamma (tau - 1/2)^2 dx^2 / (3 nu), so Wi <= Wi_max is tau - 1/2 <=
/// sqrt(3 nu Wi_max / (gamma dx^2)).
/// The Weissenberg bound is the outer flow's (the plasma's shear rate at the walls); max_tau bounds the largest tau in
/// the lattice, the cytoplasm's when the viscosity ratio exceeds 1.
double tau_cap(const CellNumerics& n, double kinematic_viscosity_m2_s, double reference_shear_rate_1_s) {
  const double max_tau = n.viscosity_ratio > 1.0 ? 0.5 + (n.max_tau - 0.5) / n.viscosity_ratio : n.max_tau;
  if (reference_shear_rate_1_s <= 0.0) return max_tau;
  const double wi_tau = 0.5 + std::sqrt(3.0 * kinematic_viscosity_m2_s * n.max_lattice_weissenberg /
                                        (reference_shear_rate_1_s * n.dx_m * n.dx_m));
  return std::min(max_tau, wi_tau);
}

}  // namespace

void derive_cell_numerics(CellNumerics& n, double kinematic_viscosity_m2_s, double reference_velocity_m_s,
                          hs::common::ConfigSection numerics, double reference_shear_rate_1_s) {
  if (reference_shear_rate_1_s <= 0.0 && numerics.has("max_lattice_weissenberg")) {
    numerics.fail("max_lattice_weissenberg", "applies to the plate cases (shear, migration) only, whose shear rate "
                                             "is the reference: remove it");
  }
  n.dt_s = n.lattice_velocity * n.dx_m / reference_velocity_m_s;
  n.collision.tau = 0.5 + 3.0 * kinematic_viscosity_m2_s * n.dt_s / (n.dx_m * n.dx_m);
  const double cap = tau_cap(n, kinematic_viscosity_m2_s, reference_shear_rate_1_s);
  if (n.collision.tau > cap) {   // slow flow: a smaller lattice velocity (more steps) keeps tau at the cap
    n.collision.tau = cap;
    n.dt_s = (cap - 0.5) * n.dx_m * n.dx_m / (3.0 * kinematic_viscosity_m2_s);
    n.lattice_velocity = reference_velocity_m_s * n.dt_s / n.dx_m;
  }
  if (reference_shear_rate_1_s > 0.0) {
    n.lattice_weissenberg = reference_shear_rate_1_s * (n.collision.tau - 0.5) * n.dt_s;
    numerics.derived("lattice_weissenberg", n.lattice_weissenberg);
  }
  double nu_lu = (n.collision.tau - 0.5) / 3.0;
  if (n.viscosity_ratio != 1.0) {
    n.inner_collision = n.collision;
    n.inner_collision.tau = 0.5 + n.viscosity_ratio * (n.collision.tau - 0.5);
    numerics.derived("tau_cytoplasm", n.inner_collision.tau);
    numerics.derived("lambda_cytoplasm", n.inner_collision.bulk_lambda());
    // The explicit membrane update feels the viscous drag of both sides; the stiffer one sets the mass (a guess, not
    // measured: the factor was calibrated at ratio 1).
    nu_lu = std::max(nu_lu, (n.inner_collision.tau - 0.5) / 3.0);
  }
  if (n.membrane_mass_factor == 0.0) {
    n.membrane_mass_factor = std::max(1.0, kMassFactorPerViscosityStep * nu_lu * static_cast<double>(n.membrane_every));
  }
  numerics.derived("time_step_s", n.dt_s);
  numerics.derived("tau", n.collision.tau);
  numerics.derived("lambda", n.collision.bulk_lambda());   // the IBM's slip follows it (collision_params.hpp)
  numerics.derived("lattice_velocity", n.lattice_velocity);          // lowered if tau hit its cap
  numerics.derived("membrane_mass_factor", n.membrane_mass_factor);  // 0 in the input means 1.25 nu_lu k
}

std::string kernel_width_warning(DeltaKernel kernel, double dx_m, CellShapeKind shape) {
  const double reach_m = 0.5 * support_points(kernel) * dx_m;
  if (reach_m <= kCellHalfThickness_m || shape == CellShapeKind::sphere) return {};
  return fmt::format("the {}-point IBM kernel reaches {:.2g} um from each vertex at dx = {:g} m, more than the cell's "
                     "half-thickness ({:.2g} um): past its membrane transient the cell can fold (docs/resolved-coupling.md, "
                     "\"The IBM kernel's width\"); the campaign's tube cases use ibm_kernel_points = 2 at dx = 1 um",
                     support_points(kernel), 1e6 * reach_m, dx_m, 1e6 * kCellHalfThickness_m);
}

}  // namespace hs::resolved
