// SPDX-License-Identifier: MIT
// `hemoscale fit` as a user meets it: a fit writes a closure that checks clean; bad files exit with code 2.
#include <gtest/gtest.h>

#include "support/run_command.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace fs = std::filesystem;

namespace {

using Result = hs::test::CommandResult;
Result run(const std::string& args) { return hs::test::run_hemoscale(args); }

fs::path write(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / name;
  std::ofstream(p) << text;
  return p;
}

}  // namespace

TEST(FitCli, FitsTheLiftCaseAndTheClosureChecksClean) {
  const fs::path out = fs::temp_directory_path() / "hs_fit_cli_lift";
  fs::remove_all(out);
  const auto fit = run("fit " + std::string(HS_SOURCE_DIR) + "/cases/regression/synthetic/lift_coefficient/fit.toml --no-plot -q -o " +
                       out.string());
  ASSERT_EQ(fit.code, 0) << fit.output;
  const auto check = run("fit --check " + (out / "cl_di_rep.toml").string());
  EXPECT_EQ(check.code, 0) << check.output;
  EXPECT_NE(check.output.find("reproduces its reference table"), std::string::npos) << check.output;
}

TEST(FitCli, BadClosureFileExitsWithCode2) {
  const auto bad = write("hs_cli_bad_closure.toml",
                         "name = \"x\"\nkind = \"drag\"\noutput = \"C_d\"\nexpression = \"24/re_pp\"\n"
                         "[variables]\nre_p = \"Re_p\"\n[validity]\nre_p = [0.01, 0.1]\n");
  const auto r = run("fit --check " + bad.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("re_pp"), std::string::npos) << r.output;
  const auto no_validity = write("hs_cli_no_validity.toml", "name = \"x\"\nkind = \"drag\"\noutput = \"C_d\"\n"
                                                             "expression = \"24/re_p\"\n[variables]\nre_p = \"Re_p\"\n");
  const auto v = run("fit --check " + no_validity.string());
  EXPECT_EQ(v.code, 2) << v.output;
  EXPECT_NE(v.output.find("validity"), std::string::npos) << v.output;
}

TEST(FitCli, BadFitFileExitsWithCode2) {
  const auto bad = write("hs_cli_bad_fit.toml", "[data]\nfile = \"nope.csv\"\ntarget = \"y\"\nfeatures = [\"x\"]\n"
                                                "[closure]\nname = \"y\"\nkind = \"generic\"\n[search]\npopulaton_size = 10\n");
  const auto r = run("fit " + bad.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("populaton_size"), std::string::npos) << r.output;
}

TEST(FitCli, DerivedFeaturesAreComputedFromTheDatasetColumns) {
  // [data.derived] y2 = "2 * x": a feature the dataset does not have, evaluated per row; y = x^2 + 1 is found in it.
  std::string csv = "x,y\n";
  for (int i = 1; i <= 20; ++i) csv += std::to_string(0.1 * i) + "," + std::to_string(0.01 * i * i + 1.0) + "\n";
  const auto data = write("hs_cli_derived.csv", csv);
  const auto fit = write("hs_cli_derived_fit.toml", "[data]\nfile = \"" + data.string() + "\"\ntarget = \"y\"\n"
                                                    "features = [\"x2\"]\n[data.derived]\nx2 = \"2 * x\"\n"
                                                    "[closure]\nname = \"y\"\nkind = \"generic\"\n"
                                                    "[search]\ngenerations = 5\npopulation_size = 100\nseed = 1\n");
  const fs::path out = fs::temp_directory_path() / "hs_fit_cli_derived";
  fs::remove_all(out);
  const auto r = run("fit " + fit.string() + " --no-plot -q -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream in(out / "y.toml");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("x2 = \"2 * x\""), std::string::npos) << text;   // its definition is its formula
  EXPECT_NE(text.find("expression = \"1 + 0.25*(x2*x2)\""), std::string::npos) << text;   // y = 1 + (x2 / 2)^2
  // A derived feature naming no column is a configuration error, exit code 2.
  const auto bad = write("hs_cli_derived_bad.toml", "[data]\nfile = \"" + data.string() + "\"\ntarget = \"y\"\n"
                                                    "features = [\"x2\"]\n[data.derived]\nx2 = \"2 * z\"\n"
                                                    "[closure]\nname = \"y\"\nkind = \"generic\"\n");
  fs::remove_all(out.string() + "_bad");
  const auto b = run("fit " + bad.string() + " --no-plot -q -o " + (out.string() + "_bad"));
  EXPECT_EQ(b.code, 2) << b.output;
  EXPECT_NE(b.output.find("data.derived"), std::string::npos) << b.output;
}
