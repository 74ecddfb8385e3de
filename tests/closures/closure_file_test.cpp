// SPDX-License-Identifier: MIT
// Closure files: a good file loads and round-trips; every kind of bad file is a ConfigError that says why.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "closures/closure_file.hpp"
#include "closures/expression_drag.hpp"
#include "closures/expression_lift.hpp"
#include "common/errors.hpp"

namespace fs = std::filesystem;
namespace hc = hs::closures;

namespace {

const std::string good = R"toml(name = "cd_test"
kind = "drag"
output = "C_d"
expression = "24/re_p*(1 + 0.5*di)"
[variables]
re_p = "particle Reynolds number"
di = "deformation index"
[validity]
re_p = [0.01, 0.12]
di = [0.1, 0.5]
[fit]
r2_test = 0.99
[pareto]
complexity = [3, 9]
loss = [0.5, 0.0]
cv_loss = [0.6, 0.0]
expressions = ["24/re_p", "24/re_p*(1 + 0.5*di)"]
[provenance]
dataset = "data.csv"
dataset_sha256 = "abc"
seed = 3
)toml";

fs::path write(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("hs_closure_" + name + ".toml");
  std::ofstream(p) << text;
  return p;
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  if (p == std::string::npos) throw std::logic_error("test text not found: " + from);
  return s.replace(p, from.size(), to);
}

std::string error_of(const std::string& name, const std::string& text) {
  try {
    (void)hc::ClosureFile::load(write(name, text));
  } catch (const hs::common::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ClosureFile, GoodFileLoadsAndRoundTrips) {
  const auto c = hc::ClosureFile::load(write("good", good));
  EXPECT_EQ(c.variables, (std::vector<std::string>{"di", "re_p"}));   // sorted by name
  ASSERT_EQ(c.pareto.size(), 2u);
  const fs::path again = fs::temp_directory_path() / "hs_closure_again.toml";
  c.write(again);
  const auto d = hc::ClosureFile::load(again);
  EXPECT_EQ(d.expression, c.expression);
  EXPECT_EQ(d.validity[1].hi, 0.12);
  EXPECT_EQ(d.pareto[1].expression, c.pareto[1].expression);
  EXPECT_EQ(d.seed, 3);
}

TEST(ClosureFile, LiftReferenceVelocityRoundTripsAndIsCheckedAndOnlyForLift) {
  const std::string lift = replaced(replaced(good, "kind = \"drag\"", "kind = \"lift\"\nreference_velocity = \"flow\""),
                                    "output = \"C_d\"", "output = \"C_l\"");
  const auto c = hc::ClosureFile::load(write("lift_flow", lift));
  EXPECT_EQ(c.reference_velocity, "flow");
  const fs::path again = fs::temp_directory_path() / "hs_closure_lift_again.toml";
  c.write(again);
  EXPECT_EQ(hc::ClosureFile::load(again).reference_velocity, "flow");
  EXPECT_EQ(hc::ExpressionLift(again).reference_velocity(), hc::LiftVelocity::flow);
  // Absent: the slip, as Saffman-Mei and the files written before the key existed.
  const auto old = hc::ClosureFile::load(write("lift_old", replaced(good, "kind = \"drag\"", "kind = \"lift\"")));
  EXPECT_EQ(old.reference_velocity, "slip");
  const auto bad = error_of("lift_bad", replaced(lift, "\"flow\"", "\"fluid\""));
  EXPECT_NE(bad.find("reference_velocity"), std::string::npos) << bad;
  const auto drag = error_of("drag_ref", replaced(good, "kind = \"drag\"", "kind = \"drag\"\nreference_velocity = \"flow\""));
  EXPECT_NE(drag.find("reference_velocity"), std::string::npos) << drag;
}

TEST(ClosureFile, TypoInExpressionVariableIsRejected) {
  const auto msg = error_of("typo_expr", replaced(good, "24/re_p*(1", "24/Re_p*(1"));
  EXPECT_NE(msg.find("expression"), std::string::npos) << msg;
  EXPECT_NE(msg.find("Re_p"), std::string::npos) << msg;
}

TEST(ClosureFile, TypoInVariableNameIsRejected) {
  const auto msg = error_of("typo_var", replaced(replaced(good, "re_p = \"particle", "rep = \"particle"),
                                                 "re_p = [0.01", "rep = [0.01"));
  EXPECT_NE(msg.find("rep"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not a closure input"), std::string::npos) << msg;
}

TEST(ClosureFile, MalformedExpressionIsRejected) {
  const auto msg = error_of("malformed", replaced(good, "24/re_p*(1 + 0.5*di)\"", "24/re_p*(1 + 0.5*di\""));
  EXPECT_NE(msg.find("expected ')'"), std::string::npos) << msg;
}

TEST(ClosureFile, MissingValidityIsRejected) {
  const auto no_section = error_of("no_validity", replaced(good, "[validity]\nre_p = [0.01, 0.12]\ndi = [0.1, 0.5]\n", ""));
  EXPECT_NE(no_section.find("validity"), std::string::npos) << no_section;
  const auto no_range = error_of("no_range", replaced(good, "di = [0.1, 0.5]\n", ""));
  EXPECT_NE(no_range.find("[validity] di"), std::string::npos) << no_range;
  const auto reversed = error_of("reversed", replaced(good, "[0.1, 0.5]", "[0.5, 0.1]"));
  EXPECT_NE(reversed.find("lo <= hi"), std::string::npos) << reversed;
}

TEST(ClosureFile, UnknownKeysAndWrongKindAreRejected) {
  EXPECT_NE(error_of("unknown", replaced(good, "[fit]", "colour = 1\n[fit]")).find("colour"), std::string::npos);
  EXPECT_NE(error_of("valid_typo", replaced(good, "di = [0.1", "dii = [0.0, 1.0]\ndi = [0.1")).find("dii"),
            std::string::npos);
  try {
    (void)hc::ExpressionLift(write("kind", good));
    FAIL();
  } catch (const hs::common::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("a lift closure is needed"), std::string::npos) << e.what();
  }
}

TEST(ClosureFileMessages, AMissingClosureFileIsCalledAClosureFile) {
  try {
    (void)hs::closures::ClosureFile::load("/nonexistent/cd.toml");
    FAIL() << "a missing closure file was read";
  } catch (const hs::common::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/cd.toml: no such closure file"), std::string::npos) << e.what();
  }
}
