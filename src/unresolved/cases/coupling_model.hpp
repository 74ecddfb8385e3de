// SPDX-License-Identifier: MIT
// The [coupling] section every CFD-DEM case reads the same way: closures by role and the model switches.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "closures/closure_registry.hpp"
#include "closures/wall_correction.hpp"
#include "common/config/config_file.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"
#include "unresolved/coupling/suspension_viscosity.hpp"

namespace hs::unresolved {

struct CouplingModel {
  bool void_fraction_rate = false;       // d(eps)/dt source (see CouplingSettings::void_fraction_rate)
  hs::closures::ClosureSpec drag{}, lift{}, deformation{};   // model "none": no lift / DI = 0
  hs::closures::WallCorrection wall_correction = hs::closures::WallCorrection::none;   // confinement factor on the drag
  bool self_induced_correction = false;  // closures get u_f - M F (CouplingSettings::self_induced_correction)
  SuspensionViscosity suspension_viscosity = SuspensionViscosity::none;   // the cells' stress (suspension_viscosity.hpp)
  double smoothing_length_m = 0.0;       // CouplingSettings::smoothing_length_m (0: none)
  bool buoyancy_over_footprint = false;  // generalised_buoyancy = "footprint" (CouplingSettings)
};

/// Closure spec from one string: a registered name ("stokes", "schiller_naumann", "saffman_mei", "none") or a
/// closure file (*.toml, model "expression"; a relative path is taken relative to `base_dir`, the case file's folder
/// in a case, the working directory when empty).
[[nodiscard]] hs::closures::ClosureSpec closure_spec_from(const std::string& name_or_file,
                                                          const std::filesystem::path& base_dir = {});

/// Reads [coupling]: void_fraction_rate (false), drag (schiller_naumann; required), lift (none), deformation (none),
/// outside_validity (clamp | extrapolate), wall_correction (none), self_induced_correction (false),
/// suspension_viscosity (none), smoothing_length_m (0). Each closure is created once to check it; a bad one is a ConfigError on its key.
[[nodiscard]] CouplingModel parse_coupling_model(hs::common::ConfigSection& coupling, const std::filesystem::path& base_dir);

/// The closures of the model, created (drag required; lift and deformation null for "none").
[[nodiscard]] CouplingClosures make_closures(const CouplingModel& m);

/// The model's names in summary.json: drag, lift, deformation (file path for closure files), wall_correction,
/// outside_validity, self_induced_correction, suspension_viscosity, smoothing_length_m.
void write_model_summary(const CouplingModel& m, nlohmann::json& summary);

}  // namespace hs::unresolved
