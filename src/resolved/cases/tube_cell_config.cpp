// SPDX-License-Identifier: MIT
// Strict reading of the tube-cell case file and the choice of lattice units from the Mach limit.
#include "resolved/cases/tube_cell_config.hpp"
#include "common/fluid_properties.hpp"

#include <cmath>

#include <fmt/format.h>

namespace hs::resolved {
namespace {

/// Peak lattice velocity: compressibility errors grow as Ma^2; Palabos-npFEM keeps u_lb <= 0.04 (resolved-methods
/// 1.3, citing Krueger et al. 2017 table 7.2: 0.03-0.1). 0.04 is the default: at 0.05 the start-up transient at
/// tau ~ 15 overshoots U_max by ~15 % and trips the Mach watchdog (0.1).
constexpr double kLatticeVelocityDefault = 0.04;
constexpr double kLatticeVelocityMax = 0.1;
constexpr long kQuickSamples = 40;

void read_numerics(hs::common::ConfigSection n, TubeCellConfig& c) {
  if (n.has("tau")) n.fail("tau", "is derived from dx_m and lattice_velocity (tau = 1/2 + 3 nu dt / dx^2); remove it");
  if (n.has("time_step_s")) n.fail("time_step_s", "is derived (dt = lattice_velocity dx / U_max); remove it");
  c.dx_m = n.positive("dx_m");
  c.lattice_velocity = n.number_in_or("lattice_velocity", 1e-4, kLatticeVelocityMax, kLatticeVelocityDefault);
  c.collision.model = n.one_of_or("collision", {"trt", "bgk"}, "trt") == "trt" ? CollisionModel::trt : CollisionModel::bgk;
  c.collision.magic = n.greater_than_or("trt_magic", 0.0, trt_magic_default);
  c.wall = n.one_of_or("wall", {"bouzidi", "half_way"}, "bouzidi") == "bouzidi" ? WallRule::bouzidi : WallRule::half_way;
  c.membrane_every = static_cast<int>(n.integer_in_or("membrane_every", 1, 100, 2));   // Palabos timestep_ShapeOp
  c.ibm.kernel = delta_kernel_from_points(static_cast<int>(n.integer_in_or("ibm_kernel_points", 2, 4, 4)));
  c.ibm.iterations = static_cast<int>(n.integer_in_or("ibm_iterations", 1, 50, 1));   // Palabos inamuro_iT = 1
}

void read_run(hs::common::ConfigSection r, hs::common::ConfigSection o, TubeCellConfig& c) {
  c.max_time_s = r.positive("max_time_s");
  c.sample_every_s = r.positive("sample_every_s");
  c.settle_periods = static_cast<int>(r.integer_in_or("settle_periods", 3, 100, 3));   // seed paper: >= 3 periods
  c.settle_spread = r.number_in_or("settle_spread", 1e-6, 1.0, 0.02);
  c.checkpoint_every_wall_s = r.positive_or("checkpoint_every_wall_s", 600.0);
  c.vtk_every_s = o.non_negative_or("vtk_every_s", 0.0);
}

}  // namespace

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
  // Samples (and checkpoints) fall on membrane-step boundaries, where the coupling state is just positions/velocities.
  const long k = c.membrane_every;
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
