// SPDX-License-Identifier: MIT
// The tube-plasma case: the committed case folder runs, writes its outputs and meets Poiseuille; bad
// inputs are ConfigErrors that name the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "unresolved/cases/tube_plasma.hpp"

namespace {

namespace fs = std::filesystem;

hs::common::CaseRequest request_for(hs::common::ConfigFile& file, const fs::path& out) {
  auto section = file.root().section("case");
  (void)section.string("type");
  return {.case_dir = file.file().parent_path(), .config = &file, .output_dir = out, .resume = false, .quiet = true,
          .quick = false};
}

TEST(TubePlasmaCase, CommittedCaseMeetsPoiseuille) {
  const fs::path out = fs::temp_directory_path() / "hs_tube_plasma_case";
  fs::remove_all(out);
  auto file = hs::common::ConfigFile::load(fs::path(HS_SOURCE_DIR) / "cases/unresolved/tube-plasma/case.toml");
  EXPECT_EQ(hs::unresolved::run_tube_plasma(request_for(*file, out)), 0);
  for (const char* f : {"summary.json", "timeseries.csv", "case.resolved.toml", "units.txt", "log.txt", "fluid.pvd"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  EXPECT_TRUE(fs::exists(out / "vtk/fluid_00000040.vti"));
  std::ifstream in(out / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  // The issue's acceptance band (2%) at the case's 10 cells across.
  EXPECT_LT(std::abs(summary["results"]["flow_rate_error_pct"].get<double>()), 2.0);
  EXPECT_TRUE(summary["passed"].get<bool>());
  EXPECT_TRUE(summary.contains("provenance"));
  EXPECT_GT(summary["groups"]["reynolds"].get<double>(), 0.0);
}

TEST(TubePlasmaCase, BadInputsNameTheKey) {
  const std::string base = R"([case]
type = "tube-plasma"
[geometry]
diameter_m = 20e-6
length_m = LENGTH
[fluid]
density_kg_m3 = 1025.0
kinematic_viscosity_m2_s = 1.2e-6
[flow]
pressure_gradient_Pa_m = -2.0e5
[numerics]
cells_across_diameter = 10
dt_s = DT
end_time_s = 1e-3
)";
  auto make = [&](const std::string& length, const std::string& dt) {
    std::string text = base;
    text.replace(text.find("LENGTH"), 6, length);
    text.replace(text.find("DT"), 2, dt);
    return hs::common::ConfigFile::parse(text, "bad.toml");
  };
  const fs::path out = fs::temp_directory_path() / "hs_tube_plasma_bad";
  auto expect_error = [&](const std::string& length, const std::string& dt, const std::string& key) {
    fs::remove_all(out);
    auto file = make(length, dt);
    try {
      hs::unresolved::run_tube_plasma(request_for(*file, out));
      ADD_FAILURE() << "expected a ConfigError about " << key;
    } catch (const hs::common::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  expect_error("7e-6", "2e-4", "length_m");   // 3.5 cells of 2 um: not a whole number
  expect_error("8e-6", "2e-3", "dt_s");       // Courant 4 at the centreline velocity 4.1 mm/s
}

}  // namespace
