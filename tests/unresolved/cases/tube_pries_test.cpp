// SPDX-License-Identifier: MIT
// The tube-pries case: the committed case runs (quick) and summarises against Pries; the learned-closure path
// runs on the synthetic closure files; bad inputs are ConfigErrors naming the key (exit code 2 in the CLI).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "unresolved/cases/short_tube_case.hpp"
#include "analysis/pries1992.hpp"
#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "unresolved/cases/tube_pries.hpp"

namespace {

namespace fs = std::filesystem;

hs::common::CaseRequest pries_request(hs::common::ConfigFile& file, const fs::path& out) {
  auto section = file.root().section("case");
  (void)section.string("type");
  return {.case_dir = file.file().parent_path(), .config = &file, .output_dir = out, .resume = false, .quiet = true,
          .quick = true};
}

TEST(TubePriesCase, CommittedCaseRunsAndSummarises) {
  const fs::path out = fs::temp_directory_path() / "hs_tube_pries_case";
  fs::remove_all(out);
  auto file = hs::common::ConfigFile::load(fs::path(HS_SOURCE_DIR) / "cases/unresolved/tube-pries/case.toml");
  EXPECT_EQ(hs::unresolved::run_tube_pries(pries_request(*file, out)), 0);
  std::ifstream in(out / "summary.json");
  const auto s = nlohmann::json::parse(in);
  EXPECT_TRUE(s["groups"].contains("channel_reynolds"));
  const auto& res = s["results"];
  for (const char* key : {"discharge_hematocrit", "relative_apparent_viscosity", "pries_discharge_hematocrit",
                          "pries_relative_apparent_viscosity", "ht_d_error_pct", "mu_rel_error_pct", "end_time_s",
                          "stopped_when_steady", "pair_contacts_at_end", "wall_contacts_at_end"}) {
    EXPECT_TRUE(res.contains(key)) << key;
  }
  // Physical bounds, not accuracy (the quick run is 20 steps): 0 < Ht_d < 1, and cells released at rest in a fluid
  // made more viscous by them can only slow the flow against the plasma-only run of the same 20 steps: mu_rel > 1.
  EXPECT_GT(res["discharge_hematocrit"].get<double>(), 0.0);
  EXPECT_LT(res["discharge_hematocrit"].get<double>(), 1.0);
  EXPECT_GT(res["relative_apparent_viscosity"].get<double>(), 1.0);
  // The reference is Pries 1992 at this tube and the insertion's achieved Ht_T, through the law that
  // tests/analysis/pries1992_test checks against the published grid.
  const double d_um = res["diameter_um"].get<double>();
  const double ht_d_pries = hs::analysis::discharge_from_tube_hematocrit(d_um, res["tube_hematocrit"].get<double>());
  EXPECT_NEAR(res["pries_discharge_hematocrit"].get<double>(), ht_d_pries, 1e-12);
  EXPECT_NEAR(res["pries_relative_apparent_viscosity"].get<double>(), hs::analysis::relative_apparent_viscosity(d_um, ht_d_pries), 1e-12);
  EXPECT_TRUE(fs::exists(out / "timeseries.csv"));
}

std::string pries_case(const std::string& hematocrit, const std::string& drag, const std::string& n_coupling) {
  return hs::test::short_tube_case(hematocrit, "drag = \"" + drag + "\"\n", n_coupling, "2e-3");
}

void expect_config_error(const std::string& text, const std::string& key) {
  auto file = hs::common::ConfigFile::parse(text, "case.toml");
  (void)file->root().section("case").string("type");
  try {
    (void)hs::unresolved::parse_tube_pries(*file, false);
    ADD_FAILURE() << "no ConfigError for " << key;
  } catch (const hs::common::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

TEST(TubePriesCase, BadInputsNameTheKey) {
  expect_config_error(pries_case("0.10", "no_such_drag", "125"), "drag");          // unknown closure
  expect_config_error(pries_case("0.80", "stokes", "125"), "tube_hematocrit");     // above random close packing
  expect_config_error(pries_case("0.10", "stokes", "1"), "n_coupling");            // DEM step 10x too large
  std::string wall = pries_case("0.10", "stokes", "125");
  wall.replace(wall.find("[numerics]"), 10, "wall_correction = \"faxen\"\n[numerics]");
  expect_config_error(wall, "wall_correction");                                     // unknown confinement correction
  std::string range = pries_case("0.10", "stokes", "125");
  range.replace(range.find("[numerics]"), 10, "outside_validity = \"wrap\"\n[numerics]");
  expect_config_error(range, "outside_validity");   // neither clamp nor extrapolate
  std::string visc = pries_case("0.10", "stokes", "125");
  visc.replace(visc.find("[numerics]"), 10, "suspension_viscosity = \"quemada\"\n[numerics]");
  expect_config_error(visc, "suspension_viscosity");   // not one of none, einstein, pries_bulk
  std::string fine = pries_case("0.10", "stokes", "125");
  fine.replace(fine.find("[numerics]"), 10, "self_induced_correction = true\n[numerics]");
  expect_config_error(fine, "self_induced_correction");   // d_p 5.6 um > dx 3 um: the correction is for point particles
}

TEST(TubePriesCase, ImpossibleHematocritForThisTubeIsAConfigError) {
  // 0.6 is allowed by the parser but cannot be inserted without overlaps in a 30 um tube (FCC capacity ~0.5 here).
  auto file = hs::common::ConfigFile::parse(pries_case("0.60", "stokes", "125"), "case.toml");
  (void)file->root().section("case").string("type");
  const auto c = hs::unresolved::parse_tube_pries(*file, true);
  EXPECT_THROW((void)hs::unresolved::simulate_tube_pries(c, [](const auto&) {}), hs::common::ConfigError);
}

TEST(TubePriesCase, LearnedClosureFilesRunThroughTheSamePath) {
  const fs::path synthetic = fs::path(HS_SOURCE_DIR) / "data/closures/synthetic";
  auto file = hs::common::ConfigFile::parse(pries_case("0.05", (synthetic / "drag_coefficient/cd_di_rep.toml").string(), "125"),
                                            "case.toml");
  (void)file->root().section("case").string("type");
  auto c = hs::unresolved::parse_tube_pries(*file, true);
  c.deformation = hs::unresolved::closure_spec_from((synthetic / "deformation_index/di_gamma_ur.toml").string());
  c.lift = hs::unresolved::closure_spec_from((synthetic / "lift_coefficient/cl_di_rep.toml").string());
  const auto r = hs::unresolved::simulate_tube_pries(c, [](const auto&) {});
  EXPECT_TRUE(std::isfinite(r.ht_d));
  EXPECT_TRUE(std::isfinite(r.mu_rel));
  EXPECT_NE(r.summary["numerics"]["drag"].get<std::string>().find("cd_di_rep.toml"), std::string::npos);
}

}  // namespace
