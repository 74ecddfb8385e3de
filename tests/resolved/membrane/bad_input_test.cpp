// SPDX-License-Identifier: MIT
// Bad meshes and bad [membrane] values are ConfigErrors (exit code 2) with a message that says what is wrong.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "resolved/membrane/membrane_parameters.hpp"
#include "resolved/membrane/mesh_quality.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"

using namespace hs::resolved;
using hs::common::ConfigError;

namespace {

std::string validation_error(const TriangleMesh& m) {
  try {
    validate_mesh(m, "cell.obj");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

std::string config_error(const std::string& toml) {
  try {
    auto f = hs::common::ConfigFile::parse(toml, "case.toml");
    auto s = f->root().section("membrane");
    (void)parse_membrane_config(s);
    f->finish();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

/// The material of a [membrane] section (ConfigError on bad input).
MembraneParameters parse(const std::string& toml) {
  auto f = hs::common::ConfigFile::parse(toml, "case.toml");
  auto s = f->root().section_or_empty("membrane");
  const MembraneConfig c = parse_membrane_config(s);
  f->finish();
  return c.material;
}

}  // namespace

TEST(BadMesh, OpenSurfaceIsRejected) {
  TriangleMesh m = make_rbc_mesh({.vertex_count = 66});
  m.triangles.pop_back();
  EXPECT_NE(validation_error(m).find("open surface"), std::string::npos) << validation_error(m);
}

TEST(BadMesh, NonManifoldEdgeIsRejected) {
  TriangleMesh m = make_rbc_mesh({.vertex_count = 66});
  const auto t = m.triangles[0];
  m.vertices_m.push_back({0.0, 0.0, 5e-6});
  m.triangles.push_back({t[1], t[0], m.vertex_count() - 1});   // a third triangle on edge (t0, t1)
  EXPECT_NE(validation_error(m).find("non-manifold"), std::string::npos) << validation_error(m);
}

TEST(BadMesh, InvertedTrianglesAreRejected) {
  TriangleMesh one = make_rbc_mesh({.vertex_count = 66});
  std::swap(one.triangles[3][1], one.triangles[3][2]);
  EXPECT_NE(validation_error(one).find("inverted"), std::string::npos) << validation_error(one);
  TriangleMesh all = make_rbc_mesh({.vertex_count = 66});
  for (auto& t : all.triangles) std::swap(t[1], t[2]);
  EXPECT_NE(validation_error(all).find("inverted mesh"), std::string::npos) << validation_error(all);
}

TEST(BadMesh, DegenerateAndOutOfRangeIndicesAreRejected) {
  TriangleMesh m = make_rbc_mesh({.vertex_count = 66});
  m.triangles[0][0] = 999;
  EXPECT_NE(validation_error(m).find("refers to vertex 999"), std::string::npos);
  TriangleMesh d = make_rbc_mesh({.vertex_count = 66});
  d.vertices_m[d.triangles[0][1]] = d.vertices_m[d.triangles[0][0]];
  EXPECT_FALSE(validation_error(d).empty());
}

TEST(BadMembraneConfig, NonPositiveModuliNameTheKey) {
  EXPECT_NE(config_error("[membrane]\nshear_modulus_N_m = 0.0\n").find("shear_modulus_N_m"), std::string::npos);
  EXPECT_NE(config_error("[membrane]\nshear_modulus_N_m = -5e-6\n").find("shear_modulus_N_m"), std::string::npos);
  EXPECT_NE(config_error("[membrane]\nbending_modulus_J = 0\n").find("bending_modulus_J"), std::string::npos);
  EXPECT_NE(config_error("[membrane]\narea_modulus_N_m = -1\n").find("area_modulus_N_m"), std::string::npos);
  EXPECT_NE(config_error("[membrane]\nvolume_modulus_Pa = 0\n").find("volume_modulus_Pa"), std::string::npos);
  EXPECT_NE(config_error("[membrane]\nvertices = 100\n").find("vertices"), std::string::npos);
  EXPECT_NE(config_error("[membrane]\nshear_modulus = 5e-6\n").find("shear_modulus"), std::string::npos);   // typo
  EXPECT_EQ(config_error("[membrane]\nshear_modulus_N_m = 4e-6\nvertices = 642\n"), "");
}

TEST(MembraneDissipation, FrictionByDefaultViscosityWhenAskedFor) {
  // Without either key: the friction of the campaign, no viscosity (earlier runs unchanged).
  const MembraneParameters legacy = parse("[membrane]\n");
  EXPECT_EQ(legacy.deformation_friction_Pa_s_m, MembraneParameters{}.deformation_friction_Pa_s_m);
  EXPECT_EQ(legacy.viscosity_N_s_m, 0.0);
  // dissipation = "viscosity": Hochmuth et al. 1979's eta_m, friction 0; giving the value alone implies it.
  const MembraneParameters viscous = parse("[membrane]\ndissipation = \"viscosity\"\n");
  EXPECT_EQ(viscous.viscosity_N_s_m, kMembraneViscosityHochmuth1979_N_s_m);
  EXPECT_EQ(viscous.deformation_friction_Pa_s_m, 0.0);
  const MembraneParameters given = parse("[membrane]\nviscosity_N_s_m = 5e-7\n");
  EXPECT_EQ(given.viscosity_N_s_m, 5e-7);
  EXPECT_EQ(given.deformation_friction_Pa_s_m, 0.0);
  const MembraneParameters both = parse("[membrane]\nviscosity_N_s_m = 5e-7\ndeformation_friction_Pa_s_m = 1e3\n");
  EXPECT_EQ(both.deformation_friction_Pa_s_m, 1e3);
  // Contradictions and bad values name the key.
  EXPECT_NE(config_error("[membrane]\ndissipation = \"friction\"\nviscosity_N_s_m = 7e-7\n").find("viscosity_N_s_m"),
            std::string::npos);
  EXPECT_NE(config_error("[membrane]\nviscosity_N_s_m = -1e-7\n").find("viscosity_N_s_m"), std::string::npos);
  EXPECT_NE(config_error("[membrane]\ndissipation = \"viscous\"\n").find("dissipation"), std::string::npos);
}

TEST(MembraneStressFreeShape, BiconcaveByDefaultOblateWhenAskedFor) {
  const auto parse = [](const std::string& toml) {
    auto f = hs::common::ConfigFile::parse(toml, "case.toml");
    auto s = f->root().section("membrane");
    MembraneConfig c = parse_membrane_config(s);
    f->finish();
    return c;
  };
  EXPECT_FALSE(parse("[membrane]\n").mesh.stress_free_reduced_volume.has_value());   // full shape memory
  EXPECT_EQ(parse("[membrane]\nstress_free_shape = \"oblate_spheroid\"\n").mesh.stress_free_reduced_volume,
            kStressFreeReducedVolume);
  const MembraneConfig given =
      parse("[membrane]\nstress_free_shape = \"oblate_spheroid\"\nstress_free_reduced_volume = 0.97\n");
  EXPECT_EQ(given.mesh.stress_free_reduced_volume, 0.97);
  EXPECT_FALSE(build_membrane_mesh(given).stress_free_vertices_m.empty());
  // The reduced volume without the shape, out of range (at or below the biconcave's 0.64), or with a mesh file.
  EXPECT_NE(config_error("[membrane]\nstress_free_reduced_volume = 0.95\n").find("stress_free_reduced_volume"),
            std::string::npos);
  EXPECT_NE(config_error("[membrane]\nstress_free_shape = \"oblate_spheroid\"\nstress_free_reduced_volume = 0.6\n")
                .find("stress_free_reduced_volume"),
            std::string::npos);
  EXPECT_NE(config_error("[membrane]\nstress_free_shape = \"sphere\"\n").find("stress_free_shape"), std::string::npos);
  EXPECT_NE(config_error("[membrane]\nmesh_file = \"cell.obj\"\nstress_free_shape = \"oblate_spheroid\"\n")
                .find("stress_free_shape"),
            std::string::npos);
}

TEST(MembraneLaw, NeoHookeanDropsTheSkalakTermsAndRefusesTheirKeys) {
  EXPECT_EQ(parse("[membrane]\n").law, InPlaneLaw::npfem_skalak);
  const MembraneParameters nh = parse("[membrane]\nlaw = \"neo_hookean\"\n");
  EXPECT_EQ(nh.law, InPlaneLaw::neo_hookean);
  EXPECT_EQ(nh.strain_hardening_ratio, 0.0);
  EXPECT_EQ(nh.global_area_modulus_N_m, 0.0);   // the law resists area change itself
  EXPECT_EQ(parse("[membrane]\nlaw = \"neo_hookean\"\nglobal_area_modulus_N_m = 1e-6\n").global_area_modulus_N_m, 1e-6);
  EXPECT_NE(config_error("[membrane]\nlaw = \"neo_hookean\"\narea_modulus_N_m = 5e-6\n").find("area_modulus_N_m"),
            std::string::npos);
  EXPECT_NE(config_error("[membrane]\nlaw = \"neo_hookean\"\nstrain_hardening_ratio = 1\n").find("strain_hardening_ratio"),
            std::string::npos);
  EXPECT_NE(config_error("[membrane]\nlaw = \"mooney\"\n").find("law"), std::string::npos);
}
