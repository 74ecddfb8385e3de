// SPDX-License-Identifier: MIT
// Strict reading of the shear-suspension case file and its derived lattice values.
#include "resolved/cases/shear_suspension_config.hpp"

#include <algorithm>
#include <cmath>

#include "resolved/cases/plate_cell_config.hpp"

namespace hs::resolved {
namespace {

constexpr long kQuickSamples = 10;   // 1.2 strain units of the shipped case: 10.4 s of 10 cells (summary_schema, shared machine)

void read_flow(hs::common::ConfigSection f, ShearSuspensionConfig& c) {
  const double mu = c.density_kg_m3 * c.kinematic_viscosity_m2_s;
  f.forbid_together("shear_rate_1_s", "capillary", "give the shear rate or the capillary number Ca = mu gamma a / k_s");
  c.shear_rate_1_s = f.has("capillary")
                         ? f.positive("capillary") * c.membrane.material.shear_modulus_N_m / (mu * kCellRadius_m)
                         : f.positive("shear_rate_1_s");
  c.reynolds = c.shear_rate_1_s * c.gap_m * c.gap_m / c.kinematic_viscosity_m2_s;
  f.derived("shear_rate_1_s", c.shear_rate_1_s);
}

void read_cells(hs::common::ConfigSection k, ShearSuspensionConfig& c) {
  c.hematocrit = k.number_in("hematocrit", 1e-6, 0.6);
  c.seed = static_cast<std::uint64_t>(k.integer_in_or("seed", 0, 1L << 40, 1));
  c.shape = k.one_of_or("shape", {"biconcave", "sphere"}, "biconcave") == "sphere" ? CellShapeKind::sphere
                                                                                   : CellShapeKind::biconcave;
  c.placement_gap_m = k.positive_or("placement_gap_m", kPlacementGap_m);
  c.contact.range_m = k.non_negative_or("contact_range_m", kCellContactRange_m);
  c.contact.stiffness_N_m = k.non_negative_or("contact_stiffness_N_m", kCellContactStiffness_N_m);
}

}  // namespace

ShearSuspensionConfig read_shear_suspension(hs::common::ConfigFile& file, bool quick) {
  ShearSuspensionConfig c;
  auto root = file.root();
  const auto geometry = read_plate_box(root, c);
  auto cells = root.section("cells");
  read_cells(cells, c);
  auto membrane = root.section_or_empty("membrane");
  c.membrane = parse_membrane_config(membrane);
  read_flow(root.section("flow"), c);
  auto numerics = root.section("numerics");
  c.numerics = read_cell_numerics(numerics);
  auto run = root.section("run");
  c.max_time_s = run.positive("max_time_s");
  c.sample_every_s = run.positive("sample_every_s");
  c.vtk_every_s = root.section_or_empty("output").non_negative_or("vtk_every_s", 0.0);
  file.finish();
  derive_cell_numerics(c.numerics, c.kinematic_viscosity_m2_s, 0.5 * c.shear_rate_1_s * c.gap_m, numerics,
                       c.shear_rate_1_s);
  const double dt = c.numerics.dt_s;
  const long k = c.numerics.membrane_every;   // samples fall on membrane-step boundaries
  c.sample_every_steps = std::max(k, k * std::lround(c.sample_every_s / (dt * static_cast<double>(k))));
  c.sample_every_s = static_cast<double>(c.sample_every_steps) * dt;
  if (quick) c.max_time_s = std::min(c.max_time_s, static_cast<double>(kQuickSamples * c.sample_every_steps) * dt);
  check_plate_box_span(geometry, c, c.numerics.dx_m);
  c.contact.period_m = {c.length_m, 0.0, c.width_m};
  return c;
}

}  // namespace hs::resolved
