// SPDX-License-Identifier: MIT
// STL import: a cube read back from binary and ASCII files gives exact distances; open, non-manifold
// and inconsistently oriented surfaces are rejected with a message naming the file.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/geometry/shape_from_config.hpp"
#include "common/geometry/stl_shape.hpp"

using namespace hs::common;
namespace fs = std::filesystem;

namespace {

using Tri = std::array<Vec3, 3>;

/// The unit cube [0,1]^3 as 12 outward-oriented triangles.
std::vector<Tri> cube() {
  const Vec3 p[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {0, 4, 7}, {0, 7, 3}};
  std::vector<Tri> out;
  for (const auto& t : f) out.push_back({p[t[0]], p[t[1]], p[t[2]]});
  return out;
}

fs::path write_binary(const std::string& name, const std::vector<Tri>& tris) {
  const auto file = fs::temp_directory_path() / name;
  std::ofstream out(file, std::ios::binary);
  const std::string header(80, ' ');
  out.write(header.data(), 80);
  const auto n = static_cast<std::uint32_t>(tris.size());
  out.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : tris) {
    float rec[12] = {0, 0, 0};
    for (int v = 0; v < 3; ++v) {
      for (int k = 0; k < 3; ++k) rec[3 + 3 * v + k] = static_cast<float>(t[static_cast<std::size_t>(v)][k]);
    }
    out.write(reinterpret_cast<const char*>(rec), 48);
    const std::uint16_t attr = 0;
    out.write(reinterpret_cast<const char*>(&attr), 2);
  }
  return file;
}

fs::path write_ascii(const std::string& name, const std::vector<Tri>& tris) {
  const auto file = fs::temp_directory_path() / name;
  std::ofstream out(file);
  out << "solid cube\n";
  for (const auto& t : tris) {
    out << " facet normal 0 0 0\n  outer loop\n";
    for (const auto& v : t) out << "   vertex " << v.x << ' ' << v.y << ' ' << v.z << '\n';
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid cube\n";
  return file;
}

std::string load_error(const fs::path& file) {
  try {
    StlShape::load(file);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(StlShape, BinaryCubeDistancesAreExact) {
  const auto shape = StlShape::load(write_binary("hs_cube.stl", cube()), 1e-6);   // file in micrometres
  EXPECT_NEAR(shape->signed_distance({0.5e-6, 0.5e-6, 0.5e-6}), -0.5e-6, 1e-18);
  EXPECT_NEAR(shape->signed_distance({0.5e-6, 0.5e-6, 1.5e-6}), 0.5e-6, 1e-18);
  EXPECT_NEAR(shape->signed_distance({2e-6, 2e-6, 2e-6}), std::sqrt(3.0) * 1e-6, 1e-18);   // corner: vertex normal sign
  EXPECT_NEAR(shape->signed_distance({2e-6, 2e-6, 0.5e-6}), std::sqrt(2.0) * 1e-6, 1e-18);  // edge
  EXPECT_NEAR(shape->signed_distance({0.1e-6, 0.2e-6, 0.5e-6}), -0.1e-6, 1e-18);
  EXPECT_EQ(shape->mesh().vertices.size(), 8u);   // welded
}

TEST(StlShape, AsciiCubeAndInwardNormalsAreAccepted) {
  auto tris = cube();
  for (auto& t : tris) std::swap(t[1], t[2]);   // all inward: still a clear closed surface, flipped on load
  const auto shape = StlShape::load(write_ascii("hs_cube_ascii.stl", tris));
  EXPECT_NEAR(shape->signed_distance({0.5, 0.5, 0.25}), -0.25, 1e-12);
  EXPECT_NEAR(shape->signed_distance({-0.5, 0.5, 0.5}), 0.5, 1e-12);
}

TEST(StlShape, OpenSurfaceIsRejected) {
  auto tris = cube();
  tris.pop_back();
  const auto msg = load_error(write_binary("hs_open.stl", tris));
  EXPECT_NE(msg.find("hs_open.stl"), std::string::npos) << msg;
  EXPECT_NE(msg.find("open surface"), std::string::npos) << msg;
}

TEST(StlShape, NonManifoldAndMisorientedSurfacesAreRejected) {
  auto tris = cube();
  tris.push_back(tris.front());   // a third triangle on the same edges
  EXPECT_NE(load_error(write_binary("hs_nonmanifold.stl", tris)).find("non-manifold"), std::string::npos);
  auto flipped = cube();
  std::swap(flipped[3][1], flipped[3][2]);   // one triangle turned over
  EXPECT_NE(load_error(write_binary("hs_flipped.stl", flipped)).find("inconsistently oriented"), std::string::npos);
  EXPECT_NE(load_error("/nonexistent.stl").find("cannot read"), std::string::npos);
}

TEST(ShapeFromConfig, BuildsEachShapeAndRejectsBadKeys) {
  auto f = ConfigFile::parse("[geometry]\nshape = \"tube\"\nradius_m = 25e-6\nlength_m = 50e-6\n", "case.toml");
  const auto tube = shape_from_config(f->root().section("geometry"));
  EXPECT_NEAR(tube->signed_distance({10e-6, 0, 0}), -25e-6, 1e-18);
  EXPECT_NO_THROW(f->finish());
  auto bad = ConfigFile::parse(
      "[geometry]\nshape = \"stenosed-tube\"\nradius_m = 25e-6\nlength_m = 50e-6\nthroat_radius_m = 30e-6\n"
      "constriction_length_m = 1e-5\n",
      "case.toml");
  try {
    (void)shape_from_config(bad->root().section("geometry"));
    FAIL() << "a throat wider than the tube must be rejected";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("[geometry] throat_radius_m"), std::string::npos) << e.what();
  }
  auto bif = ConfigFile::parse(
      "[geometry]\nshape = \"bifurcation\"\nparent_diameter_m = 20e-6\nparent_length_m = 100e-6\n"
      "daughter_diameters_m = [16e-6, 12e-6]\ndaughter_lengths_m = [100e-6, 100e-6]\ndaughter_angles_deg = [0, 60]\n",
      "case.toml");
  EXPECT_TRUE(shape_from_config(bif->root().section("geometry"))->inside({50e-6, 0, 0}));
}

TEST(ShapeFromConfig, AxisZTurnsTheShapeSoThatItsXRunsAlongZ) {
  // A bifurcation whose side branch leaves at +60 deg in the xy-plane: turned, the parent runs along +z and the branch
  // keeps its y. Every point of the turned shape is the original's point (z, y, -x), the bounds likewise.
  const std::string keys =
      "shape = \"bifurcation\"\nparent_diameter_m = 20e-6\nparent_length_m = 100e-6\n"
      "daughter_diameters_m = [16e-6, 12e-6]\ndaughter_lengths_m = [100e-6, 100e-6]\ndaughter_angles_deg = [0, 60]\n";
  auto along_x = ConfigFile::parse("[geometry]\n" + keys, "case.toml");
  auto along_z = ConfigFile::parse("[geometry]\naxis = \"z\"\n" + keys, "case.toml");
  const auto x_shape = shape_from_config(along_x->root().section("geometry"));
  const auto z_shape = shape_from_config(along_z->root().section("geometry"));
  EXPECT_NO_THROW(along_z->finish());
  for (const Vec3 q : {Vec3{50e-6, 0, 0}, Vec3{150e-6, 40e-6, 3e-6}, Vec3{120e-6, -30e-6, 0}, Vec3{50e-6, 0, 9.9e-6}}) {
    const Vec3 p{-q.z, q.y, q.x};
    EXPECT_EQ(z_shape->signed_distance(p), x_shape->signed_distance(q));
  }
  EXPECT_TRUE(z_shape->inside({0, 0, 50e-6}));
  EXPECT_FALSE(z_shape->inside({50e-6, 0, 0}));
  const Box3 bx = x_shape->bounds(), bz = z_shape->bounds();
  EXPECT_EQ(bz.lo.z, bx.lo.x);
  EXPECT_EQ(bz.hi.z, bx.hi.x);
  EXPECT_EQ(bz.lo.x, -bx.hi.z);
  EXPECT_EQ(bz.hi.x, -bx.lo.z);
  EXPECT_EQ(bz.lo.y, bx.lo.y);
  auto bad = ConfigFile::parse("[geometry]\naxis = \"y\"\n" + keys, "case.toml");
  try {
    (void)shape_from_config(bad->root().section("geometry"));
    FAIL() << "axis = \"y\" must be rejected";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("[geometry] axis"), std::string::npos) << e.what();
  }
}
