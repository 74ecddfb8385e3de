// SPDX-License-Identifier: MIT
// Strict reading of the tube-cell case file and the choice of lattice units from the Mach limit.
#include "resolved/cases/tube_cell_config.hpp"

#include "resolved/cases/cytoplasm_viscosity.hpp"
#include "resolved/cases/cell_numerics.hpp"
#include "common/dimensionless_groups.hpp"
#include "common/fluid_properties.hpp"
#include "resolved/measure/flow_mode.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

namespace hs::resolved {
namespace {

constexpr long kQuickSamples = 40;
/// Spin-up: the longer of 4 R^2 / nu and 10 tau steps (the lattice stress relaxes over ~tau steps). One R^2 / nu was
/// enough with the 4-point kernel; with the 2-point one the end of that ramp pushed a node next to a free cell to
/// lattice Mach 0.10 (the watchdog's limit; tau 12.5, a cell at r* 0.5 and a stiff one on the axis; measured, and a
/// transient: with the watchdog off the stiff cell reached 0.99 U_max smoothly). 4 R^2 / nu (2.5 ms) starts both.
constexpr double kSpinUpViscousTimes = 4.0;
constexpr double kSpinUpTaus = 10.0;

void apply_numerics(const CellNumerics& n, TubeCellConfig& c) {
  c.dx_m = n.dx_m;
  c.lattice_velocity = n.lattice_velocity;
  c.max_tau = n.max_tau;
  c.collision = n.collision;
  c.viscosity_ratio = n.viscosity_ratio;
  c.inner_collision = n.inner_collision;
  c.wall = n.wall;
  c.membrane_every = n.membrane_every;
  c.membrane_mass_factor = n.membrane_mass_factor;
  c.ibm = n.ibm;
  c.traction_area = n.traction_area;
  c.drive_on_enclosed_volume = n.drive_on_enclosed_volume;
  c.membrane_force = n.membrane_force;
  c.streaming = n.streaming;
  c.dt_s = n.dt_s;
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
  c.lift_settle_spread = r.number_in_or("lift_settle_spread", 1e-6, 1.0, 0.1);
  c.checkpoint_every_wall_s = r.positive_or("checkpoint_every_wall_s", 600.0);
  c.vtk_every_s = o.non_negative_or("vtk_every_s", 0.0);
}

long spin_up_steps_of(const TubeCellConfig& c) {
  return std::max(std::lround(kSpinUpViscousTimes * c.radius_m * c.radius_m / c.kinematic_viscosity_m2_s / c.dt_s),
                  std::lround(kSpinUpTaus * c.collision.tau));
}

}  // namespace

TubeCellConfig half_time_step_stage(const TubeCellConfig& c) {
  TubeCellConfig h = c;
  h.dt_s = 0.5 * c.dt_s;
  h.lattice_velocity = 0.5 * c.lattice_velocity;
  h.collision.tau = 0.5 + 0.5 * (c.collision.tau - 0.5);               // nu = c_s^2 (tau - 1/2) dx^2 / dt kept
  h.inner_collision.tau = 0.5 + 0.5 * (c.inner_collision.tau - 0.5);
  h.max_tau = std::max(h.collision.tau, h.viscosity_ratio != 1.0 ? h.inner_collision.tau : 0.0);
  h.spin_up_steps = spin_up_steps_of(h);
  h.sample_every_steps = 2 * c.sample_every_steps;                      // the same sampling in seconds
  h.transient_s = kHalfTimeStepStageSpinUps * static_cast<double>(h.spin_up_steps) * h.dt_s;
  // A run capped inside its transient (--quick) keeps its cap; otherwise as long after the start-up as the first stage.
  h.max_time_s = c.max_time_s <= c.transient_s ? c.max_time_s : h.transient_s + (c.max_time_s - c.transient_s);
  h.extrapolate_lattice_memory = false;
  return h;
}

double extrapolated_to_zero_weissenberg(double value_1, double wi_1, double value_2, double wi_2) {
  return value_2 - (value_1 - value_2) * wi_2 / (wi_1 - wi_2);
}

double jeffery_period_s(const TubeCellConfig& c) {
  const double gamma = common::poiseuille_shear_rate(c.u_max_m_s, c.radial_position * c.radius_m, c.radius_m);
  return gamma > 0.0 ? jeffery_period(gamma) : std::numeric_limits<double>::infinity();
}

double membrane_relaxation_time_s(const TubeCellConfig& c) {
  const double a = 0.5 * kCellDiameterD0_m;   // as in Ca
  return shape_relaxation_time_s(c.membrane.material, a);
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
  c.disc_tilt_rad = cell.number_in_or("disc_tilt_deg", 0.0, 90.0, 0.0) * std::numbers::pi / 180.0;
  const double viscosity_ratio = read_cytoplasm_viscosity_ratio(cell, c.density_kg_m3 * c.kinematic_viscosity_m2_s);
  auto membrane = root.section_or_empty("membrane");
  c.membrane = parse_membrane_config(membrane);
  CellNumerics numerics = read_cell_numerics(root.section("numerics"));
  numerics.viscosity_ratio = viscosity_ratio;
  c.extrapolate_lattice_memory = root.section("numerics").boolean_or("extrapolate_lattice_memory", false);
  read_run(root.section("run"), root.section_or_empty("output"), c);
  file.finish();
  c.u_max_m_s = c.reynolds * c.kinematic_viscosity_m2_s / (2.0 * c.radius_m);
  derive_cell_numerics(numerics, c.kinematic_viscosity_m2_s, c.u_max_m_s, root.section("numerics"));
  check_cytoplasm_relaxation(cell, numerics);
  apply_numerics(numerics, c);
  // Samples (and checkpoints) fall on membrane-step boundaries, where the coupling state is just positions/velocities.
  const long k = c.membrane_every;
  if (c.max_jeffery_periods > 0.0) {
    if (c.radial_position == 0.0) {
      root.section("run").fail("max_jeffery_periods", "has no meaning on the axis (no shear, no tumbling); give max_time_s");
    }
    c.max_time_s = kMembraneTransientTimes * membrane_relaxation_time_s(c) + c.max_jeffery_periods * jeffery_period_s(c);
  }
  c.spin_up_steps = spin_up_steps_of(c);
  c.transient_s = kMembraneTransientTimes * membrane_relaxation_time_s(c);
  c.sample_every_steps = std::max(k, k * std::lround(c.sample_every_s / (c.dt_s * static_cast<double>(k))));
  c.sample_every_s = static_cast<double>(c.sample_every_steps) * c.dt_s;
  if (quick) c.max_time_s = std::min(c.max_time_s, static_cast<double>(kQuickSamples * c.sample_every_steps) * c.dt_s);
  flow.derived("u_max_m_s", c.u_max_m_s);
  if (c.length_m < 10.0 * c.dx_m) geometry.fail("length_m", fmt::format("must span at least 10 dx_m = {:g} m", 10.0 * c.dx_m));
  return c;
}

}  // namespace hs::resolved
