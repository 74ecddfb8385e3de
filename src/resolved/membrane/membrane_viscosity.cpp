// SPDX-License-Identifier: MIT
// Membrane shear viscosity: per-triangle in-plane rate of strain, Rayleigh function, viscous forces and a proxy.
#include "resolved/membrane/membrane_viscosity.hpp"

#include <Eigen/Geometry>

namespace hs::resolved {

MembraneViscosity::MembraneViscosity(std::vector<std::array<int, 3>> triangles, double viscosity_pN_us_um)
    : triangles_(std::move(triangles)), frozen_(triangles_.size()), eta_(viscosity_pN_us_um) {}

void MembraneViscosity::freeze(const Positions& x) {
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    const auto& t = triangles_[i];
    const Eigen::Vector3d p0 = x.row(t[0]).transpose();
    const Eigen::Vector3d e1 = x.row(t[1]).transpose() - p0;
    const Eigen::Vector3d e2 = x.row(t[2]).transpose() - p0;
    const Eigen::Vector3d normal = e1.cross(e2);
    Frozen& f = frozen_[i];
    f.area = 0.5 * normal.norm();
    f.t1 = e1.normalized();
    f.t2 = normal.normalized().cross(f.t1);
    // Edge matrix in the frame, E = [(|e1|, 0), (e2.t1, e2.t2)] (columns), upper triangular; grad phi_k = row k-1 of
    // E^-1, since the in-plane gradient of a linear field u is [u1 - u0, u2 - u0] E^-1.
    const double a = e1.norm();
    const double b = e2.dot(f.t1);
    const double c = e2.dot(f.t2);
    f.g1 = {1.0 / a, -b / (a * c)};
    f.g2 = {0.0, 1.0 / c};
  }
}

Eigen::Matrix2d MembraneViscosity::velocity_gradient(const Positions& v, std::size_t t) const {
  const auto& tri = triangles_[t];
  const Frozen& f = frozen_[t];
  const Eigen::Vector3d d1 = (v.row(tri[1]) - v.row(tri[0])).transpose();
  const Eigen::Vector3d d2 = (v.row(tri[2]) - v.row(tri[0])).transpose();
  const Eigen::Vector2d w1{d1.dot(f.t1), d1.dot(f.t2)};   // in-plane components of the velocity differences
  const Eigen::Vector2d w2{d2.dot(f.t1), d2.dot(f.t2)};
  return w1 * f.g1.transpose() + w2 * f.g2.transpose();   // L_ij = d w_i / d xi_j
}

Eigen::Matrix2d MembraneViscosity::rate_of_strain(const Positions& v, std::size_t t) const {
  const Eigen::Matrix2d l = velocity_gradient(v, t);
  return 0.5 * (l + l.transpose());
}

double MembraneViscosity::rayleigh(const Positions& v, Positions& gradient) const {
  double r = 0.0;
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    const auto& t = triangles_[i];
    const Frozen& f = frozen_[i];
    Eigen::Matrix2d d = rate_of_strain(v, i);
    const double mean = 0.5 * d.trace();
    d.diagonal().array() -= mean;   // D_dev
    r += eta_ * f.area * d.squaredNorm();
    // dR/dw_k = A tau g_k with tau = 2 eta D_dev; back to 3-D along the frame.
    const Eigen::Matrix2d tau_a = (2.0 * eta_ * f.area) * d;
    const Eigen::Vector2d q1 = tau_a * f.g1;
    const Eigen::Vector2d q2 = tau_a * f.g2;
    const Eigen::Vector3d f1 = q1[0] * f.t1 + q1[1] * f.t2;
    const Eigen::Vector3d f2 = q2[0] * f.t1 + q2[1] * f.t2;
    gradient.row(t[1]) += f1.transpose();
    gradient.row(t[2]) += f2.transpose();
    gradient.row(t[0]) -= (f1 + f2).transpose();
  }
  return r;
}

void MembraneViscosity::append_hessian(double scale, std::vector<Eigen::Triplet<double>>& out) const {
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    const auto& tri = triangles_[i];
    const Frozen& f = frozen_[i];
    const Eigen::Vector2d g[3] = {-(f.g1 + f.g2), f.g1, f.g2};
    Eigen::Matrix<double, 3, 2> t;
    t << f.t1, f.t2;
    const double w = scale * eta_ * f.area;
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        const Eigen::Matrix2d h2 = w * (g[a].dot(g[b]) * Eigen::Matrix2d::Identity() + g[b] * g[a].transpose() -
                                        g[a] * g[b].transpose());
        const Eigen::Matrix3d block = t * h2 * t.transpose();
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) out.emplace_back(3 * tri[a] + r, 3 * tri[b] + c, block(r, c));
      }
    }
  }
}

}  // namespace hs::resolved
