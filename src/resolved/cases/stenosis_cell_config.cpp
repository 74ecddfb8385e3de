// SPDX-License-Identifier: MIT
// Strict reading of the stenosis case file and its derived lattice values.
#include "resolved/cases/stenosis_cell_config.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

#include <fmt/format.h>

#include "common/fluid_properties.hpp"

namespace hs::resolved {
namespace {

constexpr long kQuickSamples = 40;
/// Spin-up of the drive: the longer of H^2 / nu and 10 tau steps (the lattice stress relaxes over ~tau steps).
constexpr double kSpinUpTaus = 10.0;
/// Clearance (in dx) between the released cell and a wall: the 4-point IBM stencil reaches 2 dx, the stress is
/// sampled up to 2 dx outside the membrane (resolved-methods.md 1.4).
constexpr double kWallClearanceDx = 2.0;
/// Membrane-wall repulsion (wall_repulsion.hpp). Without it the cell crosses the walls of the 5.5 um throat at
/// dx = 1 um (measured: a vertex 1.4 um inside the wall, the cell passing undeformed, D_y 0.98), because the membrane
/// moves with the fluid traction it samples 1-2 dx outside itself, and the squeezed film is not resolved. Range 0.5 um:
/// half a lattice spacing, under the 1.5 um gap each side of a 2.5 um thick cell in the 5.5 um throat. Stiffness
/// 2e-5 N/m: 5 pN at 0.25 um inside the range, the force that holds the stuck cell against the whole periodic drive
/// (rho g L x cell section ~ 50 pN over ~10-50 contact vertices); k_w h^2 / m_vertex = 0.3 at dx = 1 um and 0.1 at
/// 0.75 um (the case refuses > 1: the spring is explicit).
constexpr double kWallRepulsionRange_m = 0.5e-6;
constexpr double kWallRepulsionStiffness_N_m = 2.0e-5;
/// How far from a whole number of dx a box extent may be (relative to dx): round-off of decimal inputs only.
constexpr double kWholeNodesTolerance = 1e-6;
/// Fewest nodes across the throat: below 4 the throat flow is a staircase of 1-2 fluid nodes.
constexpr double kThroatNodesMin = 4.0;

void read_geometry(hs::common::ConfigSection g, StenosisCellConfig& c) {
  c.height_m = g.positive("height_m");
  c.throat_height_m = g.positive("throat_height_m");
  c.constriction_length_m = g.positive("constriction_length_m");
  c.throat_x_m = g.positive("throat_x_m");
  c.length_m = g.positive("length_m");
  c.width_m = g.positive("width_m");
  if (c.throat_height_m >= c.height_m) {
    g.fail("throat_height_m", fmt::format("= {:g} m must be < height_m = {:g} m", c.throat_height_m, c.height_m));
  }
}

void read_cell(hs::common::ConfigSection cell, StenosisCellConfig& c) {
  c.release_x_m = cell.number_in("release_x_m", -1.0, 1.0);
  c.initial_height = cell.number_in_or("initial_height", 0.05, 0.95, 0.5);
  const std::string axis = cell.one_of_or("disc_axis", {"x", "y", "z"}, "z");
  c.disc_axis = axis == "x" ? 0 : (axis == "y" ? 1 : 2);
  c.stop_x_m = cell.number_in("stop_x_m", -1.0, 1.0);
}

void read_run(hs::common::ConfigSection r, hs::common::ConfigSection o, StenosisCellConfig& c) {
  c.max_time_s = r.positive("max_time_s");
  c.sample_every_s = r.positive("sample_every_s");
  c.checkpoint_every_wall_s = r.positive_or("checkpoint_every_wall_s", 600.0);
  c.vtk_every_s = o.non_negative_or("vtk_every_s", 0.0);
}

/// Where the cell starts and stops against the constriction and its periodic image, and the lattice size.
void check_layout(hs::common::ConfigSection geometry, hs::common::ConfigSection cell, const StenosisCellConfig& c) {
  const double dx = c.numerics.dx_m;
  for (const auto& [key, value] : std::initializer_list<std::pair<const char*, double>>{
           {"height_m", c.height_m}, {"length_m", c.length_m}, {"width_m", c.width_m}}) {
    if (value < 10.0 * dx) geometry.fail(key, fmt::format("must span at least 10 dx_m = {:g} m", 10.0 * dx));
    // The box is a whole number of nodes and the straight walls fall half-way between nodes: otherwise the flow rate
    // per width and the wall positions would differ from the input.
    if (std::abs(value / dx - std::round(value / dx)) > kWholeNodesTolerance) {
      geometry.fail(key, fmt::format("= {:g} m must be a whole number of dx_m = {:g} m", value, dx));
    }
  }
  if (c.throat_height_m < kThroatNodesMin * dx) {
    geometry.fail("throat_height_m", fmt::format("must span at least {:g} dx_m = {:g} m", kThroatNodesMin, kThroatNodesMin * dx));
  }
  const double entry = c.throat_x_m - 0.5 * c.constriction_length_m;
  const double exit = c.throat_x_m + 0.5 * c.constriction_length_m;
  if (entry < 2.0 * dx || exit > c.length_m - 2.0 * dx) {
    geometry.fail("throat_x_m", fmt::format("puts the constriction [{:g}, {:g}] m outside the box [2 dx, length_m - 2 dx]",
                                            entry, exit));
  }
  const double a = 0.5 * kCellDiameter_m;
  if (c.release_x_m + a > entry) {
    cell.fail("release_x_m", fmt::format("puts the cell front at x = {:g} m, past the constriction entry {:g} m; release "
                                         "it upstream, in the straight part", c.release_x_m + a, entry));
  }
  if (c.stop_x_m <= c.throat_x_m || c.stop_x_m + a > entry + c.length_m) {
    cell.fail("stop_x_m", fmt::format("must lie in ({:g}, {:g}] m: past the throat, and the cell front must not reach the "
                                      "periodic image of the constriction entry", c.throat_x_m, entry + c.length_m - a));
  }
  const double clearance = std::min(c.initial_height, 1.0 - c.initial_height) * c.height_m - a;
  if (clearance < kWallClearanceDx * dx) {
    cell.fail("initial_height", fmt::format("puts the cell rim {:.3g} m from a wall; keep >= {:g} dx_m (the IBM stencil)",
                                            clearance, kWallClearanceDx));
  }
}

}  // namespace

common::StenosedChannelSpec StenosisCellConfig::channel() const {
  return {.x_start_m = 0.0, .x_end_m = length_m, .centre_y_m = 0.5 * height_m, .height_m = height_m,
          .throat_height_m = throat_height_m, .constriction_length_m = constriction_length_m,
          .constriction_centre_x_m = throat_x_m, .z_lo_m = 0.0, .z_hi_m = width_m};
}

StenosisCellConfig read_stenosis_cell(hs::common::ConfigFile& file, bool quick) {
  StenosisCellConfig c;
  c.quick = quick;
  auto root = file.root();
  auto geometry = root.section("geometry");
  read_geometry(geometry, c);
  const common::FluidProperties fluid = common::parse_fluid(root.section("fluid"));
  c.density_kg_m3 = fluid.density_kg_m3;
  c.kinematic_viscosity_m2_s = fluid.kinematic_viscosity_m2_s;
  auto flow = root.section("flow");
  c.mean_velocity_m_s = flow.positive("mean_velocity_m_s");
  auto cell = root.section("cell");
  read_cell(cell, c);
  auto membrane = root.section_or_empty("membrane");
  c.membrane = parse_membrane_config(membrane);
  auto numerics = root.section("numerics");
  c.numerics = read_cell_numerics(numerics);
  c.repulsion.range_m = numerics.non_negative_or("wall_repulsion_range_m", kWallRepulsionRange_m);
  c.repulsion.stiffness_N_m = numerics.non_negative_or("wall_repulsion_stiffness_N_m", kWallRepulsionStiffness_N_m);
  c.repulsion.period_x_m = c.length_m;
  read_run(root.section("run"), root.section_or_empty("output"), c);
  file.finish();
  // The fastest plasma is at the throat: 1.5 q / h_t (plane Poiseuille); it fixes dt from the lattice velocity.
  const double u_throat_max = 1.5 * c.flow_rate_m2_s() / c.throat_height_m;
  derive_cell_numerics(c.numerics, c.kinematic_viscosity_m2_s, u_throat_max, numerics);
  flow.derived("flow_rate_m2_s", c.flow_rate_m2_s());
  const double dt = c.numerics.dt_s;
  const long k = c.numerics.membrane_every;   // samples and checkpoints fall on membrane-step boundaries
  c.sample_every_steps = std::max(k, k * std::lround(c.sample_every_s / (dt * static_cast<double>(k))));
  c.sample_every_s = static_cast<double>(c.sample_every_steps) * dt;
  c.spin_up_steps = std::max(std::lround(c.height_m * c.height_m / c.kinematic_viscosity_m2_s / dt),
                             std::lround(kSpinUpTaus * c.numerics.collision.tau));
  if (quick) c.max_time_s = std::min(c.max_time_s, static_cast<double>(kQuickSamples * c.sample_every_steps) * dt);
  check_layout(geometry, cell, c);
  return c;
}

}  // namespace hs::resolved
