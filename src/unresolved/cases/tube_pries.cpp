// SPDX-License-Identifier: MIT
// Case type "tube-pries": parsing and the coupled simulation (plasma reference, insertion, averaging).
#include "unresolved/cases/tube_pries.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "analysis/pries1992.hpp"
#include "closures/register_builtin.hpp"
#include "common/dimensionless_groups.hpp"
#include "common/errors.hpp"
#include "common/geometry/tube.hpp"
#include "common/io/checkpoint.hpp"
#include "common/stop_request.hpp"
#include "unresolved/cases/cfd_dem_frames.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"
#include "unresolved/dem/hertz_contact_law.hpp"
#include "unresolved/dem/insertion.hpp"
#include "common/fluid_properties.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

/// Creates a closure to check the spec at parse time; a bad one becomes a ConfigError on `key`.
template <typename Make>
void check_closure(hs::common::ConfigSection& section, const char* key, const hs::closures::ClosureSpec& spec, Make make) {
  if (spec.model == "none") return;
  try {
    (void)make(spec);
  } catch (const hs::common::ConfigError& e) {
    section.fail(key, e.what());
  }
}

std::array<SideCondition, 6> periodic_z() {
  std::array<SideCondition, 6> sides{};
  sides[4].type = SideType::periodic;
  sides[5].type = SideType::periodic;
  return sides;
}

}  // namespace

hs::closures::ClosureSpec closure_spec_from(const std::string& name_or_file, const std::filesystem::path& base_dir) {
  const std::filesystem::path p(name_or_file);
  if (p.extension() == ".toml") {
    return {.model = "expression", .file = std::filesystem::absolute(p.is_relative() && !base_dir.empty() ? base_dir / p : p)};
  }
  return {.model = name_or_file, .file = {}};
}

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
  auto closure_key = [&](const char* key, const char* fallback, auto make) {
    const hs::closures::ClosureSpec spec = coupling.has(key) ? closure_spec_from(coupling.string(key), file.file().parent_path())
                                                             : closure_spec_from(fallback);
    check_closure(coupling, key, spec, make);
    return spec;
  };
  c.void_fraction_rate = coupling.boolean_or("void_fraction_rate", false);   // see CouplingSettings: noisy without smoothing
  c.drag = closure_key("drag", "schiller_naumann", hs::closures::make_drag_closure);
  c.lift = closure_key("lift", "none", hs::closures::make_lift_closure);
  c.deformation = closure_key("deformation", "none", hs::closures::make_deformation_closure);
  if (c.drag.model == "none") coupling.fail("drag", "a drag closure is required (a name or a closure file)");
  const std::string outside = coupling.string_or("outside_validity", "clamp");   // closures/closure_registry.hpp
  if (outside != "clamp" && outside != "extrapolate") {
    coupling.fail("outside_validity", fmt::format("\"{}\": use \"clamp\" (learned closures evaluated at the nearest point "
                                                  "of their validity box) or \"extrapolate\"", outside));
  }
  for (hs::closures::ClosureSpec* s : {&c.drag, &c.lift, &c.deformation}) {
    s->outside = outside == "clamp" ? hs::closures::OutsideValidity::clamp : hs::closures::OutsideValidity::extrapolate;
  }
  // Default "none" keeps the closures' drag; "haberman_sayre" multiplies it by the on-axis confinement factor
  // K(d_p / D), "haberman_sayre_relative" by K(d_p / D) / K(d_p / 50 um) (closures/wall_correction.hpp).
  try {
    c.wall_correction = hs::closures::wall_correction_from_name(coupling.string_or("wall_correction", "none"));
  } catch (const hs::common::ConfigError& e) {
    coupling.fail("wall_correction", e.what());
  }
  // Off by default: it needs d_p <= dx, i.e. a coarse grid in a narrow tube (self_mobility.hpp).
  c.self_induced_correction = coupling.boolean_or("self_induced_correction", false);
  try {
    c.suspension_viscosity = suspension_viscosity_from_name(coupling.string_or("suspension_viscosity", "none"));
  } catch (const hs::common::ConfigError& e) {
    coupling.fail("suspension_viscosity", e.what());
  }
  c.cells_across = static_cast<int>(numerics.integer_in("cells_across_diameter", 4, 1000));
  c.dt_s = numerics.positive("dt_s");
  c.pressure_coupling =
      pressure_coupling_from_name(numerics.one_of_or("pressure_coupling", {"piso", "projection"}, "piso"));
  c.n_coupling = static_cast<int>(numerics.integer_in("n_coupling", 1, 1000000));
  c.end_time_s = numerics.positive("end_time_s");
  c.average_from_fraction = numerics.number_in_or("average_from_fraction", 0.0, 0.95, 0.5);
  c.steady_tolerance = numerics.positive_or("steady_tolerance", 0.02);   // 2%: below the 5% acceptance band
  c.checkpoint_every_wall_s = numerics.positive_or("checkpoint_every_wall_s", 600.0);   // DESIGN.md: every N minutes
  const double dx = c.diameter_m / c.cells_across;
  const double along = c.length_m / dx;
  if (std::abs(along - std::round(along)) > 1e-6 * along) {
    geometry.fail("length_m", fmt::format("must be a whole number of cells of {:.6g} m (it is {:.4f})", dx, along));
  }
  if (c.self_induced_correction && c.particles.diameter_m > dx) {
    coupling.fail("self_induced_correction", fmt::format("needs spheres no larger than a cell, but d_p = {:.4g} m > dx = {:.4g} m; "
                                                         "use cells_across_diameter <= {}", c.particles.diameter_m, dx,
                                                         static_cast<int>(std::floor(c.diameter_m / c.particles.diameter_m))));
  }
  const double r = 0.5 * c.diameter_m;
  const double u_max = -c.pressure_gradient_Pa_m * r * r / (4.0 * c.fluid.density_kg_m3 * c.fluid.kinematic_viscosity_m2_s);
  if (u_max * c.dt_s / dx > 1.0) {   // CFDEM keeps Co < 1 (methods note sec. 0), at the plasma centreline speed
    numerics.fail("dt_s", fmt::format("gives a Courant number {:.3g} > 1 at the Poiseuille centreline speed {:.4g} m/s; use "
                                      "dt_s <= {:.4g}", u_max * c.dt_s / dx, u_max, dx / u_max));
  }
  const double dt_dem = c.dt_s / c.n_coupling;
  const double limit = 0.1 * std::min(rayleigh_time_s(c.particles), hertz_time_s(c.particles, c.particles.max_impact_velocity_m_s));
  if (dt_dem > limit) {
    numerics.fail("n_coupling", fmt::format("gives a DEM step dt_s / n_coupling = {:.4g} s > 0.1 min(t_Rayleigh, t_Hertz) = "
                                            "{:.4g} s; use n_coupling >= {}", dt_dem, limit, static_cast<long>(std::ceil(c.dt_s / limit))));
  }
  if (quick) c.end_time_s = std::min(c.end_time_s, 20.0 * c.dt_s);
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

namespace {

struct Tube3 {
  hs::common::Tube shape;
  FvmGrid grid;
  Tube3(const TubePriesConfig& c)
      : shape({.start_m = {0, 0, 0}, .end_m = {0, 0, c.length_m}, .radius_m = 0.5 * c.diameter_m}),
        grid(shape, {.box_m = {{-0.5 * c.diameter_m, -0.5 * c.diameter_m, 0.0}, {0.5 * c.diameter_m, 0.5 * c.diameter_m, c.length_m}},
                     .dx_m = c.diameter_m / c.cells_across, .sides = periodic_z()}) {}
};

FlowDrive drive_of(const TubePriesConfig& c) {
  return {.mode = FlowDrive::Mode::pressure_gradient, .axis = 2, .pressure_gradient_Pa_m = c.pressure_gradient_Pa_m};
}

/// Q_plasma: the same grid and pressure gradient without cells, run to the same end time.
double plasma_flow_rate(const TubePriesConfig& c, const FvmGrid& grid) {
  FvmSolver plasma(grid, c.fluid, {.dt_s = c.dt_s, .coupling = c.pressure_coupling}, drive_of(c));
  const long steps = std::max(1L, std::lround(c.end_time_s / c.dt_s));
  for (long s = 0; s < steps; ++s) plasma.step();
  return plasma.flow_rate_m3_s(2);
}

CouplingClosures make_closures(const TubePriesConfig& c) {
  CouplingClosures k;
  k.drag = hs::closures::make_drag_closure(c.drag);
  if (c.lift.model != "none") k.lift = hs::closures::make_lift_closure(c.lift);
  if (c.deformation.model != "none") k.deformation = hs::closures::make_deformation_closure(c.deformation);
  return k;
}

double rbc_flow_rate(const DemSystem& dem, double length_m) {
  const ParticleStore& p = dem.particles();
  double sum = 0.0;
  for (std::size_t i = 0; i < p.n_owned(); ++i) {
    const double r = p.radius_m()[i];
    sum += 4.0 / 3.0 * std::numbers::pi * r * r * r * p.velocity_m_s()[2][i];
  }
  return sum / length_m;   // the mean over the periodic length of the flux through a cross-section
}

}  // namespace

namespace {

constexpr std::size_t kSampleValues = 5;   // the fields of TubePriesSample

/// Everything the coupled run carries from step to step besides the solvers: the insertion result and the samples.
struct TubePriesState {
  double ht_achieved = 0.0;
  double rbc_count = 0.0;
  std::vector<TubePriesSample> series;
};

void write_tube_checkpoint(const CfdDemCoupling& coupling, const TubePriesState& st, const TubePriesRestart& restart) {
  hs::common::Checkpoint cp;
  coupling.write_state(cp);
  std::vector<double> series;
  for (const TubePriesSample& s : st.series) {
    series.insert(series.end(), {s.time_s, s.q_blood_m3_s, s.q_rbc_m3_s, s.ht_d, s.pressure_iterations});
  }
  cp.put("series", series);
  const std::vector<double> insertion{st.ht_achieved, st.rbc_count};
  cp.put("insertion", insertion);
  cp.meta()["case_type"] = "tube-pries";
  cp.meta()["step"] = coupling.steps();
  cp.write(restart.dir, restart.rank);
}

TubePriesState read_tube_checkpoint(CfdDemCoupling& coupling, const TubePriesRestart& restart) {
  const hs::common::Checkpoint cp = hs::common::Checkpoint::read(restart.dir, restart.rank);
  if (cp.meta().value("case_type", "") != "tube-pries") {
    throw hs::common::ConfigError(fmt::format("{}: not a tube-pries checkpoint", restart.dir.string()));
  }
  coupling.read_state(cp);
  TubePriesState st;
  const std::vector<double>& series = cp.doubles("series");
  const std::vector<double>& insertion = cp.doubles("insertion");
  if (series.size() != kSampleValues * static_cast<std::size_t>(coupling.steps()) || insertion.size() != 2) {
    throw hs::common::ConfigError(fmt::format("{}: checkpoint series of {} values for {} steps", restart.dir.string(),
                                              series.size(), coupling.steps()));
  }
  for (std::size_t k = 0; k < series.size(); k += kSampleValues) {
    st.series.push_back({series[k], series[k + 1], series[k + 2], series[k + 3], series[k + 4]});
  }
  st.ht_achieved = insertion[0];
  st.rbc_count = insertion[1];
  return st;
}

/// Means over the last (1 - from_fraction) of the series, and Ht_d of that window's two halves (steadiness).
struct SeriesAverages {
  double q_blood_m3_s, q_rbc_m3_s, ht_d_first_half, ht_d_second_half;
  long samples;
};

SeriesAverages average_series(const std::vector<TubePriesSample>& series, double from_fraction) {
  const long total = static_cast<long>(series.size());
  const long first = static_cast<long>(from_fraction * static_cast<double>(total));
  double sum_blood = 0.0, sum_rbc = 0.0;
  std::array<double, 2> half_rbc{}, half_blood{};
  for (long s = first; s < total; ++s) {
    const TubePriesSample& x = series[static_cast<std::size_t>(s)];
    sum_blood += x.q_blood_m3_s;
    sum_rbc += x.q_rbc_m3_s;
    const std::size_t half = 2 * (s - first) < total - first ? 0 : 1;
    half_rbc[half] += x.q_rbc_m3_s;
    half_blood[half] += x.q_blood_m3_s;
  }
  const double n = static_cast<double>(total - first);
  return {sum_blood / n, sum_rbc / n, half_rbc[0] / half_blood[0], half_rbc[1] / half_blood[1], total - first};
}

}  // namespace

TubePriesResult simulate_tube_pries(const TubePriesConfig& c, const std::function<void(const TubePriesSample&)>& observe,
                                    const TubePriesRestart& restart, CfdDemFrames* frames) {
  const Tube3 tube(c);
  const double r_tube = 0.5 * c.diameter_m;
  const Domain dem_domain{.box = {{-r_tube, -r_tube, 0.0}, {r_tube, r_tube, c.length_m}}, .periodic = {false, false, true}};
  DemSystem dem({.params = c.particles, .domain = dem_domain, .time_step_s = c.dt_s / c.n_coupling}, &tube.shape);
  FvmSolver fluid(tube.grid, c.fluid, {.dt_s = c.dt_s, .coupling = c.pressure_coupling}, drive_of(c));
  const double q_plasma = plasma_flow_rate(c, tube.grid);
  const double u_plasma = q_plasma / (std::numbers::pi * r_tube * r_tube);
  CfdDemCoupling coupling(fluid, dem,
                          {.n_coupling = c.n_coupling, .void_fraction_rate = c.void_fraction_rate, .axis = 2, .axis_point_m = {0, 0, 0},
                           .tube_radius_m = r_tube, .wall_correction = c.wall_correction,
                           .self_induced_correction = c.self_induced_correction,
                           .suspension_viscosity = c.suspension_viscosity},
                          make_closures(c));
  TubePriesState st;
  if (restart.resume) {
    st = read_tube_checkpoint(coupling, restart);   // restores the mean velocity the saved run used for u_r+ too
    for (const TubePriesSample& s : st.series) observe(s);
  } else {
    const InsertionResult inserted = insert_at_volume_fraction(
        tube.shape, dem_domain, {.volume_fraction = c.tube_hematocrit, .radius_m = c.particles.radius_m(), .seed = c.seed, .key = "tube_hematocrit"});
    // Fluid and cells start at rest: the slip stays in the closures' range (u_r+ < 0) while the flow develops.
    for (const Vec3& x : inserted.positions_m) dem.add_particle(x);
    st.ht_achieved = inserted.achieved_fraction;
    st.rbc_count = static_cast<double>(inserted.positions_m.size());
    coupling.set_mean_velocity_m_s(u_plasma);
  }
  const long steps = std::max(1L, std::lround(c.end_time_s / c.dt_s));
  hs::common::CheckpointSchedule schedule(c.checkpoint_every_wall_s);
  const hs::common::StopRequestScope stop_requests;
  while (coupling.steps() < steps) {
    coupling.step();
    const double q_rbc = rbc_flow_rate(dem, c.length_m);
    const double q_blood = fluid.flow_rate_m3_s(2) + q_rbc;
    st.series.push_back({fluid.time_s(), q_blood, q_rbc, q_rbc / q_blood, static_cast<double>(fluid.last_stats().pressure_iterations)});
    observe(st.series.back());
    if (frames != nullptr) frames->after_step(fluid, dem, coupling.steps(), coupling.steps() == steps);
    if (const int signal = hs::common::stop_signal()) {
      if (!restart.dir.empty()) write_tube_checkpoint(coupling, st, restart);
      throw hs::common::RunInterrupted(fmt::format("stopped by signal {} at step {} of {}{}", signal, coupling.steps(), steps,
                                                   restart.dir.empty() ? "" : "; checkpoint written, continue with --resume"),
                                       signal);
    }
    if (!restart.dir.empty() && schedule.due()) write_tube_checkpoint(coupling, st, restart);
  }
  if (!restart.dir.empty()) write_tube_checkpoint(coupling, st, restart);
  const SeriesAverages avg = average_series(st.series, c.average_from_fraction);
  const double q_blood = avg.q_blood_m3_s;
  const double q_rbc = avg.q_rbc_m3_s;
  const double ht_first = avg.ht_d_first_half;
  const double ht_second = avg.ht_d_second_half;
  const long n_avg = avg.samples;
  const long total = static_cast<long>(st.series.size());
  const double ht_achieved = st.ht_achieved;
  const double d_um = c.diameter_m * 1e6;
  TubePriesResult res;
  res.ht_d = q_rbc / q_blood;
  res.mu_rel = q_plasma / q_blood;
  res.ht_d_pries = hs::analysis::discharge_from_tube_hematocrit(d_um, ht_achieved);
  res.mu_rel_pries = hs::analysis::relative_apparent_viscosity(d_um, res.ht_d_pries);
  res.ht_d_error_pct = 100.0 * (res.ht_d - res.ht_d_pries) / res.ht_d_pries;
  res.mu_rel_error_pct = 100.0 * (res.mu_rel - res.mu_rel_pries) / res.mu_rel_pries;
  const double mu = c.fluid.density_kg_m3 * c.fluid.kinematic_viscosity_m2_s;
  const double u_blood = q_blood / (std::numbers::pi * r_tube * r_tube);
  const double wall_shear_rate = 4.0 * u_plasma / r_tube;   // Poiseuille plasma: 4 u_mean / R
  auto& j = res.summary;
  j["diameter_um"] = d_um;
  j["tube_hematocrit_requested"] = c.tube_hematocrit;
  j["tube_hematocrit"] = ht_achieved;
  j["rbc_count"] = static_cast<long>(st.rbc_count);
  j["discharge_hematocrit"] = res.ht_d;
  j["relative_apparent_viscosity"] = res.mu_rel;
  j["pries_discharge_hematocrit"] = res.ht_d_pries;
  j["pries_relative_apparent_viscosity"] = res.mu_rel_pries;
  j["ht_d_error_pct"] = res.ht_d_error_pct;
  j["mu_rel_error_pct"] = res.mu_rel_error_pct;
  j["flow_rate_blood_m3_s"] = q_blood;
  j["flow_rate_rbc_m3_s"] = q_rbc;
  j["flow_rate_plasma_only_m3_s"] = q_plasma;
  j["steady"] = std::abs(ht_second - ht_first) <= c.steady_tolerance * std::abs(ht_second);
  j["ht_d_change_between_averaging_halves"] = ht_second - ht_first;
  j["averaged_steps"] = n_avg;
  j["cfd_steps"] = total;
  j["lost_solid_volume_m3"] = coupling.exchange().lost_solid_volume_m3;
  j["drag"] = c.drag.model == "expression" ? c.drag.file.string() : c.drag.model;
  j["lift"] = c.lift.model == "expression" ? c.lift.file.string() : c.lift.model;
  j["deformation"] = c.deformation.model == "expression" ? c.deformation.file.string() : c.deformation.model;
  j["wall_correction"] = hs::closures::wall_correction_name(c.wall_correction);
  j["outside_validity"] = c.drag.outside == hs::closures::OutsideValidity::clamp ? "clamp" : "extrapolate";
  j["self_induced_correction"] = c.self_induced_correction;
  j["suspension_viscosity"] = suspension_viscosity_name(c.suspension_viscosity);
  j["pressure_coupling"] = c.pressure_coupling == PressureCoupling::piso ? "piso" : "projection";
  j["groups"] = {{"channel_reynolds", hs::common::channel_reynolds(c.fluid.density_kg_m3, c.diameter_m, 2.0 * u_blood, mu)},
                 {"wall_gamma_plus", hs::common::shear_rate_plus(wall_shear_rate, r_tube, c.fluid.kinematic_viscosity_m2_s)},
                 {"confinement_d_over_D", c.particles.diameter_m / c.diameter_m},
                 {"n_coupling", c.n_coupling},
                 {"viscous_number", c.fluid.kinematic_viscosity_m2_s * c.dt_s / std::pow(c.diameter_m / c.cells_across, 2)}};
  return res;
}

}  // namespace hs::unresolved
