// SPDX-License-Identifier: MIT
// ParaView output of tube-pries: particles.pvd/fields.pvd and their frames at [output] vtk_every_s, continued by --resume.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "unresolved/cases/short_tube_case.hpp"
#include "common/config/config_file.hpp"
#include "common/io/vtk_image.hpp"
#include "unresolved/cases/tube_pries.hpp"

namespace {

namespace fs = std::filesystem;

/// A 30 um tube, 10 cells across, 0.2 ms steps; frames every 0.4 ms.
std::string vtk_case(int steps) {
  return hs::test::short_tube_case("0.30", "", "125", std::to_string(2e-4 * steps), "[output]\nvtk_every_s = 4e-4\n");
}

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(TubePriesVtk, FramesAtTheIntervalAndContinuedByResume) {
  const fs::path out = fs::temp_directory_path() / "hs_tube_pries_vtk";
  fs::remove_all(out);
  for (const auto& [steps, resume] : {std::pair{4, false}, std::pair{6, true}}) {
    auto file = hs::common::ConfigFile::parse(vtk_case(steps), "case.toml");
    (void)file->root().section("case").string("type");
    const hs::common::CaseRequest request{.case_dir = fs::temp_directory_path(), .config = file.get(), .output_dir = out,
                                          .resume = resume, .quiet = true, .quick = false};
    (void)hs::unresolved::run_tube_pries(request);   // far from steady: exit 1 by design
  }
  for (const char* series : {"particles", "fields"}) {
    const std::string pvd = slurp(out / (std::string(series) + ".pvd"));
    EXPECT_EQ(pvd.rfind("<?xml", 0), 0u);
    EXPECT_NE(pvd.find("</VTKFile>"), std::string::npos);
    EXPECT_EQ(count(pvd, "<DataSet "), 3) << pvd;   // steps 2, 4 (first run) and 6 (resumed)
    const std::string ext = std::string(series) == "particles" ? ".vtp" : ".vti";
    for (int step : {2, 4, 6}) {
      char name[64];
      std::snprintf(name, sizeof name, "vtk/%s_%07d%s", series, step, ext.c_str());
      EXPECT_NE(pvd.find(name), std::string::npos) << name;
      EXPECT_TRUE(fs::exists(out / name)) << name;
    }
  }
  const std::string vtp = slurp(out / "vtk/particles_0000006.vtp");
  EXPECT_EQ(vtp.rfind("<?xml", 0), 0u);
  EXPECT_NE(vtp.find("</VTKFile>"), std::string::npos);
  for (const char* a : {"radius_m", "velocity_m_s", "force_N", "external_force_N", "drag_force_N", "deformation_index",
                        "inlet_opening"}) {
    EXPECT_NE(vtp.find(std::string("Name=\"") + a + "\""), std::string::npos) << a;
  }
  std::smatch m;
  const std::string sj = slurp(out / "summary.json");
  ASSERT_TRUE(std::regex_search(sj, m, std::regex(R"("rbc_count":\s*(\d+))")));
  EXPECT_NE(vtp.find("NumberOfPoints=\"" + m[1].str() + "\""), std::string::npos);
  const fs::path vti = out / "vtk/fields_0000006.vti";
  EXPECT_NE(slurp(vti).find("</VTKFile>"), std::string::npos);
  const auto eps = hs::common::read_vti_array(vti, "void_fraction");
  const auto ht = hs::common::read_vti_array(vti, "local_hematocrit");
  ASSERT_EQ(eps.size(), 10u * 10u * 10u);
  ASSERT_EQ(hs::common::read_vti_array(vti, "velocity_m_s").size(), 3 * eps.size());
  ASSERT_EQ(hs::common::read_vti_array(vti, "pressure_Pa").size(), eps.size());
  double solid = 0.0;
  for (std::size_t k = 0; k < eps.size(); ++k) {
    EXPECT_NEAR(ht[k], 1.0 - eps[k], 1e-6);
    solid += ht[k];
  }
  EXPECT_GT(solid, 0.0);   // the cells are in the field
  fs::remove_all(out);
}

}  // namespace
