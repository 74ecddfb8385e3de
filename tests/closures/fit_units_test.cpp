// SPDX-License-Identifier: MIT
// A fit told its columns' SI units searches only dimensionally consistent formulas and records the units in the
// closure file; a wrong unit or a [units] key that names no column is refused with the key in the message.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "closures/closure_file.hpp"
#include "closures/closure_fit.hpp"
#include "common/errors.hpp"
#include "regression/dimension.hpp"

namespace fs = std::filesystem;
namespace hc = hs::closures;
namespace hsr = hs::regression;

namespace {

// Stokes drag F = 3 pi mu d U on SI columns (water-like mu, micrometre spheres, um/s..mm/s speeds).
fs::path write_case(const std::string& name, const std::string& units) {
  const fs::path dir = fs::temp_directory_path() / ("hs_fit_units_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream csv(dir / "dataset.csv");
  csv << "mu,d,U,F\n";
  std::mt19937_64 rng(2);
  auto u = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  for (int i = 0; i < 120; ++i) {
    const double mu = u(1e-3, 4e-3), d = u(2e-6, 8e-6), U = u(1e-5, 1e-3);
    csv << mu << "," << d << "," << U << "," << 3.0 * M_PI * mu * d * U << "\n";
  }
  std::ofstream fit(dir / "fit.toml");
  fit << "[data]\nfile = \"dataset.csv\"\ntarget = \"F\"\nfeatures = [\"mu\", \"d\", \"U\"]\n"
      << "[closure]\nname = \"stokes\"\nkind = \"generic\"\n"
      << "[units]\n" << units
      << "[search]\npopulation_size = 300\ngenerations = 10\nseed = 1\n"
      << "functions = [\"add\", \"sub\", \"mul\", \"div\", \"sqrt\", \"exp\", \"sin\"]\n";
  return dir;
}

}  // namespace

TEST(FitUnits, TheClosureIsConsistentAndRecordsItsUnits) {
  const fs::path dir = write_case("ok", "mu = \"Pa*s\"\nd = \"m\"\nU = \"m/s\"\nF = \"N\"\n");
  const auto request = hc::read_fit_request(dir / "fit.toml");
  ASSERT_EQ(request.search.feature_dimensions.size(), 3u);
  const auto written = hc::run_fit(request, dir / "out", true);
  const auto c = hc::ClosureFile::load(dir / "out" / "stokes.toml");
  EXPECT_EQ(c.units.at("F"), "N");
  EXPECT_EQ(c.units.at("mu"), "Pa*s");
  EXPECT_EQ(c.units.at("U"), "m/s");
  const std::vector<hsr::Dimension> dims{hsr::parse_unit("Pa*s"), hsr::parse_unit("m"), hsr::parse_unit("m/s")};
  EXPECT_TRUE(hsr::check_dimensions(c.parsed(), dims).consistent) << c.expression;
  EXPECT_EQ(written.expression, c.expression);
}

TEST(FitUnits, BadUnitsAreRefusedWithTheirKey) {
  auto message = [](const fs::path& dir) {
    try {
      (void)hc::read_fit_request(dir / "fit.toml");
    } catch (const hs::common::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string unknown = message(write_case("unit", "mu = \"Pa*s\"\nd = \"um\"\nU = \"m/s\"\nF = \"N\"\n"));
  EXPECT_NE(unknown.find("d"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("um"), std::string::npos) << unknown;
  const std::string stray = message(write_case("key", "mu = \"Pa*s\"\nD = \"m\"\n"));
  EXPECT_NE(stray.find("neither the target nor a feature"), std::string::npos) << stray;
}
