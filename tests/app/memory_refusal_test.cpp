// SPDX-License-Identifier: MIT
// #31 "sizes checked": a case whose lattice cannot fit in memory is refused before anything is allocated or written
// (exit 2, naming the keys and the estimate), with a hint when a length looks like micrometres given as metres.
#include <gtest/gtest.h>

#include "support/run_command.hpp"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

/// A copy of a shipped case folder with one line of its case.toml replaced; the path of the copy.
fs::path edited_case(const std::string& shipped, const std::string& from, const std::string& to,
                     const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("hs_memory_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ostringstream text;
  text << std::ifstream(fs::path(HS_SOURCE_DIR) / shipped / "case.toml").rdbuf();
  const std::string edited = std::regex_replace(text.str(), std::regex(from), to);
  EXPECT_NE(edited, text.str()) << "the line to edit is not in " << shipped;
  std::ofstream(dir / "case.toml") << edited;
  return dir;
}

/// Exit 2 naming the estimate and `key`, with `hint` in the message (an empty hint: no micrometre hint at all).
void expect_refused(const fs::path& dir, const std::string& key, const std::string& hint) {
  const auto r = hs::test::run_hemoscale("run " + dir.string() + " --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("GiB"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(key), std::string::npos) << r.output;
  if (hint.empty()) {
    EXPECT_EQ(r.output.find("micrometres is written"), std::string::npos) << r.output;
  } else {
    EXPECT_NE(r.output.find(hint), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(dir / "runs")) << "a refused run left a run folder";
  fs::remove_all(dir);
}

}  // namespace

TEST(MemoryRefusal, MicrometresGivenAsMetresInTubePoiseuille) {
  // radius_m = 25.0 (micrometres meant): a lattice of ~1e22 nodes.
  expect_refused(edited_case("cases/resolved/tube-poiseuille", "radius_m = 25.0e-6", "radius_m = 25.0", "radius"),
                 "[geometry] radius_m = 25", "25 micrometres is written 25e-6");
}

TEST(MemoryRefusal, MillimetreTubeInTubePoiseuille) {
  // 25.0e-4 m = 2.5 mm (25e-6 meant): 5001^2 x 50 nodes at dx = 1 um, ~0.4 TB, where today's machine has 24 GiB.
  expect_refused(edited_case("cases/resolved/tube-poiseuille", "radius_m = 25.0e-6", "radius_m = 25.0e-4", "mm"),
                 "[geometry] radius_m = 0.0025", "2.5 mm, not cell scale");
}

TEST(MemoryRefusal, NanometreSpacingInShear) {
  // dx_m = 1e-9: 24000 x 24000 x 16000 nodes; no length looks like micrometres, so no hint, but the keys are named.
  expect_refused(edited_case("cases/resolved/shear", "dx_m = 1.0e-6", "dx_m = 1.0e-9", "dx"), "[numerics] dx_m = 1e-09",
                 "");
}

TEST(MemoryRefusal, TubeCellCase) {
  expect_refused(edited_case("cases/resolved/tube-drag", "length_m = 50.0e-6", "length_m = 50.0", "tubecell"),
                 "[geometry] length_m = 50", "50 micrometres is written 50e-6");
}

TEST(MemoryRefusal, OpenGeometryCase) {
  // dx_m = 2e-8 (with dt_s = 2e-6 for the Courant check) over the 120 x 102 x 30 um box: 6000 x 5100 x 1500 cells,
  // ~9e13 bytes.
  expect_refused(edited_case("cases/unresolved/y-bifurcation", "dx_m            = 3e-6[^\n]*\ndt_s            = 2.0e-4",
                             "dx_m = 2e-8\ndt_s = 2e-6", "opengeometry"),
                 "[numerics] dx_m = 2e-08", "");
}

TEST(MemoryRefusal, CfdDemTubeCases) {
  // length_m = 120 (micrometres meant) at 10 cells across a 30 um tube: 4e7 cells along, ~8e12 bytes of grid.
  expect_refused(edited_case("cases/unresolved/tube-open", "length_m += 120e-6", "length_m = 120.0", "tubeopen"),
                 "[geometry] length_m = 120", "120 micrometres is written 120e-6");
  // length_m = 8 (micrometres meant) at 10 cells across a 20 um tube: 4e6 cells along.
  expect_refused(edited_case("cases/unresolved/tube-plasma", "length_m += 8e-6", "length_m = 8.0", "tubeplasma"),
                 "[numerics] cells_across_diameter = 10", "8 micrometres is written 8e-6");
}
