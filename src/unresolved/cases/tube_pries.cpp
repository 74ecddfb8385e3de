// SPDX-License-Identifier: MIT
// Case type "tube-pries": the case file (the run itself is tube_pries_measurement.cpp on the CFD-DEM skeleton).
#include "unresolved/cases/tube_pries.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/fluid_properties.hpp"
#include "unresolved/cases/loop_numerics.hpp"
#include "unresolved/cases/step_limits.hpp"

namespace hs::unresolved {

TubePriesConfig parse_tube_pries(hs::common::ConfigFile& file, bool quick) {
  auto root = file.root();
  auto geometry = root.section("geometry");
  auto flow = root.section("flow");
  auto cells = root.section("cells");
  auto particles = root.section_or_empty("particles");
  auto coupling = root.section_or_empty("coupling");
  auto numerics = root.section("numerics");
  TubePriesConfig c{};
  c.diameter_m = geometry.positive("diameter_m");
  c.length_m = geometry.positive("length_m");
  c.fluid = hs::common::parse_fluid(root.section("fluid"));
  c.pressure_gradient_Pa_m = flow.number_in("pressure_gradient_Pa_m", -1e12, -1e-12);
  // Random close packing of equal spheres is ~0.64 (Scott & Kilgour 1969); insertion reports the actual limit.
  c.tube_hematocrit = cells.number_in("tube_hematocrit", 1e-6, 0.64);
  c.seed = static_cast<std::uint64_t>(cells.integer_in_or("seed", 0, 1L << 40, 1));
  c.particles = parse_particle_params(particles);
  const CouplingModel model = parse_coupling_model(coupling, file.file().parent_path());
  c.void_fraction_rate = model.void_fraction_rate;
  c.drag = model.drag;
  c.lift = model.lift;
  c.deformation = model.deformation;
  c.wall_correction = model.wall_correction;
  c.self_induced_correction = model.self_induced_correction;
  c.suspension_viscosity = model.suspension_viscosity;
  c.smoothing_length_m = model.smoothing_length_m;
  c.buoyancy_over_footprint = model.buoyancy_over_footprint;
  c.cells_across = static_cast<int>(numerics.integer_in("cells_across_diameter", 4, 1000));
  c.dt_s = numerics.positive("dt_s");
  c.pressure_coupling =
      pressure_coupling_from_name(numerics.one_of_or("pressure_coupling", {"piso", "projection"}, "piso"));
  c.piso_correctors = read_piso_correctors(numerics);
  c.n_coupling = static_cast<int>(numerics.integer_in("n_coupling", 1, 1000000));
  c.end_time_s = numerics.positive("end_time_s");
  // Past end_time_s the run goes on until Ht_d and mu_rel are steady, at most to max_end_time_s (absent: no further).
  c.max_end_time_s = numerics.positive_or("max_end_time_s", c.end_time_s);
  if (c.max_end_time_s < c.end_time_s) {
    numerics.fail("max_end_time_s", fmt::format("must be at least end_time_s = {:.6g} s (the shortest run)", c.end_time_s));
  }
  c.average_from_fraction = numerics.number_in_or("average_from_fraction", 0.0, 0.95, 0.5);
  c.steady_tolerance = numerics.positive_or("steady_tolerance", 0.02);   // 2%: below the 5% acceptance band
  c.checkpoint_every_wall_s = numerics.positive_or("checkpoint_every_wall_s", 600.0);   // DESIGN.md: every N minutes
  const double dx = c.diameter_m / c.cells_across;
  const double along = c.length_m / dx;
  if (std::abs(along - std::round(along)) > 1e-6 * along) {
    geometry.fail("length_m", fmt::format("must be a whole number of cells of {:.6g} m (it is {:.4f})", dx, along));
  }
  if (c.self_induced_correction && c.particles.diameter_m > dx && !(c.smoothing_length_m > 0.0)) {
    coupling.fail("self_induced_correction", fmt::format("needs spheres no larger than a cell, but d_p = {:.4g} m > dx = {:.4g} m; "
                                                         "use cells_across_diameter <= {} or smooth the exchange "
                                                         "(smoothing_length_m, about d_p)", c.particles.diameter_m, dx,
                                                         static_cast<int>(std::floor(c.diameter_m / c.particles.diameter_m))));
  }
  const double r = 0.5 * c.diameter_m;
  const double u_max = -c.pressure_gradient_Pa_m * r * r / (4.0 * c.fluid.density_kg_m3 * c.fluid.kinematic_viscosity_m2_s);
  check_courant(numerics, u_max, c.dt_s, dx, "the Poiseuille centreline speed");
  check_dem_step(numerics, c.particles, c.dt_s, c.n_coupling);
  if (quick) {
    c.end_time_s = std::min(c.end_time_s, 20.0 * c.dt_s);
    c.max_end_time_s = c.end_time_s;
  }
  c.vtk_every_s = root.section_or_empty("output").positive_or("vtk_every_s", 0.0);   // 0 (absent): final frame only
  if (c.wall_correction != hs::closures::WallCorrection::none) {
    try {
      (void)hs::closures::wall_correction_factor(c.wall_correction, c.particles.diameter_m, c.diameter_m);
    } catch (const hs::common::ConfigError& e) {
      coupling.fail("wall_correction", e.what());
    }
  }
  file.finish();
  return c;
}

}  // namespace hs::unresolved
