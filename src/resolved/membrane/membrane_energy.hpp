// SPDX-License-Identifier: MIT
// The npFEM membrane energies (Kotsalos et al. 2019) with their gradients and the constant stiffness proxy.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace hs::resolved {

/// Vertex coordinates, one row per vertex (internal units: micrometres).
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3>;

/// The triangles' in-plane law: Palabos-npFEM's modified Skalak law with its area penalty (the RBC's), or the
/// neo-Hookean law of the capsule benchmarks (Ramanujan & Pozrikidis 1998: W = (G_s/2)(I1 - 1 + 1/(I2 + 1)), area
/// dilation resisted by the law itself, small-strain K_s = 3 G_s).
enum class InPlaneLaw { npfem_skalak, neo_hookean };

/// Moduli in the solver's internal units (um, us, fg; force pN, energy pN um = 1e-18 J).
struct EnergyModuli {
  InPlaneLaw law = InPlaneLaw::npfem_skalak;
  double skalak_lambda_pN_um = 0.0;     // lambda = 4 G_s
  double hardening_mu_pN_um = 0.0;      // mu of the (mu/4)(s - 1)^4 hardening term (npfem_skalak only)
  double area_weight_pN_um = 0.0;       // PD area weight w = 2 K (npfem_skalak only)
  double bending_pN_um = 0.0;           // bending modulus k_c
  double volume_modulus_pN_um2 = 0.0;   // k_V
  double global_area_pN_um = 0.0;       // k_A
};

/// E(x) = sum_T A0 [W(s1, s2) + (w/2) |(s1, s2) - proj_{s1 s2 = 1}|^2]            (triangles)
///      + sum_hinges (k_c c_b / 2) 3/(A0 + A1) (|K x| - |K x_rest|)^2                (bending)
///      + (k_V/2) (V - V0)^2 / V0 + (k_A/2) (A - A0)^2 / A0                          (global)
/// with W(s) = (1/2) sum_i [(mu/4)(s_i - 1)^4 + (lambda/8) s_i^4 - (lambda/4) s_i^2] - W(1, 1) the modified
/// Skalak law of Palabos-npFEM (reference §3.2; small-strain shear modulus lambda/4), s_i the principal
/// stretches of the 2x2 deformation gradient, K the cotangent hinge operator of Bergou et al. 2006 and
/// c_b = 1: sum_hinges 3/(A0 + A1) |K x|^2 approximates integral (2H)^2 dA (on unit spheres we measure 1.015 x 16 pi
/// for icosphere meshes and 1.12 x 16 pi for octahedron meshes; tested), so the bending term is the Helfrich energy
/// (k_c/2) integral (2H - 2H_rest)^2 dA with the rest shape as spontaneous curvature.
/// With InPlaneLaw::neo_hookean the triangle term is A0 (G_s/2)(s1^2 + s2^2 + 1/(s1 s2)^2 - 3), G_s = lambda/4, and
/// carries no area penalty.
class MembraneEnergy {
 public:
  MembraneEnergy(const Positions& rest_um, std::vector<std::array<int, 3>> triangles, const EnergyModuli& moduli);
  /// The same with the triangles' in-plane reference (the spectrin network's stress-free shape, vertex by vertex)
  /// apart from the rest shape, which keeps the bending (spontaneous curvature) and the volume and area targets.
  MembraneEnergy(const Positions& rest_um, const Positions& stress_free_um, std::vector<std::array<int, 3>> triangles,
                 const EnergyModuli& moduli);

  /// Returns E(x) in pN um and writes dE/dx (pN) into `gradient` (resized to x's shape).
  double evaluate(const Positions& x, Positions& gradient);
  /// L = sum_c w_c A_c^T A_c (n x n, same for x, y, z): the PD Laplacian of the triangle and bending terms,
  /// with the hyperelastic term at weight (lambda + mu)/2 and the area term at `area_fraction` of its weight
  /// (1 for the Rayleigh damping matrix; less for the Hessian proxy, see NpfemSettings::area_proxy_fraction).
  [[nodiscard]] Eigen::SparseMatrix<double> stiffness_proxy(double area_fraction = 1.0) const;

  [[nodiscard]] double volume(const Positions& x) const;
  [[nodiscard]] double area(const Positions& x) const;
  /// Gradients of the enclosed volume and of the area at x (for the rank-2 proxy of the global terms).
  void volume_area_gradients(const Positions& x, Positions& grad_volume, Positions& grad_area) const;
  [[nodiscard]] double rest_volume() const { return rest_volume_; }
  [[nodiscard]] double rest_area() const { return rest_area_; }
  [[nodiscard]] const EnergyModuli& moduli() const { return moduli_; }
  [[nodiscard]] const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }
  /// Bending normalisation c_b (see class comment).
  static constexpr double bending_normalisation = 1.0;

 private:
  struct TriangleRest {
    Eigen::Matrix2d r0_inv;   // inverse of the rest edge matrix in the triangle's own 2-D frame
    double area0;
  };
  struct Hinge {
    std::array<int, 4> v;     // edge (v0, v1), opposite vertices v2, v3
    Eigen::Vector4d k;        // cotangent weights at rest
    double weight;            // k_c c_b 3/(A0 + A1)
    double rest_norm;         // |K x_rest|
  };
  double triangle_terms(const Positions& x, Positions& gradient) const;
  double bending_terms(const Positions& x, Positions& gradient) const;
  double global_terms(const Positions& x, Positions& gradient);
  void build_hinges(const Positions& rest_um);

  std::vector<std::array<int, 3>> triangles_;
  std::vector<TriangleRest> rest_;
  std::vector<Hinge> hinges_;
  EnergyModuli moduli_;
  int vertex_count_;
  double rest_volume_ = 0.0;
  double rest_area_ = 0.0;
  Positions grad_volume_;
  Positions grad_area_;
};

}  // namespace hs::resolved
