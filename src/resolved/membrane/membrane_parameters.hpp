// SPDX-License-Identifier: MIT
// Membrane material parameters (SI) and npFEM solver settings, read from a case file's [membrane] section.
#pragma once

#include <filesystem>
#include <optional>

#include "common/config/config_file.hpp"
#include "resolved/membrane/membrane_energy.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"

namespace hs::resolved {

/// RBC membrane (surface) shear viscosity: 7e-7 N s/m, the middle of the 6-8e-7 N s/m of Hochmuth, Worthy & Evans 1979
/// (Biophys J 26:101; extensional recovery of a cell released between two pipettes, t_c = 0.10-0.13 s times their
/// shear modulus 6 uN/m). Other measurements: ~5e-7 (Hochmuth & Hampel 1979, J Rheol 23:669), ~1e-6 (Evans &
/// Hochmuth 1976, Biophys J 16:1); shared/reference/validation/wave2/membrane_and_cytoplasm_viscosity.csv.
inline constexpr double kMembraneViscosityHochmuth1979_N_s_m = 7.0e-7;

/// Reduced volume of the oblate stress-free shape when one is asked for (stress_free_shape = "oblate_spheroid"): 0.95,
/// the default of Amoudruz et al.'s RBC model library (cselab/tRBC-UQ, packages/dpdprops/dpdprops/rbcmesh.py
/// DEFAULT_STRESS_FREE_REDUCED_VOLUME; they ship 0.93-0.97; arXiv 2303.03404 infers the stress-free shape from
/// equilibrium-shape, stretching and relaxation data), a "nearly spherical" network as Peng, Mashayekh & Zhu 2014
/// (JFM 742:96) argue for. The default shape stays the biconcave one (measured: docs/resolved-coupling.md).
inline constexpr double kStressFreeReducedVolume = 0.95;

/// Material of the RBC membrane, SI. Every default names its source.
struct MembraneParameters {
  /// The in-plane law: the RBC's modified Skalak law (below: shear modulus, hardening, area penalty), or neo-Hookean
  /// (`law = "neo_hookean"`: the shear modulus alone, the capsule benchmarks'; no hardening or area penalty).
  InPlaneLaw law = InPlaneLaw::npfem_skalak;
  /// In-plane shear modulus G_s: 2.5 uN/m, the low end of the literature range 2.5-12 uN/m (Evans 1973; Hochmuth &
  /// Waugh 1987; rbc_blood_properties.csv). Palabos-npFEM's own calibration on the Mills experiment amounts to
  /// lambda/4 = 1.25 uN/m (reference §3.2); Mills' 5.3 uN/m (their 3-D FE model) makes this model too stiff
  /// (axial 12.3 um at 193 pN vs the 14.5-18.0 um band). One set for all forces: `hemoscale validate stretching`.
  double shear_modulus_N_m = 2.5e-6;
  /// Strain hardening mu_h / lambda of the modified Skalak law (reference §3.2). Palabos-npFEM ships 7 (lambda = 5,
  /// mu = 35 pN/um), which with G_s >= 2.5 uN/m under-stretches; 0.75 is our global calibration on all 12 loaded
  /// Mills levels at G_s = 2.5 uN/m (0.25-0.5 minimise the RMS deviation from the band mid values equally well).
  double strain_hardening_ratio = 0.75;
  /// Local area-dilation modulus K of the per-triangle area energy: Palabos-npFEM area weight 5000 pN/um
  /// (= 2K, reference §3.2). (The real membrane, ~0.4 N/m, is stiffer; this penalty keeps area within 0.1%.)
  double area_modulus_N_m = 2.5e-3;
  /// Global surface-area modulus: set equal to the local one (same source and reasoning).
  double global_area_modulus_N_m = 2.5e-3;
  /// Bending modulus k_c: 1e-19 J (~25 kBT), the low end of 1e-19..7e-19 J, Evans 1983 (Biophys J 43:27),
  /// rbc_blood_properties.csv.
  double bending_modulus_J = 1.0e-19;
  /// Global volume modulus k_V (energy k_V/2 (V-V0)^2/V0): 330 Pa is what Palabos-npFEM's PBD volume
  /// weight 250 amounts to on the 258-vertex mesh (our conversion, reference §3.2).
  double volume_modulus_Pa = 330.0;
  /// RBC density for the lumped vertex masses (cytoplasm included): 1125 kg/m^3 in Palabos-npFEM (reference §3.1).
  double density_kg_m3 = 1125.0;
  /// Stiffness-proportional Rayleigh damping C = beta L: beta = 0.01 us in Palabos-npFEM flow runs (reference §3.1).
  double rayleigh_beta_s = 1.0e-8;
  /// Friction per unit membrane area against non-rigid (deforming) motion, zeta_A: each vertex's velocity relative
  /// to the rigid-body motion relaxes as m dv/dt = F - zeta_A A_v v (lumped area A_v). Palabos-npFEM applies this as
  /// v += C_alpha (v_rigid - v) with C_alpha = 0.9 per npFEM step (K2019 calibration, reference §3.3 step 6), which
  /// only means something at their step h = 0.25 us and physical density 1125 kg/m^3: that is
  /// zeta_A = C_alpha / (1 - C_alpha) * rho (V / A) / h = 9 * 1125 * 0.697 um / 0.25 us = 2.82e4 Pa s/m (V / A of the
  /// 7.82 um Evans-Fung cell). Stated per area and time, it no longer depends on the step, the lattice spacing or the
  /// numerical mass factor (docs/resolved-coupling.md, "Membrane friction"). 0 gives a purely elastic membrane.
  double deformation_friction_Pa_s_m = 2.82e4;
  /// Membrane shear viscosity eta_m (MembraneViscosity, Kelvin-Voigt, integrated implicitly by npFEM). 0 here: the
  /// friction above is the dissipation of every case that does not ask for the viscosity (the campaign's). A case
  /// with [membrane] dissipation = "viscosity" gets kMembraneViscosityHochmuth1979_N_s_m and friction 0 by default
  /// (docs/resolved-coupling.md, "Membrane viscosity").
  double viscosity_N_s_m = 0.0;
};

/// Kelvin-Voigt time of a shape change over the length L: (zeta_A L^2 + eta_m) / G_s (friction and viscosity in
/// series with the shear modulus; the viscous part is Hochmuth et al. 1979's t_c = eta_m / G_s).
[[nodiscard]] double shape_relaxation_time_s(const MembraneParameters& m, double length_m);

enum class NpfemIteration { lbfgs, projective_dynamics };

/// Numerical settings of the minimisation (not physics: they change speed and residual, not the model).
struct NpfemSettings {
  NpfemIteration iteration = NpfemIteration::lbfgs;   // Liu et al. 2017 quasi-Newton; PD = plain local/global
  int lbfgs_history = 7;                                // Palabos-npFEM default m = 7
  int max_iterations = 30;                              // Palabos-npFEM `max_iterations`
  /// Stop when max_v |grad g|_v <= tolerance * G_s * mean rest edge (the elastic force scale of one vertex).
  double gradient_tolerance = 1.0e-4;
  int line_search_halvings = 5;                         // Palabos-npFEM: alpha = 1, 1/2, ..., 1/32
  /// Weight of the local-area term in the Hessian proxy, as a fraction of its energy weight. The PD proxy w D D^T
  /// is stiff in every in-plane direction, while the area energy only resists area change, so at full weight it
  /// over-damps the soft shear modes; 0.3 measured 40% fewer L-BFGS iterations per step on a loaded 258-vertex cell
  /// (bench npfem). It changes only the preconditioner, never the minimiser (nor the Rayleigh damping matrix).
  double area_proxy_fraction = 0.3;
  /// With membrane viscosity: npFEM steps between refactorisations of the step proxy (ViscousStepProxy) at the
  /// current geometry; 1 = every step. Only the preconditioner ages, the minimiser is the same. Shear Ca = 1 (first
  /// 8 ms, 760 steps, all converged, DI equal to 7 digits): 1, 4, 8, 16 took 5.7, 3.3, 2.9, 2.9 s of CPU with 8.3,
  /// 8.5, 9.0, 10.3 iterations per step (the elastic membrane: 1.5 s). 8 steps turn the cell by ~1 degree there.
  int viscous_proxy_refresh_steps = 8;
};

/// The rest shape a case builds its cell with: the RBC of [membrane], or the subdivided sphere of the same vertex
/// count (a capsule: the stiff-sphere check of the stresslet, the capsule-in-shear benchmark).
enum class CellShapeKind { biconcave, sphere };

/// Everything the [membrane] section describes: mesh, material, solver.
struct MembraneConfig {
  RbcMeshOptions mesh;
  std::optional<std::filesystem::path> mesh_file;        // an .obj instead of the generated mesh
  double mesh_file_length_unit_m = 1.0;
  MembraneParameters material;
  NpfemSettings solver;
};

/// Reads [membrane] (all keys optional, SI). Non-positive moduli etc. throw ConfigError naming the key.
[[nodiscard]] MembraneConfig parse_membrane_config(hs::common::ConfigSection& section);
/// The generated or read mesh, validated (ConfigError for open, non-manifold or inverted meshes).
[[nodiscard]] TriangleMesh build_membrane_mesh(const MembraneConfig& config);

}  // namespace hs::resolved
