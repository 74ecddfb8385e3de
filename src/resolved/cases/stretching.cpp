// SPDX-License-Identifier: MIT
// The "stretching" case: [membrane] + [stretching] in, diameters vs force (CSV, PNG, VTK, summary) out.
#include "resolved/cases/stretching.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/check_list.hpp"
#include "common/io/csv_writer.hpp"
#include "common/io/vtk_polydata.hpp"
#include "common/log.hpp"
#include "common/run_context.hpp"
#include "common/run_folder.hpp"
#include "resolved/membrane/membrane_parameters.hpp"
#include "resolved/membrane/mesh_io.hpp"
#include "resolved/membrane/mesh_quality.hpp"
#include "resolved/membrane/stretching_experiment.hpp"
#include "resolved/membrane/stretching_reference.hpp"

namespace hs::resolved {
namespace {

struct StretchingCase {
  MembraneConfig membrane;
  StretchingSetup setup;
  std::filesystem::path reference_csv;
  std::vector<StretchingBandPoint> band;   // one per force level, in loading order
  bool write_vtk = true;
};

StretchingCase parse_case(const hs::common::CaseRequest& request) {
  StretchingCase c;
  auto root = request.config->root();
  auto membrane = root.section_or_empty("membrane");
  c.membrane = parse_membrane_config(membrane);
  auto s = root.section_or_empty("stretching");
  const StretchingSetup d;
  c.setup.contact_diameter_m = s.positive_or("contact_diameter_m", d.contact_diameter_m);
  c.setup.time_step_s = s.positive_or("time_step_s", d.time_step_s);
  c.setup.max_steps_per_force = static_cast<int>(s.integer_in_or("max_steps_per_force", 1, 1000000, d.max_steps_per_force));
  c.setup.steady_tolerance_m = s.positive_or("steady_tolerance_m", d.steady_tolerance_m);
  c.reference_csv = s.has("reference_csv") ? s.file_path("reference_csv") : default_stretching_band_csv();
  c.write_vtk = root.section_or_empty("output").boolean_or("vtk", true);
  c.band = read_stretching_band(c.reference_csv);
  if (request.quick) c.band = {c.band[1], c.band[c.band.size() / 2], c.band.back()};   // low, middle, top force
  request.config->finish();
  return c;
}

void plot(const hs::common::RunFolder& run, const std::filesystem::path& reference_csv, hs::common::Log& log) {
  const std::filesystem::path script = std::filesystem::path(HS_TOOLS_DIR) / "plot_stretching.py";
  if (!std::filesystem::exists("/usr/bin/python3") || !std::filesystem::exists(script)) return;
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}' '{}' '{}' > /dev/null 2>&1", script.string(),
                                      run.file("stretching.csv").string(), reference_csv.string(),
                                      run.file("stretching.png").string());
  if (std::system(cmd.c_str()) != 0) log.warning("plot_stretching.py failed (matplotlib missing?); no PNG written");
}

}  // namespace

int run_stretching(const hs::common::CaseRequest& request) {
  const StretchingCase c = parse_case(request);
  const TriangleMesh mesh = build_membrane_mesh(c.membrane);   // bad meshes fail before any output is written
  hs::common::RunContext ctx = hs::common::RunContext::start(request, "stretching");
  const hs::common::RunFolder& run = ctx.folder();
  hs::common::Log& log = ctx.log();
  log.set_quiet(request.quiet);
  write_mesh_obj(mesh, run.file("rest_mesh.obj"));
  StretchingExperiment experiment(mesh, c.membrane.material, c.membrane.solver, c.setup);
  log.info("stretching: {} vertices, {} patch vertices per end, G_s = {} N/m, {} force levels", mesh.vertex_count(),
           experiment.patch_vertex_count(), c.membrane.material.shear_modulus_N_m, c.band.size());
  hs::common::CsvWriter csv(run.file("stretching.csv"),
                            {"force_N", "axial_m", "transverse_m", "axial_lower_m", "axial_upper_m", "transverse_lower_m",
                             "transverse_upper_m", "inside_band", "area_change", "volume_change", "steps", "iterations"});
  hs::common::PvdSeries pvd(run.vtk_dir() / "membrane.pvd");
  nlohmann::json levels = nlohmann::json::array();
  bool all_good = true;
  hs::common::CheckList checks;   // one per force level: steady and inside the band
  double time_s = 0.0;
  for (std::size_t i = 0; i < c.band.size(); ++i) {
    const StretchingBandPoint& b = c.band[i];
    const StretchingPoint p = experiment.run_force(b.force_N);
    time_s += p.steps * c.setup.time_step_s;
    const bool inside = b.axial_inside(p.axial_m) && b.transverse_inside(p.transverse_m);
    all_good = all_good && inside && p.steady;
    checks.expect(fmt::format("F = {:g} pN: steady, inside the Mills band", b.force_N * 1e12), inside && p.steady,
                  fmt::format("axial {:.3f} um, transverse {:.3f} um{}", p.axial_m * 1e6, p.transverse_m * 1e6,
                              p.steady ? "" : ", NOT steady"));
    log.result("F = {:6.1f} pN: axial {:.3f} um [{:.2f}, {:.2f}], transverse {:.3f} um [{:.2f}, {:.2f}] {}; dA/A {:.1e}, "
               "dV/V {:.1e}; {} steps, {} L-BFGS iterations, {} steps unconverged{}",
               b.force_N * 1e12, p.axial_m * 1e6, b.axial_lower_m * 1e6, b.axial_upper_m * 1e6, p.transverse_m * 1e6,
               b.transverse_lower_m * 1e6, b.transverse_upper_m * 1e6, inside ? "inside" : "OUTSIDE", p.area_change,
               p.volume_change, p.steps, p.iterations, p.unconverged_steps, p.steady ? "" : " (NOT steady)");
    csv.row({b.force_N, p.axial_m, p.transverse_m, b.axial_lower_m, b.axial_upper_m, b.transverse_lower_m,
             b.transverse_upper_m, inside ? 1.0 : 0.0, p.area_change, p.volume_change, static_cast<double>(p.steps),
             static_cast<double>(p.iterations)});
    if (c.write_vtk) {
      const std::string name = fmt::format("membrane_{:03d}.vtp", i);
      write_mesh_vtp(experiment.solver().current_mesh(), run.vtk_dir() / name);
      pvd.add(time_s, name);
    }
    levels.push_back({{"force_N", b.force_N}, {"axial_m", p.axial_m}, {"transverse_m", p.transverse_m},
                      {"inside_band", inside}, {"steady", p.steady}, {"area_change", p.area_change},
                      {"volume_change", p.volume_change}, {"steps", p.steps}, {"iterations", p.iterations}});
  }
  nlohmann::json summary;
  summary["results"] = {{"levels", levels}, {"all_inside_band", all_good}, {"reference", c.reference_csv.string()}};
  summary["numerics"] = {{"mesh", to_json(mesh_quality(mesh))},
                         {"npfem_factorisation_s", experiment.solver().statistics().factorisation_s}};
  ctx.write_summary(summary, checks);
  plot(run, c.reference_csv, log);
  checks.print(log, "stretching");
  log.result("stretching: {} -> {}", all_good ? "all levels inside the Mills band" : "some levels OUTSIDE the band",
             run.path().string());
  return checks.exit_code();
}

}  // namespace hs::resolved
