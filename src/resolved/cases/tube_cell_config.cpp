// SPDX-License-Identifier: MIT
// Strict reading of the tube-cell case file and the choice of lattice units from the Mach limit.
#include "resolved/cases/tube_cell_config.hpp"
#include "common/dimensionless_groups.hpp"
#include "common/fluid_properties.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

namespace hs::resolved {
namespace {

/// Peak lattice velocity: compressibility errors grow as Ma^2; Palabos-npFEM keeps u_lb <= 0.04 (resolved-methods
/// 1.3, citing Krueger et al. 2017 table 7.2: 0.03-0.1). 0.04 is the default: at 0.05 the start-up transient at
/// tau ~ 15 overshoots U_max by ~15 % and trips the Mach watchdog (0.1).
constexpr double kLatticeVelocityDefault = 0.04;
constexpr double kLatticeVelocityMax = 0.1;
constexpr long kQuickSamples = 40;
/// The membrane takes the fluid force explicitly (at x_n). Read 2 lu outside, that force acts like a drag
/// c ~ mu A / d on the vertex velocity, and the explicit update is stable only while h c / m stays small, i.e.
/// h nu_lu / m_lu is bounded: at tau = 12.5 (nu_lu = 4, k = 2) the 1125 kg/m^3 membrane diverged within 30
/// steps, 3x heavier after 280 steps, 5x was noisy, 10x stayed smooth (measured, docs/resolved-coupling.md). The
/// default factor is 1.25 nu_lu k (10 there). The cell's Stokes number stays < 0.01 (summary: cell_stokes_number).
constexpr double kMassFactorPerViscosityStep = 1.25;
/// Largest relaxation time: one RBC at r* = 0.2 in the campaign tube ran stably at tau = 30.5 (Re 0.2) and diverged
/// near the cell after ~540 steps at tau = 60.5 (Re 0.1, lattice velocity 0.04), measured; docs/resolved-coupling.md.
constexpr double kMaxTauDefault = 30.5;
/// Spin-up: the longer of R^2 / nu and 10 tau steps (the lattice stress relaxes over ~tau steps).
constexpr double kSpinUpTaus = 10.0;

void read_numerics(hs::common::ConfigSection n, TubeCellConfig& c) {
  if (n.has("tau")) n.fail("tau", "is derived from dx_m and lattice_velocity (tau = 1/2 + 3 nu dt / dx^2); remove it");
  if (n.has("time_step_s")) n.fail("time_step_s", "is derived (dt = lattice_velocity dx / U_max); remove it");
  c.dx_m = n.positive("dx_m");
  c.lattice_velocity = n.number_in_or("lattice_velocity", 1e-4, kLatticeVelocityMax, kLatticeVelocityDefault);
  c.max_tau = n.number_in_or("max_tau", 0.51, 1000.0, kMaxTauDefault);
  c.collision.model = n.one_of_or("collision", {"trt", "bgk"}, "trt") == "trt" ? CollisionModel::trt : CollisionModel::bgk;
  c.collision.magic = n.greater_than_or("trt_magic", 0.0, trt_magic_default);
  c.wall = n.one_of_or("wall", {"bouzidi", "half_way"}, "bouzidi") == "bouzidi" ? WallRule::bouzidi : WallRule::half_way;
  c.membrane_every = static_cast<int>(n.integer_in_or("membrane_every", 1, 100, 2));   // Palabos timestep_ShapeOp
  c.membrane_mass_factor = n.number_in_or("membrane_mass_factor", 1.0, 1.0e4, 0.0);
  c.ibm.kernel = delta_kernel_from_points(static_cast<int>(n.integer_in_or("ibm_kernel_points", 2, 4, 4)));
  c.ibm.iterations = static_cast<int>(n.integer_in_or("ibm_iterations", 1, 50, 1));   // Palabos inamuro_iT = 1
  c.traction_area = n.one_of_or("traction_area", {"sampled_surface", "membrane"}, "sampled_surface") == "membrane"
                        ? TractionArea::membrane
                        : TractionArea::sampled_surface;   // fluid_traction.hpp: why the sampled surface
}

void read_run(hs::common::ConfigSection r, hs::common::ConfigSection o, TubeCellConfig& c) {
  r.forbid_together("max_time_s", "max_jeffery_periods", "give the cap either in seconds or in Jeffery periods");
  if (r.has("max_jeffery_periods")) {
    c.max_jeffery_periods = r.positive("max_jeffery_periods");
  } else {
    c.max_time_s = r.positive("max_time_s");
  }
  c.sample_every_s = r.positive("sample_every_s");
  c.settle_periods = static_cast<int>(r.integer_in_or("settle_periods", 3, 100, 3));   // seed paper: >= 3 periods
  c.settle_spread = r.number_in_or("settle_spread", 1e-6, 1.0, 0.02);
  c.checkpoint_every_wall_s = r.positive_or("checkpoint_every_wall_s", 600.0);
  c.vtk_every_s = o.non_negative_or("vtk_every_s", 0.0);
}

}  // namespace

double jeffery_period_s(const TubeCellConfig& c) {
  const double gamma = common::poiseuille_shear_rate(c.u_max_m_s, c.radial_position * c.radius_m, c.radius_m);
  return gamma > 0.0 ? 2.0 * std::numbers::pi * (0.37 + 1.0 / 0.37) / gamma : std::numeric_limits<double>::infinity();
}

TubeCellConfig read_tube_cell(hs::common::ConfigFile& file, bool quick) {
  TubeCellConfig c{};
  auto root = file.root();
  auto geometry = root.section("geometry");
  c.radius_m = geometry.positive("radius_m");
  c.length_m = geometry.positive("length_m");
  const common::FluidProperties fluid = common::parse_fluid(root.section("fluid"));
  c.density_kg_m3 = fluid.density_kg_m3;
  c.kinematic_viscosity_m2_s = fluid.kinematic_viscosity_m2_s;
  auto flow = root.section("flow");
  c.reynolds = flow.positive("reynolds");
  auto cell = root.section("cell");
  c.setup = cell.one_of("setup", {"drag", "lift"}) == "drag" ? TubeCellSetup::drag : TubeCellSetup::lift;
  c.radial_position = cell.number_in("radial_position", 0.0, 0.9);
  auto membrane = root.section_or_empty("membrane");
  c.membrane = parse_membrane_config(membrane);
  read_numerics(root.section("numerics"), c);
  read_run(root.section("run"), root.section_or_empty("output"), c);
  file.finish();
  c.u_max_m_s = c.reynolds * c.kinematic_viscosity_m2_s / (2.0 * c.radius_m);
  c.dt_s = c.lattice_velocity * c.dx_m / c.u_max_m_s;
  c.collision.tau = 0.5 + 3.0 * c.kinematic_viscosity_m2_s * c.dt_s / (c.dx_m * c.dx_m);
  if (c.collision.tau > c.max_tau) {   // low Re: a smaller lattice velocity (more steps) keeps tau at max_tau
    c.collision.tau = c.max_tau;
    c.dt_s = (c.max_tau - 0.5) * c.dx_m * c.dx_m / (3.0 * c.kinematic_viscosity_m2_s);
    c.lattice_velocity = c.u_max_m_s * c.dt_s / c.dx_m;
  }
  // Samples (and checkpoints) fall on membrane-step boundaries, where the coupling state is just positions/velocities.
  const long k = c.membrane_every;
  if (c.max_jeffery_periods > 0.0) {
    if (c.radial_position == 0.0) {
      root.section("run").fail("max_jeffery_periods", "has no meaning on the axis (no shear, no tumbling); give max_time_s");
    }
    c.max_time_s = c.max_jeffery_periods * jeffery_period_s(c);
  }
  const double nu_lu = (c.collision.tau - 0.5) / 3.0;
  if (c.membrane_mass_factor == 0.0) c.membrane_mass_factor = std::max(1.0, kMassFactorPerViscosityStep * nu_lu * static_cast<double>(k));
  c.spin_up_steps = std::max(std::lround(c.radius_m * c.radius_m / c.kinematic_viscosity_m2_s / c.dt_s),
                             std::lround(kSpinUpTaus * c.collision.tau));
  c.sample_every_steps = std::max(k, k * std::lround(c.sample_every_s / (c.dt_s * static_cast<double>(k))));
  c.sample_every_s = static_cast<double>(c.sample_every_steps) * c.dt_s;
  if (quick) c.max_time_s = std::min(c.max_time_s, static_cast<double>(kQuickSamples * c.sample_every_steps) * c.dt_s);
  auto numerics = root.section("numerics");
  numerics.derived("time_step_s", c.dt_s);
  numerics.derived("tau", c.collision.tau);
  flow.derived("u_max_m_s", c.u_max_m_s);
  if (c.length_m < 10.0 * c.dx_m) geometry.fail("length_m", fmt::format("must span at least 10 dx_m = {:g} m", 10.0 * c.dx_m));
  return c;
}

}  // namespace hs::resolved
