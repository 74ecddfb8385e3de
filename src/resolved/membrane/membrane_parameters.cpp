// SPDX-License-Identifier: MIT
// Reading [membrane]: mesh choice, material moduli and npFEM settings, all checked.
#include "resolved/membrane/membrane_parameters.hpp"

#include <fmt/format.h>

#include "resolved/membrane/mesh_io.hpp"
#include "resolved/membrane/mesh_quality.hpp"

namespace hs::resolved {
namespace {

MembraneParameters parse_material(hs::common::ConfigSection& s) {
  const MembraneParameters d;
  MembraneParameters p;
  p.shear_modulus_N_m = s.positive_or("shear_modulus_N_m", d.shear_modulus_N_m);
  // The neo-Hookean law resists area change by itself (K_s = 3 G_s at small strain): the Skalak law's hardening and
  // area penalty do not apply, and the whole-membrane area term is off unless asked for.
  p.law = s.one_of_or("law", {"npfem_skalak", "neo_hookean"}, "npfem_skalak") == "neo_hookean" ? InPlaneLaw::neo_hookean
                                                                                              : InPlaneLaw::npfem_skalak;
  if (p.law == InPlaneLaw::neo_hookean) {
    for (const char* key : {"strain_hardening_ratio", "area_modulus_N_m"}) {
      if (s.has(key)) s.fail(key, "applies to law = \"npfem_skalak\" (the neo-Hookean law has the shear modulus alone)");
    }
    p.strain_hardening_ratio = 0.0;
    p.area_modulus_N_m = 0.0;
  } else {
    p.strain_hardening_ratio = s.non_negative_or("strain_hardening_ratio", d.strain_hardening_ratio);
    p.area_modulus_N_m = s.positive_or("area_modulus_N_m", d.area_modulus_N_m);
  }
  p.global_area_modulus_N_m = s.non_negative_or(
      "global_area_modulus_N_m", p.law == InPlaneLaw::neo_hookean ? 0.0 : d.global_area_modulus_N_m);
  p.bending_modulus_J = s.positive_or("bending_modulus_J", d.bending_modulus_J);
  p.volume_modulus_Pa = s.positive_or("volume_modulus_Pa", d.volume_modulus_Pa);
  p.density_kg_m3 = s.positive_or("density_kg_m3", d.density_kg_m3);
  p.rayleigh_beta_s = s.non_negative_or("rayleigh_beta_s", d.rayleigh_beta_s);
  // The membrane's dissipation: the friction against non-rigid motion (the default, the campaign's), or the membrane
  // viscosity (chosen by `dissipation` or by giving viscosity_N_s_m), with friction 0 unless given as well.
  const bool viscous =
      s.one_of_or("dissipation", {"friction", "viscosity"}, s.has("viscosity_N_s_m") ? "viscosity" : "friction") ==
      "viscosity";
  if (!viscous && s.has("viscosity_N_s_m")) {
    s.fail("viscosity_N_s_m", "applies to dissipation = \"viscosity\" (remove it, or set dissipation = \"viscosity\")");
  }
  p.viscosity_N_s_m = viscous ? s.non_negative_or("viscosity_N_s_m", kMembraneViscosityHochmuth1979_N_s_m) : 0.0;
  p.deformation_friction_Pa_s_m =
      s.non_negative_or("deformation_friction_Pa_s_m", viscous ? 0.0 : d.deformation_friction_Pa_s_m);
  return p;
}

NpfemSettings parse_solver(hs::common::ConfigSection& s) {
  const NpfemSettings d;
  NpfemSettings n;
  const std::string it = s.one_of_or("iteration", {"lbfgs", "projective_dynamics"}, "lbfgs");
  n.iteration = it == "lbfgs" ? NpfemIteration::lbfgs : NpfemIteration::projective_dynamics;
  n.lbfgs_history = static_cast<int>(s.integer_in_or("lbfgs_history", 1, 50, d.lbfgs_history));
  n.max_iterations = static_cast<int>(s.integer_in_or("max_iterations", 1, 100000, d.max_iterations));
  n.gradient_tolerance = s.positive_or("gradient_tolerance", d.gradient_tolerance);
  n.line_search_halvings = static_cast<int>(s.integer_in_or("line_search_halvings", 0, 30, d.line_search_halvings));
  n.area_proxy_fraction = s.number_in_or("area_proxy_fraction", 0.01, 1.0, d.area_proxy_fraction);
  n.viscous_proxy_refresh_steps =
      static_cast<int>(s.integer_in_or("viscous_proxy_refresh_steps", 1, 1000, d.viscous_proxy_refresh_steps));
  return n;
}

}  // namespace

double shape_relaxation_time_s(const MembraneParameters& m, double length_m) {
  return (m.deformation_friction_Pa_s_m * length_m * length_m + m.viscosity_N_s_m) / m.shear_modulus_N_m;
}

MembraneConfig parse_membrane_config(hs::common::ConfigSection& section) {
  MembraneConfig c;
  section.forbid_together("mesh_file", "vertices", "the mesh is either read from a file or generated");
  if (section.has("mesh_file")) {
    c.mesh_file = section.file_path("mesh_file");
    c.mesh_file_length_unit_m = section.positive_or("mesh_file_length_unit_m", 1.0);
  } else {
    c.mesh.vertex_count = static_cast<int>(section.integer_in_or("vertices", 18, 70000, c.mesh.vertex_count));
    if (!is_supported_vertex_count(c.mesh.vertex_count)) {
      section.fail("vertices", "must be 4*4^k+2 (octahedron: 66, 258, 1026) or 10*4^k+2 (icosahedron: 162, 642, 2562)");
    }
    c.mesh.diameter_m = section.positive_or("diameter_m", c.mesh.diameter_m);
    c.mesh.relax_iterations = static_cast<int>(section.integer_in_or("relax_iterations", 0, 10000, c.mesh.relax_iterations));
  }
  // The spectrin network's stress-free shape: the biconcave rest shape (full shape memory, the default) or an oblate
  // spheroid of a given reduced volume (above the biconcave's 0.64; 1 = the sphere), for the generated mesh only.
  const bool oblate =
      section.one_of_or("stress_free_shape", {"biconcave", "oblate_spheroid"}, "biconcave") == "oblate_spheroid";
  if (oblate && c.mesh_file) {
    section.fail("stress_free_shape", "\"oblate_spheroid\" applies to the generated mesh (remove mesh_file or this key)");
  }
  if (!oblate && section.has("stress_free_reduced_volume")) {
    section.fail("stress_free_reduced_volume", "applies to stress_free_shape = \"oblate_spheroid\"");
  }
  if (oblate) {
    c.mesh.stress_free_reduced_volume =
        section.number_in_or("stress_free_reduced_volume", 0.65, 1.0, kStressFreeReducedVolume);
  }
  c.material = parse_material(section);
  c.solver = parse_solver(section);
  return c;
}

TriangleMesh build_membrane_mesh(const MembraneConfig& config) {
  if (config.mesh_file) {
    TriangleMesh mesh = read_mesh_obj(*config.mesh_file, config.mesh_file_length_unit_m);
    validate_mesh(mesh, config.mesh_file->string());
    return mesh;
  }
  TriangleMesh mesh = make_rbc_mesh(config.mesh);
  validate_mesh(mesh, fmt::format("generated RBC mesh ({} vertices)", config.mesh.vertex_count));
  return mesh;
}

}  // namespace hs::resolved
