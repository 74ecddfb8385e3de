// SPDX-License-Identifier: MIT
// The open-geometry case (any shape between named openings) on the CFD-DEM skeleton: the committed Y bifurcation runs
// (--quick) with per-opening counters, exact bookkeeping and frames; bad openings, hematocrits and an open STL each
// give a ConfigError naming the file's key; a run that claims a scale ([check] min_cells_passed) fails below it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"
#include "unresolved/cases/open_geometry.hpp"
#include "unresolved/cases/open_geometry_measurement.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kCase = fs::path(HS_SOURCE_DIR) / "cases/unresolved/y-bifurcation/case.toml";

std::string committed_text() {
  std::ifstream in(kCase);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The committed case with `from` replaced by `to` (which must occur).
std::string edited(const std::string& from, const std::string& to) {
  std::string text = committed_text();
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The ConfigError of parsing `text`, or "" when it parses.
std::string parse_error(const std::string& text) {
  try {
    auto file = hs::common::ConfigFile::parse(text, kCase.string());
    (void)file->root().section("case").string("type");
    (void)hs::unresolved::parse_open_geometry(*file, false);
  } catch (const hs::common::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(OpenGeometryCase, CommittedBifurcationRunsWithCountersAndFrames) {
  const fs::path out = fs::temp_directory_path() / "hs_open_geometry_case";
  fs::remove_all(out);
  auto file = hs::common::ConfigFile::load(kCase);
  (void)file->root().section("case").string("type");
  const hs::common::CaseRequest request{.case_dir = file->file().parent_path(), .config = file.get(), .output_dir = out,
                                        .resume = false, .quiet = true, .quick = true};
  // --quick: the bookkeeping check runs, the steady-state ones are skipped (not failed).
  EXPECT_EQ(hs::unresolved::run_open_geometry(request), 0);
  const auto table = hs::common::read_csv(out / "timeseries.csv");
  for (const char* column : {"inlet_cells_in", "inlet_fluid_flux_m3_s", "upper_cells_out", "upper_fluid_flux_m3_s",
                             "lower_rbc_flux_m3_s", "domain_hematocrit", "mean_di", "bookkeeping_error"}) {
    EXPECT_EQ(table.column(column).size(), 20u) << column;
  }
  EXPECT_GT(table.column("inlet_cells_in").back(), 0.0);   // cells came in within 20 steps
  std::ifstream summary_file(out / "summary.json");
  const auto s = nlohmann::json::parse(summary_file);
  EXPECT_TRUE(s["results"]["bookkeeping_exact_every_step"].get<bool>());
  ASSERT_EQ(s["results"]["openings"].size(), 3u);
  EXPECT_EQ(s["results"]["openings"][0]["name"], "inlet");   // names sorted
  EXPECT_TRUE(s["timings"].contains("cells_in_out"));
  EXPECT_TRUE(s["groups"].contains("channel_reynolds"));
  EXPECT_TRUE(fs::exists(out / "particles.pvd"));
  EXPECT_TRUE(fs::exists(out / "fields.pvd"));
  fs::remove_all(out);
}

TEST(OpenGeometryCase, BadOpeningsAndHematocritsNameTheirKey) {
  EXPECT_EQ(parse_error(committed_text()), "");
  struct Case {
    std::string from, to, key;
  };
  const Case cases[] = {
      {"discharge_hematocrit = 0.20", "", "discharge_hematocrit"},
      {"discharge_hematocrit = 0.20", "discharge_hematocrit = 0.7", "discharge_hematocrit"},
      {"radius_m = 12e-6\npressure_Pa = 0.0\n\n[openings.lower]",
       "radius_m = 12e-6\npressure_Pa = 0.0\ndischarge_hematocrit = 0.2\n\n[openings.lower]", "discharge_hematocrit"},
      // Between the daughters: wall material, not an opening.
      {"centre_m = [120e-6, 34.6410162e-6, 0.0]", "centre_m = [120e-6, 0.0, 0.0]", "centre_m"},
      {"radius_m = 12e-6\npressure_Pa = 0.0\n\n[openings.lower]", "radius_m = 12e-6\n\n[openings.lower]", "pressure_Pa"},
  };
  for (const Case& c : cases) {
    const std::string error = parse_error(edited(c.from, c.to));
    ASSERT_NE(error, "") << "no ConfigError for " << c.to;
    EXPECT_NE(error.find("case.toml"), std::string::npos) << error;
    EXPECT_NE(error.find(c.key), std::string::npos) << error;
  }
  // No pressure outlet: both daughters take half the inflow, which balances, but the CFD-DEM needs one.
  std::string shares = committed_text();
  for (auto at = shares.find("pressure_Pa = 0.0"); at != std::string::npos; at = shares.find("pressure_Pa = 0.0")) {
    shares.replace(at, 17, "flow_fraction = 0.5");
  }
  const std::string error = parse_error(shares);
  EXPECT_NE(error.find("[openings.upper] flow_fraction"), std::string::npos) << error;
  EXPECT_NE(error.find("pressure_Pa"), std::string::npos) << error;
}

TEST(OpenGeometryCase, OpenStlSurfaceIsRefused) {
  const fs::path dir = fs::temp_directory_path() / "hs_open_geometry_stl";
  fs::create_directories(dir);
  // One triangle: every edge belongs to one triangle only.
  std::ofstream(dir / "open.stl") << "solid open\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1e-5 0 0\n"
                                     "vertex 0 1e-5 0\nendloop\nendfacet\nendsolid open\n";
  std::string text = committed_text();
  const auto begin = text.find("shape = \"bifurcation\"");
  const auto end = text.find("[domain]");
  text.replace(begin, end - begin, "shape = \"stl\"\nfile = \"" + (dir / "open.stl").string() + "\"\n\n");
  const std::string error = parse_error(text);
  EXPECT_NE(error.find("closed"), std::string::npos) << error;
  fs::remove_all(dir);
}

TEST(OpenGeometryCase, TheScaleCheckFailsBelowItsCellCountAndIsSkippedWithQuick) {
  auto file = hs::common::ConfigFile::load(fs::path(HS_SOURCE_DIR) /
                                           "cases/unresolved/stenosis/throat-85um-paper-scale/case.toml");
  (void)file->root().section("case").string("type");
  hs::unresolved::OpenGeometryConfig c = hs::unresolved::parse_open_geometry(*file, false);
  EXPECT_EQ(c.min_cells_passed, 100000);
  // A steady, balanced run's results with `removed` cells out: only the scale check can fail.
  const auto verdict = [&](long removed, bool quick) {
    c.quick = quick;
    const nlohmann::json results{{"bookkeeping_exact_every_step", true}, {"cells_injected", removed + 4000},
                                 {"cells_removed", removed}, {"cells_present", 4000}, {"residence_times", 23.0},
                                 {"injected_over_owed", 1.0}, {"fluid_balance_pct", 0.0},
                                 {"domain_hematocrit_halves", {0.037, 0.037}},
                                 // 5 cells back out of the inlet: they do not count as passed
                                 {"openings", {{{"condition", "flow_rate_inlet"}, {"cells_out", 5}},
                                               {{"condition", "pressure_outlet"}, {"cells_out", removed - 5}}}}};
    hs::common::CheckList checks;
    hs::unresolved::check_open_geometry(c, results, checks);
    return checks.exit_code();
  };
  EXPECT_EQ(verdict(100005, false), 0);
  EXPECT_EQ(verdict(100004, false), 1);
  EXPECT_EQ(verdict(10, true), 0);   // --quick: skipped, not failed
  EXPECT_NE(parse_error(edited("[numerics]", "[check]\nmin_cells_passed = -1\n\n[numerics]")).find("min_cells_passed"),
            std::string::npos);
}

}  // namespace
