// SPDX-License-Identifier: MIT
// The membrane's (surface) shear viscosity: the in-plane Kelvin-Voigt viscous tension of each triangle.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "resolved/membrane/membrane_energy.hpp"

namespace hs::resolved {

/// Kelvin-Voigt membrane viscosity eta_m (Evans & Hochmuth 1976; Barthes-Biesel & Sgaier 1985): the viscous tension of
/// the membrane is tau = 2 eta_m D_dev, with D the in-plane rate of strain and D_dev = D - (tr D / 2) I, so it dissipates
/// 2 eta_m |D_dev|^2 per unit area. Evans & Hochmuth define eta_m by the shear resultant T_s = 2 eta_m V_s, which is this
/// tensor law; with the elastic T_s = 2 G_s eps_s the shape recovers with t_c = eta_m / G_s (Hochmuth et al. 1979).
/// Each triangle is linear: D is uniform on it, computed from its three vertex velocities in its own plane at a frozen
/// geometry (freeze()). So any rigid motion of the frozen geometry, at any orientation, has D = 0 exactly, and the
/// forces of every triangle sum to zero (momentum) with zero torque about the frozen positions (angular momentum).
/// The dilatational viscosity is left out: the stiff area energy (K / G_s = 1000) keeps tr D ~ 0 anyway.
/// Internal units of the npFEM solver: um, us, pN; eta_m in pN us / um (1 N s/m = 1e12 pN us / um).
class MembraneViscosity {
 public:
  MembraneViscosity(std::vector<std::array<int, 3>> triangles, double viscosity_pN_us_um);

  /// Takes each triangle's plane, in-plane frame, area and shape-function gradients from x (one row per vertex).
  void freeze(const Positions& x);
  /// The Rayleigh function R(v) = sum_T eta_m A_T |D_dev(v)|^2 at the frozen geometry (half the dissipation rate
  /// 2 R; pN um / us for v in um / us); adds dR/dv (the negated viscous force, pN) into `gradient` (sized n x 3).
  /// R is quadratic: R(u) / h = h R(u / h) for a displacement u over a step h.
  double rayleigh(const Positions& v, Positions& gradient) const;
  /// The in-plane rate of strain of triangle t at the frozen geometry, in its own orthonormal frame (2 x 2, symmetric).
  [[nodiscard]] Eigen::Matrix2d rate_of_strain(const Positions& v, std::size_t t) const;
  /// R's Hessian at the frozen geometry, times `scale`, appended as 3n x 3n triplets (row and column 3 i + c for
  /// vertex i, coordinate c). Per triangle and vertex pair (a, b) it is eta_m A T [(g_a . g_b) I + g_b g_a^T -
  /// g_a g_b^T] T^T, with T = [t1 t2] the in-plane frame and g the shape-function gradients: stiff in the plane,
  /// zero along the normal, which no per-coordinate (n x n) proxy can represent.
  void append_hessian(double scale, std::vector<Eigen::Triplet<double>>& out) const;
  [[nodiscard]] double viscosity_pN_us_um() const { return eta_; }

 private:
  struct Frozen {
    Eigen::Vector3d t1, t2;   // orthonormal in-plane frame
    Eigen::Vector2d g1, g2;   // in-plane gradients of the shape functions of vertices 1 and 2 (vertex 0: -(g1 + g2))
    double area;
  };
  [[nodiscard]] Eigen::Matrix2d velocity_gradient(const Positions& v, std::size_t t) const;

  std::vector<std::array<int, 3>> triangles_;
  std::vector<Frozen> frozen_;
  double eta_;
};

}  // namespace hs::resolved
