// SPDX-License-Identifier: MIT
// The [coupling] section of the CFD-DEM cases: parsing, closure creation, summary names.
#include "unresolved/cases/coupling_model.hpp"

#include <fmt/format.h>

#include "closures/named_closure_set.hpp"
#include "closures/register_builtin.hpp"
#include "common/errors.hpp"

namespace hs::unresolved {
namespace {

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

std::string closure_name(const hs::closures::ClosureSpec& s) { return s.model == "expression" ? s.file.string() : s.model; }

}  // namespace

hs::closures::ClosureSpec closure_spec_from(const std::string& name_or_file, const std::filesystem::path& base_dir) {
  const std::filesystem::path p(name_or_file);
  if (p.extension() == ".toml") {
    return {.model = "expression", .file = std::filesystem::absolute(p.is_relative() && !base_dir.empty() ? base_dir / p : p)};
  }
  return {.model = name_or_file, .file = {}};
}

CouplingModel parse_coupling_model(hs::common::ConfigSection& coupling, const std::filesystem::path& base_dir) {
  CouplingModel m;
  // A committed set's name ("resolved") becomes its file, so the run's summary records which file it used.
  auto closure_key = [&](const char* key, const char* fallback, hs::closures::ClosureKind kind, auto make) {
    hs::closures::ClosureSpec spec = coupling.has(key) ? closure_spec_from(coupling.string(key), base_dir)
                                                       : closure_spec_from(fallback);
    try {
      spec = hs::closures::resolve_closure_set(spec, kind);
    } catch (const hs::common::ConfigError& e) {
      coupling.fail(key, e.what());
    }
    check_closure(coupling, key, spec, make);
    return spec;
  };
  m.void_fraction_rate = coupling.boolean_or("void_fraction_rate", false);   // see CouplingSettings: noisy without smoothing
  using hs::closures::ClosureKind;
  m.drag = closure_key("drag", "schiller_naumann", ClosureKind::drag, hs::closures::make_drag_closure);
  m.lift = closure_key("lift", "none", ClosureKind::lift, hs::closures::make_lift_closure);
  m.deformation = closure_key("deformation", "none", ClosureKind::deformation, hs::closures::make_deformation_closure);
  if (m.drag.model == "none") coupling.fail("drag", "a drag closure is required (a name or a closure file)");
  const std::string outside = coupling.string_or("outside_validity", "clamp");   // closures/closure_registry.hpp
  if (outside != "clamp" && outside != "extrapolate") {
    coupling.fail("outside_validity", fmt::format("\"{}\": use \"clamp\" (learned closures evaluated at the nearest point "
                                                  "of their validity box) or \"extrapolate\"", outside));
  }
  for (hs::closures::ClosureSpec* s : {&m.drag, &m.lift, &m.deformation}) {
    s->outside = outside == "clamp" ? hs::closures::OutsideValidity::clamp : hs::closures::OutsideValidity::extrapolate;
  }
  // Default "none" keeps the closures' drag; "haberman_sayre" multiplies it by the on-axis confinement factor
  // K(d_p / D), "haberman_sayre_relative" by K(d_p / D) / K(d_p / 50 um) (closures/wall_correction.hpp).
  try {
    m.wall_correction = hs::closures::wall_correction_from_name(coupling.string_or("wall_correction", "none"));
  } catch (const hs::common::ConfigError& e) {
    coupling.fail("wall_correction", e.what());
  }
  // Off by default: it needs d_p <= dx, i.e. a coarse grid in a narrow tube (self_mobility.hpp).
  m.self_induced_correction = coupling.boolean_or("self_induced_correction", false);
  try {
    m.suspension_viscosity = suspension_viscosity_from_name(coupling.string_or("suspension_viscosity", "none"));
  } catch (const hs::common::ConfigError& e) {
    coupling.fail("suspension_viscosity", e.what());
  }
  // The fields' smoothing length (diffusion_smoothing.hpp); up to 1 mm, far beyond any cell-scale footprint.
  m.smoothing_length_m = coupling.number_in_or("smoothing_length_m", 0.0, 1e-3, 0.0);
  // "centre" (default, every committed result) or "footprint" (CouplingSettings::buoyancy_over_footprint).
  m.buoyancy_over_footprint = coupling.one_of_or("generalised_buoyancy", {"centre", "footprint"}, "centre") == "footprint";
  return m;
}

CouplingClosures make_closures(const CouplingModel& m) {
  CouplingClosures k;
  k.drag = hs::closures::make_drag_closure(m.drag);
  if (m.lift.model != "none") k.lift = hs::closures::make_lift_closure(m.lift);
  if (m.deformation.model != "none") k.deformation = hs::closures::make_deformation_closure(m.deformation);
  return k;
}

void write_model_summary(const CouplingModel& m, nlohmann::json& j) {
  j["drag"] = closure_name(m.drag);
  j["lift"] = closure_name(m.lift);
  j["deformation"] = closure_name(m.deformation);
  j["wall_correction"] = hs::closures::wall_correction_name(m.wall_correction);
  j["outside_validity"] = m.drag.outside == hs::closures::OutsideValidity::clamp ? "clamp" : "extrapolate";
  j["self_induced_correction"] = m.self_induced_correction;
  j["suspension_viscosity"] = suspension_viscosity_name(m.suspension_viscosity);
  if (m.smoothing_length_m > 0.0) j["smoothing_length_m"] = m.smoothing_length_m;   // absent: none (old fingerprints hold)
  if (m.buoyancy_over_footprint) j["generalised_buoyancy"] = "footprint";            // absent: centre
}

}  // namespace hs::unresolved
