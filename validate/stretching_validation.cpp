// SPDX-License-Identifier: MIT
// `hemoscale validate stretching`: RBC optical-tweezers stretching vs Mills et al. 2004 (Mech Chem Biosyst 1:169).
// Default membrane parameters (one set for all forces), 2 um contact patches, all 13 force levels at 258 vertices
// and, for mesh independence, at 642 vertices (--quick: 3 levels, 258 only). Acceptance: axial and transverse
// diameters inside the experimental band (lower-upper) at every level, each quasi-static solve converged; exit 1
// otherwise. --tighten F shrinks each band about its midpoint by F (tests of the failure path).
#include "validate/stretching_validation.hpp"
#include <cstdio>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/case_request.hpp"
#include "common/check_list.hpp"
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

/// The band shrunk about its midpoint by `tighten` (1: the published band).
StretchingBandPoint tightened(StretchingBandPoint b, double tighten) {
  const auto shrink = [tighten](double& lower, double mid, double& upper) {
    lower = mid - (mid - lower) / tighten;
    upper = mid + (upper - mid) / tighten;
  };
  shrink(b.axial_lower_m, b.axial_mid_m, b.axial_upper_m);
  shrink(b.transverse_lower_m, b.transverse_mid_m, b.transverse_upper_m);
  return b;
}

nlohmann::json run_resolution(int vertices, const std::vector<StretchingBandPoint>& band, hs::common::CheckList& checks) {
  StretchingExperiment experiment(make_rbc_mesh({.vertex_count = vertices}), MembraneParameters{}, quasi_static_settings(),
                                  StretchingSetup{});
  nlohmann::json levels = nlohmann::json::array();
  fmt::print("{} vertices ({} per contact patch)\n  force_pN  axial_um [band]            transverse_um [band]\n",
             vertices, experiment.patch_vertex_count());
  for (const StretchingBandPoint& b : band) {
    const StretchingPoint p = experiment.run_force(b.force_N);
    const bool axial_in = b.axial_inside(p.axial_m);
    const bool transverse_in = b.transverse_inside(p.transverse_m);
    const std::string level = fmt::format("{} vertices, {:.0f} pN", vertices, b.force_N * 1e12);
    checks.expect(level + ": axial diameter", axial_in,
                  fmt::format("{:.3f} um, band [{:.2f}, {:.2f}]", p.axial_m * 1e6, b.axial_lower_m * 1e6, b.axial_upper_m * 1e6));
    checks.expect(level + ": transverse diameter", transverse_in,
                  fmt::format("{:.3f} um, band [{:.2f}, {:.2f}]", p.transverse_m * 1e6, b.transverse_lower_m * 1e6,
                              b.transverse_upper_m * 1e6));
    checks.expect(level + ": quasi-static solve converged", p.steady, "");
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
  for (StretchingBandPoint& b : band) b = tightened(b, options.tighten);
  hs::common::CheckList checks;
  nlohmann::json result = {{"validation", "stretching"},
                           {"reference", "Mills et al. 2004, Mech Chem Biosyst 1:169 (optical tweezers)"},
                           {"shear_modulus_N_m", MembraneParameters{}.shear_modulus_N_m},
                           {"strain_hardening_ratio", MembraneParameters{}.strain_hardening_ratio},
                           {"bending_modulus_J", MembraneParameters{}.bending_modulus_J}};
  result["levels"] = run_resolution(258, band, checks);
  if (options.quick) {
    checks.skip("642 vertices (mesh independence)", "--quick: 258 vertices and 3 force levels only");
  } else {
    result["levels_642"] = run_resolution(642, band, checks);
  }
  checks.write_to(result);
  result["provenance"] = hs::common::provenance();
  checks.print("stretching vs Mills 2004");
  if (options.json_file) hs::common::write_json(*options.json_file, result);
  return checks.exit_code();
}

}  // namespace hs::resolved
