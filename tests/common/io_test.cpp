// SPDX-License-Identifier: MIT
// VTK and CSV writers: files read back to the values written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "common/io/csv_writer.hpp"
#include "common/io/vtk_image.hpp"
#include "common/io/vtk_polydata.hpp"

namespace fs = std::filesystem;

namespace {
fs::path temp_dir(const char* name) {
  const auto d = fs::temp_directory_path() / ("hs_io_test_" + std::string(name));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}
std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(VtkImage, ReadsBackWhatWasWritten) {
  const auto dir = temp_dir("vti");
  std::vector<double> rho(2 * 3 * 4);
  std::vector<double> u(3 * rho.size());
  for (std::size_t i = 0; i < rho.size(); ++i) rho[i] = 1.0 + 0.01 * static_cast<double>(i);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = -0.5 * static_cast<double>(i);
  hs::common::VtkImage img({2, 3, 4}, {0, 0, 0}, 1e-6);
  img.add_scalar("density", rho, true);
  img.add_vector("velocity_m_s", u);
  img.write(dir / "f.vti");
  EXPECT_EQ(hs::common::read_vti_array(dir / "f.vti", "density"), rho);   // Float64: exact
  const auto back = hs::common::read_vti_array(dir / "f.vti", "velocity_m_s");
  ASSERT_EQ(back.size(), u.size());
  for (std::size_t i = 0; i < u.size(); ++i) EXPECT_FLOAT_EQ(static_cast<float>(back[i]), static_cast<float>(u[i]));
  const auto text = slurp(dir / "f.vti");
  EXPECT_NE(text.find("WholeExtent=\"0 1 0 2 0 3\""), std::string::npos);
}

TEST(VtkPolyData, WritesTrianglesAndSeries) {
  const auto dir = temp_dir("vtp");
  const std::vector<hs::common::Vec3> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::array<int, 3>> tris{{0, 1, 2}};
  hs::common::VtkPolyData poly(pts, tris);
  poly.add_point_scalar("di", std::vector<double>{1, 2, 3});
  poly.write(dir / "m.vtp");
  const auto text = slurp(dir / "m.vtp");
  EXPECT_NE(text.find("NumberOfPoints=\"3\""), std::string::npos);
  EXPECT_NE(text.find("NumberOfPolys=\"1\""), std::string::npos);
  hs::common::PvdSeries series(dir / "m.pvd");
  series.add(0.0, "m.vtp");
  series.add(1e-6, "m.vtp");
  hs::common::PvdSeries resumed(dir / "m.pvd");   // a resumed run reads the series back and continues it
  resumed.add(2e-6, "m.vtp");
  const auto pvd = slurp(dir / "m.pvd");
  EXPECT_NE(pvd.find("timestep=\"2e-06\""), std::string::npos);
  EXPECT_NE(pvd.find("timestep=\"1e-06\""), std::string::npos);
}

TEST(CsvWriter, WritesHeaderRowsAndAppends) {
  const auto dir = temp_dir("csv");
  {
    hs::common::CsvWriter csv(dir / "t.csv", {"time_s", "drag_N"});
    csv.row({0.0, 1.5e-12});
  }
  {
    hs::common::CsvWriter csv(dir / "t.csv", {"time_s", "drag_N"}, true);
    csv.row({1e-6, 2.5e-12});
  }
  const auto t = hs::common::read_csv(dir / "t.csv");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.column("drag_N")[1], 2.5e-12);
}
