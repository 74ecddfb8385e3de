// SPDX-License-Identifier: MIT
// A committed closure set named in a case (`drag = "resolved"`) is the same closure as its file named by path.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "closures/named_closure_set.hpp"
#include "closures/register_builtin.hpp"
#include "common/errors.hpp"

namespace fs = std::filesystem;
namespace hc = hs::closures;

namespace {

const fs::path kResolved = fs::path(HS_SOURCE_DIR) / "data/closures/resolved";
// Inside each committed closure's [validity] box (gamma+ 0.02-0.35, u_r+ -0.055..-0.016, DI 0.484-0.512, Re_p
// 0.0057-0.054, shear ratio 0.093-0.61): the same formula on the same inputs, so by name and by path agree exactly.
const hc::ClosureInputs kInside{.re_p = 0.02, .shear_ratio = 0.3, .gamma_plus = 0.2, .u_r_plus = -0.03, .di = 0.49};

}  // namespace

TEST(NamedClosureSet, ResolvedNamesTheCommittedFiles) {
  EXPECT_EQ(hc::named_closure_file("resolved", hc::ClosureKind::drag), kResolved / "drag_coefficient/cd_di_rep.toml");
  EXPECT_EQ(hc::named_closure_file("resolved", hc::ClosureKind::lift),
            kResolved / "lift_coefficient/cl_shear_ratio_rep.toml");
  EXPECT_EQ(hc::named_closure_file("resolved", hc::ClosureKind::deformation),
            kResolved / "deformation_index/di_gamma_ur.toml");
}

TEST(NamedClosureSet, ByNameEqualsByPath) {
  const auto by_name = hc::make_drag_closure({.model = "resolved", .file = {}});
  const auto by_path = hc::make_drag_closure({.model = "expression", .file = kResolved / "drag_coefficient/cd_di_rep.toml"});
  EXPECT_EQ(by_name->drag_coefficient(kInside), by_path->drag_coefficient(kInside));
  EXPECT_GT(by_name->drag_coefficient(kInside), 0.0);
  const auto lift = hc::make_lift_closure({.model = "resolved", .file = {}});
  EXPECT_EQ(lift->lift_coefficient(kInside),
            hc::make_lift_closure({.model = "expression", .file = kResolved / "lift_coefficient/cl_shear_ratio_rep.toml"})
                ->lift_coefficient(kInside));
  const auto di = hc::make_deformation_closure({.model = "resolved", .file = {}});
  EXPECT_EQ(di->deformation_index(kInside),
            hc::make_deformation_closure({.model = "expression", .file = kResolved / "deformation_index/di_gamma_ur.toml"})
                ->deformation_index(kInside));
}

TEST(NamedClosureSet, ResolveTurnsTheNameIntoItsFileAndLeavesOthers) {
  const auto spec = hc::resolve_closure_set({.model = "resolved", .file = {}, .outside = hc::OutsideValidity::extrapolate},
                                            hc::ClosureKind::lift);
  EXPECT_EQ(spec.model, "expression");
  EXPECT_EQ(spec.file, kResolved / "lift_coefficient/cl_shear_ratio_rep.toml");
  EXPECT_EQ(spec.outside, hc::OutsideValidity::extrapolate);
  EXPECT_EQ(hc::resolve_closure_set({.model = "schiller_naumann", .file = {}}, hc::ClosureKind::drag).model, "schiller_naumann");
}

TEST(NamedClosureSet, UnknownNamesListTheSet) {
  try {
    (void)hc::make_drag_closure({.model = "resolvd", .file = {}});
    FAIL() << "an unknown closure name must be refused";
  } catch (const hs::common::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("resolved"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)hc::named_closure_file("synthetic-not-registered", hc::ClosureKind::drag), hs::common::ConfigError);
}

// An installed hemoscale finds the sets away from the source tree (#31): $HS_DATA_DIR first, then
// share/hemoscale/data beside bin/, then the tree; a set found nowhere names every folder looked in.
TEST(NamedClosureSet, DataDirFromTheEnvironmentComesFirstAndMissingSetsSayWhereTheyWereLookedFor) {
  const fs::path data = fs::temp_directory_path() / "hs_named_set_data";
  fs::remove_all(data);
  fs::create_directories(data / "closures/resolved/drag_coefficient");
  fs::copy_file(kResolved / "drag_coefficient/cd_di_rep.toml", data / "closures/resolved/drag_coefficient/cd_di_rep.toml");
  ::setenv("HS_DATA_DIR", data.c_str(), 1);
  const auto dirs = hc::closure_data_dirs();
  ASSERT_EQ(dirs.size(), 3U);
  EXPECT_EQ(dirs[0], data);
  EXPECT_EQ(dirs[1].filename(), "data");   // PREFIX/share/hemoscale/data beside the executable's folder
  EXPECT_EQ(dirs[2], kResolved.parent_path().parent_path());
  EXPECT_EQ(hc::named_closure_file("resolved", hc::ClosureKind::drag), data / "closures/resolved/drag_coefficient/cd_di_rep.toml");
  try {
    (void)hc::closure_set_dir("no-such-set");
    FAIL() << "a set found nowhere must be refused";
  } catch (const hs::common::ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find((data / "closures/no-such-set").string()), std::string::npos) << m;
    EXPECT_NE(m.find((kResolved.parent_path() / "no-such-set").string()), std::string::npos) << m;
    EXPECT_NE(m.find("HS_DATA_DIR"), std::string::npos) << m;
  }
  ::unsetenv("HS_DATA_DIR");
  EXPECT_EQ(hc::named_closure_file("resolved", hc::ClosureKind::drag), kResolved / "drag_coefficient/cd_di_rep.toml");
  fs::remove_all(data);
}
