// SPDX-License-Identifier: MIT
// Strict reading of the shear and migration case files and their derived lattice values.
#include "resolved/cases/plate_cell_config.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "resolved/cases/cytoplasm_viscosity.hpp"
#include "resolved/cases/stokes_analogue.hpp"
#include "resolved/measure/flow_mode.hpp"
#include "resolved/membrane/triangle_mesh.hpp"

namespace hs::resolved {
namespace {

constexpr long kQuickSamples = 40;
/// Spin-up of the Poiseuille drive: the longer of H^2 / nu and 10 tau steps (the lattice stress relaxes over ~tau steps).
constexpr double kSpinUpTaus = 10.0;
/// Clearance (in dx) between the released cell and a wall: the 4-point IBM stencil reaches 2 dx, the stress is
/// sampled up to 2 dx outside the membrane (resolved-methods.md 1.4).
constexpr double kWallClearanceDx = 2.0;

void read_flow(hs::common::ConfigSection f, PlateCellConfig& c) {
  const double mu = c.density_kg_m3 * c.kinematic_viscosity_m2_s;
  if (c.flow == PlateFlow::poiseuille) {
    c.reynolds = f.positive("reynolds");
    c.u_max_m_s = c.reynolds * c.kinematic_viscosity_m2_s / c.gap_m;
    c.shear_rate_1_s = 4.0 * c.u_max_m_s / c.gap_m;
    f.derived("u_max_m_s", c.u_max_m_s);
    return;
  }
  f.forbid_together("shear_rate_1_s", "capillary", "give the shear rate or the capillary number Ca = mu gamma a / k_s");
  if (f.has("capillary")) {
    c.shear_rate_1_s = f.positive("capillary") * c.membrane.material.shear_modulus_N_m / (mu * kCellRadius_m);
    c.stokes_analogue = f.boolean_or("stokes_analogue", false);
  } else {
    if (f.has("stokes_analogue")) {
      f.fail("stokes_analogue", "keeps Ca while it raises the viscosities: give [flow] capillary, not shear_rate_1_s");
    }
    c.shear_rate_1_s = f.positive("shear_rate_1_s");
  }
}

/// Shear: the wall speed and Reynolds number of the (final) shear rate and viscosity.
void derive_shear_flow(hs::common::ConfigSection f, PlateCellConfig& c) {
  c.u_max_m_s = 0.5 * c.shear_rate_1_s * c.gap_m;
  c.reynolds = c.shear_rate_1_s * c.gap_m * c.gap_m / c.kinematic_viscosity_m2_s;
  f.derived("shear_rate_1_s", c.shear_rate_1_s);
  if (c.stokes_analogue) f.derived("analogue_viscosity_factor", c.analogue_viscosity_factor);
}

/// [flow] stokes_analogue: every viscosity (plasma, cytoplasm through the kept ratio, membrane) times the factor, the
/// shear rate over it. The cell's mass (with the mass factor) needs that factor given, not derived from tau.
void apply_stokes_analogue(hs::common::ConfigSection numerics, PlateCellConfig& c) {
  if (c.numerics.membrane_mass_factor == 0.0) {
    numerics.fail("membrane_mass_factor", "must be given with [flow] stokes_analogue = true (the analogue keeps the "
                                          "cell's Stokes number, which the mass factor sets; the shear cases use 100)");
  }
  const double volume_m3 = mesh_volume_m3(build_membrane_mesh(c.membrane));
  const double factor = stokes_analogue_viscosity_factor(
      {.kinematic_viscosity_m2_s = c.kinematic_viscosity_m2_s, .density_kg_m3 = c.density_kg_m3,
       .shear_rate_1_s = c.shear_rate_1_s,
       .cell_mass_kg = c.membrane.material.density_kg_m3 * c.numerics.membrane_mass_factor * volume_m3,
       .cell_radius_m = kCellRadius_m});
  c.analogue_viscosity_factor = factor;
  c.kinematic_viscosity_m2_s *= factor;
  c.membrane.material.viscosity_N_s_m *= factor;
  c.membrane.material.deformation_friction_Pa_s_m *= factor;
  c.shear_rate_1_s /= factor;
}

void read_run(hs::common::ConfigSection r, hs::common::ConfigSection o, PlateCellConfig& c) {
  if (c.flow == PlateFlow::shear) {
    r.forbid_together("max_time_s", "max_jeffery_periods", "give the cap either in seconds or in Jeffery periods");
  }
  c.max_time_s = c.flow == PlateFlow::shear && r.has("max_jeffery_periods")
                     ? r.positive("max_jeffery_periods") * jeffery_period(c.shear_rate_1_s)
                     : r.positive("max_time_s");
  // Shear: stop as soon as the membrane's whole revolutions are settled (PlateCellSeries::tank_treading_settled), the
  // cap above still bounding a run that never settles (a tumbling cell).
  c.stop_when_settled = c.flow == PlateFlow::shear ? r.boolean_or("stop_when_settled", false) : false;
  c.sample_every_s = r.positive("sample_every_s");
  c.checkpoint_every_wall_s = r.positive_or("checkpoint_every_wall_s", 600.0);
  c.vtk_every_s = o.non_negative_or("vtk_every_s", 0.0);
}

void read_check(hs::common::ConfigSection k, PlateCellConfig& c) {
  if (c.flow == PlateFlow::poiseuille) {
    c.expect_toward_centreline = k.boolean_or("toward_centreline", false);
    return;
  }
  c.expect_flow_mode = k.one_of_or("flow_mode", {"", "tumbling", "tank-treading", "intermediate", "steady"}, "");
  if (k.has("period_over_jeffery")) {
    const std::vector<double> band = k.numbers_in("period_over_jeffery", 0.01, 100.0, 2);
    if (band.size() != 2 || band[0] >= band[1]) {
      k.fail("period_over_jeffery", "must be [min, max] with min < max (the band of the tumbling period / Jeffery's)");
    }
    if (c.expect_flow_mode != "tumbling") k.fail("period_over_jeffery", "applies to flow_mode = \"tumbling\" only");
    c.period_over_jeffery_min = band[0];
    c.period_over_jeffery_max = band[1];
  }
}

}  // namespace

PlateCellConfig read_plate_cell(hs::common::ConfigFile& file, PlateFlow flow, bool quick) {
  PlateCellConfig c;
  c.flow = flow;
  auto root = file.root();
  const auto geometry = read_plate_box(root, c);
  auto cell = root.section_or_empty("cell");
  c.initial_height = cell.number_in_or("initial_height", 0.05, 0.95, 0.5);
  c.shape = cell.one_of_or("shape", {"biconcave", "sphere"}, "biconcave") == "sphere" ? CellShapeKind::sphere
                                                                                 : CellShapeKind::biconcave;
  if (c.shape == CellShapeKind::sphere && cell.has("disc_axis")) {
    cell.fail("disc_axis", "applies to shape = \"biconcave\" (a sphere has no disc axis)");
  }
  const std::string axis = cell.one_of_or("disc_axis", {"x", "y", "z"}, flow == PlateFlow::shear ? "y" : "z");
  c.disc_axis = axis == "x" ? 0 : (axis == "y" ? 1 : 2);
  const double viscosity_ratio = read_cytoplasm_viscosity_ratio(cell, c.density_kg_m3 * c.kinematic_viscosity_m2_s);
  auto membrane = root.section_or_empty("membrane");
  c.membrane = parse_membrane_config(membrane);
  read_flow(root.section("flow"), c);
  auto numerics = root.section("numerics");
  c.numerics = read_cell_numerics(numerics);
  c.numerics.viscosity_ratio = viscosity_ratio;
  if (c.stokes_analogue) apply_stokes_analogue(numerics, c);
  if (flow == PlateFlow::shear) derive_shear_flow(root.section("flow"), c);
  read_run(root.section("run"), root.section_or_empty("output"), c);
  read_check(root.section_or_empty("check"), c);
  file.finish();
  // The wall shear rate (simple shear: gamma everywhere; plane Poiseuille: 4 U_max / H) bounds the lattice's memory.
  derive_cell_numerics(c.numerics, c.kinematic_viscosity_m2_s, c.u_max_m_s, numerics, c.shear_rate_1_s);
  check_cytoplasm_relaxation(cell, c.numerics);
  const double dt = c.numerics.dt_s;
  const long k = c.numerics.membrane_every;   // samples and checkpoints fall on membrane-step boundaries
  c.sample_every_steps = std::max(k, k * std::lround(c.sample_every_s / (dt * static_cast<double>(k))));
  c.sample_every_s = static_cast<double>(c.sample_every_steps) * dt;
  if (flow == PlateFlow::poiseuille) {
    c.spin_up_steps = std::max(std::lround(c.gap_m * c.gap_m / c.kinematic_viscosity_m2_s / dt),
                               std::lround(kSpinUpTaus * c.numerics.collision.tau));
  }
  if (quick) c.max_time_s = std::min(c.max_time_s, static_cast<double>(kQuickSamples * c.sample_every_steps) * dt);
  const double dx = c.numerics.dx_m;
  check_plate_box_span(geometry, c, dx);
  // The rim (radius a) must clear the walls by the IBM stencil, whatever the orientation.
  const double clearance = std::min(c.initial_height, 1.0 - c.initial_height) * c.gap_m - kCellRadius_m;
  if (clearance < kWallClearanceDx * dx) {
    cell.fail("initial_height", fmt::format("puts the cell rim {:.3g} m from a wall; keep >= {:g} dx_m (the IBM stencil)",
                                            clearance, kWallClearanceDx));
  }
  return c;
}

}  // namespace hs::resolved
