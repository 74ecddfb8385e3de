// SPDX-License-Identifier: MIT
// `hemoscale validate stretching`: RBC optical-tweezers stretching vs Mills et al. 2004 (Mech Chem Biosyst 1:169).
// Default membrane parameters (one set for all forces), 2 um contact patches, all 13 force levels at 258 vertices
// and, for mesh independence, at 642 vertices (--quick: 3 levels, 258 only). Acceptance: axial and transverse
// diameters inside the experimental band (lower-upper) at every level.
#include "validate/stretching_validation.hpp"
#include <cstdio>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/case_request.hpp"
#include "common/run_folder.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"
#include "resolved/membrane/stretching_experiment.hpp"
#include "resolved/membrane/stretching_reference.hpp"

namespace hs::resolved {
namespace {

/// Each long quasi-static step is allowed to converge (the default 30 iterations suit 0.25 us coupled steps).
NpfemSettings quasi_static_settings() {
  NpfemSettings s;
  s.max_iterations = 300;
  return s;
}

nlohmann::json run_resolution(int vertices, const std::vector<StretchingBandPoint>& band, int& outside) {
  StretchingExperiment experiment(make_rbc_mesh({.vertex_count = vertices}), MembraneParameters{}, quasi_static_settings(),
                                  StretchingSetup{});
  nlohmann::json levels = nlohmann::json::array();
  fmt::print("{} vertices ({} per contact patch)\n  force_pN  axial_um [band]            transverse_um [band]\n",
             vertices, experiment.patch_vertex_count());
  for (const StretchingBandPoint& b : band) {
    const StretchingPoint p = experiment.run_force(b.force_N);
    const bool axial_in = b.axial_inside(p.axial_m);
    const bool transverse_in = b.transverse_inside(p.transverse_m);
    if (!(axial_in && transverse_in && p.steady)) ++outside;
    fmt::print("  {:7.1f}  {:6.3f} [{:5.2f}, {:5.2f}] {:3}  {:6.3f} [{:5.2f}, {:5.2f}] {:3}  dA/A {:+.1e} dV/V {:+.1e}\n",
               b.force_N * 1e12, p.axial_m * 1e6, b.axial_lower_m * 1e6, b.axial_upper_m * 1e6, axial_in ? "in" : "OUT",
               p.transverse_m * 1e6, b.transverse_lower_m * 1e6, b.transverse_upper_m * 1e6, transverse_in ? "in" : "OUT",
               p.area_change, p.volume_change);
    levels.push_back({{"force_pN", b.force_N * 1e12}, {"axial_um", p.axial_m * 1e6},
                      {"transverse_um", p.transverse_m * 1e6}, {"inside_band", axial_in && transverse_in},
                      {"axial_inside", axial_in}, {"transverse_inside", transverse_in}, {"steady", p.steady},
                      {"area_change", p.area_change}, {"volume_change", p.volume_change}});
  }
  return levels;
}

}  // namespace

int validate_stretching(const hs::common::TaskOptions& options) {
  std::vector<StretchingBandPoint> band = read_stretching_band(default_stretching_band_csv());
  if (options.quick) band = {band[1], band[band.size() / 2], band.back()};
  int outside = 0;
  nlohmann::json result = {{"validation", "stretching"},
                           {"reference", "Mills et al. 2004, Mech Chem Biosyst 1:169 (optical tweezers)"},
                           {"shear_modulus_N_m", MembraneParameters{}.shear_modulus_N_m},
                           {"strain_hardening_ratio", MembraneParameters{}.strain_hardening_ratio},
                           {"bending_modulus_J", MembraneParameters{}.bending_modulus_J}};
  result["levels"] = run_resolution(258, band, outside);
  if (!options.quick) result["levels_642"] = run_resolution(642, band, outside);
  result["levels_outside_band"] = outside;
  result["provenance"] = hs::common::provenance();
  fmt::print("stretching: {} level(s) outside the Mills band\n", outside);
  if (options.json_file) hs::common::write_json(*options.json_file, result);
  return outside == 0 ? 0 : 1;
}

}  // namespace hs::resolved
