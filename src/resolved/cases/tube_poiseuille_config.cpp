// SPDX-License-Identifier: MIT
// Strict reading of the tube-poiseuille case file.
#include "resolved/cases/tube_poiseuille_config.hpp"
#include "common/fluid_properties.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "resolved/cases/lattice_budget.hpp"

namespace hs::resolved {
namespace {

/// Lattice Mach limit: compressibility errors grow as Ma^2 (Krueger et al. 2017, section 7.3.3).
constexpr double kMachMax = 0.1;
/// Coarsening of --quick: R = 25 um at dx = 2.5 um is 10 lattice spacings, where Bouzidi walls are < 1 % off.
constexpr double kQuickCoarsening = 2.5;

void read_numerics(hs::common::ConfigSection n, TubePoiseuilleConfig& c, bool quick) {
  n.forbid_together("tau", "time_step_s", "the time step follows from dx_m, tau and the viscosity; give tau only");
  if (n.has("time_step_s")) n.fail("time_step_s", "is derived (dt = (tau - 1/2) dx^2 / (3 nu)); give tau instead");
  c.dx_m = n.positive("dx_m") * (quick ? kQuickCoarsening : 1.0);
  n.derived("dx_m_used", c.dx_m);   // differs from dx_m with --quick
  c.collision.tau = n.greater_than("tau", 0.5);
  c.collision.model = collision_model_from_name(n.one_of_or("collision", {"trt", "bgk", "regularized"}, "trt"));
  c.collision.magic = n.greater_than_or("trt_magic", 0.0, trt_magic_default);
  c.wall = n.one_of_or("wall", {"bouzidi", "half_way"}, "bouzidi") == "bouzidi" ? WallRule::bouzidi
                                                                                 : WallRule::half_way;
}

}  // namespace

TubePoiseuilleConfig read_tube_poiseuille(hs::common::ConfigFile& file, bool quick) {
  TubePoiseuilleConfig c{};
  auto root = file.root();
  auto geometry = root.section("geometry");
  c.radius_m = geometry.positive("radius_m");
  c.length_m = geometry.positive("length_m");
  const common::FluidProperties fluid = common::parse_fluid(root.section("fluid"));
  c.density_kg_m3 = fluid.density_kg_m3;
  c.kinematic_viscosity_m2_s = fluid.kinematic_viscosity_m2_s;
  auto flow = root.section("flow");
  c.reynolds = flow.positive("reynolds");
  read_numerics(root.section("numerics"), c, quick);
  const double min_box = 2.0 * c.radius_m + 4.0 * c.dx_m;
  c.box_width_m = geometry.positive_or("box_width_m", min_box);
  if (c.box_width_m < 2.0 * c.radius_m + 2.0 * c.dx_m) {
    geometry.fail("box_width_m", fmt::format("the tube (radius_m = {:g}, diameter {:g} m) does not fit: the box must be at "
                                             "least 2 radius_m + 2 dx_m = {:g} m wide",
                                             c.radius_m, 2.0 * c.radius_m, 2.0 * c.radius_m + 2.0 * c.dx_m));
  }
  if (c.length_m < 2.0 * c.dx_m) geometry.fail("length_m", fmt::format("must span at least 2 dx_m = {:g} m", 2.0 * c.dx_m));
  auto run = root.section_or_empty("run");
  c.steady_tolerance = run.number_in_or("steady_tolerance", 1e-12, 1e-2, 1e-5);
  c.check_every_steps = run.integer_in_or("check_every_steps", 1, 1000000, 100);
  c.max_steps = run.integer_in_or("max_steps", 1, 100000000, 200000);
  auto output = root.section_or_empty("output");
  c.vtk_frames = output.integer_in_or("vtk_frames", 1, 1000, 5);
  file.finish();
  // Derived: U_max from Re, dt from dx, tau and nu, and the lattice Mach number.
  c.u_max_m_s = c.reynolds * c.kinematic_viscosity_m2_s / (2.0 * c.radius_m);
  c.dt_s = (c.collision.tau - 0.5) * c.dx_m * c.dx_m / (3.0 * c.kinematic_viscosity_m2_s);
  c.lattice_mach = c.u_max_m_s * c.dt_s / c.dx_m * std::sqrt(3.0);
  auto numerics = root.section("numerics");
  numerics.derived("time_step_s", c.dt_s);
  numerics.derived("lattice_mach", c.lattice_mach);
  root.section("flow").derived("u_max_m_s", c.u_max_m_s);
  require_lattice_memory(file, tube_poiseuille_nodes(c),
                         {{"[geometry] radius_m", c.radius_m, true}, {"[geometry] length_m", c.length_m, true},
                          {"[numerics] dx_m", quick ? c.dx_m / kQuickCoarsening : c.dx_m, true}});
  if (c.lattice_mach > kMachMax) {
    root.section("flow").fail("reynolds", fmt::format("gives U_max = {:g} m/s and a lattice Mach number {:.3f} > {} at dx_m = "
                                                      "{:g}, tau = {:g}; lower reynolds, dx_m or tau",
                                                      c.u_max_m_s, c.lattice_mach, kMachMax, c.dx_m, c.collision.tau));
  }
  return c;
}

std::array<int, 3> tube_poiseuille_nodes(const TubePoiseuilleConfig& c) {
  const double across_d = std::floor(c.box_width_m / c.dx_m + 1e-9) + 1.0;
  // Clamped to int: a size beyond it is refused by the memory check (which sees the clamped count, still far too big).
  int across = static_cast<int>(std::min(across_d, 2.0e9));
  if (across % 2 == 0) --across;
  return {across, across, std::max(2, static_cast<int>(std::min(std::round(c.length_m / c.dx_m), 2.0e9)))};
}

}  // namespace hs::resolved
