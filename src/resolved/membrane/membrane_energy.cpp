// SPDX-License-Identifier: MIT
// npFEM energies: modified Skalak triangles + PD area, cotangent hinge bending, global volume and area.
#include "resolved/membrane/membrane_energy.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include <Eigen/Geometry>
#include <Eigen/LU>

namespace hs::resolved {
namespace {

using Vec = Eigen::Vector3d;

Vec row(const Positions& x, int i) { return x.row(i).transpose(); }

/// Eigen-decomposition of a symmetric 2x2 matrix: eigenvalues (descending) and eigenvectors as columns.
void sym2_eigen(const Eigen::Matrix2d& c, Eigen::Vector2d& values, Eigen::Matrix2d& vectors) {
  const double half_trace = 0.5 * (c(0, 0) + c(1, 1));
  const double diff = 0.5 * (c(0, 0) - c(1, 1));
  const double r = std::sqrt(diff * diff + c(0, 1) * c(0, 1));
  values = {half_trace + r, half_trace - r};
  if (r < 1e-300) {
    vectors.setIdentity();
    return;
  }
  // First eigenvector (diff + r, c01) (or the equivalent (c01, r - diff) when diff < 0, to avoid cancellation).
  Eigen::Vector2d e = diff >= 0.0 ? Eigen::Vector2d(diff + r, c(0, 1)) : Eigen::Vector2d(c(0, 1), r - diff);
  e.normalize();
  vectors << e[0], -e[1], e[1], e[0];
}

/// Closest point (d1, d2) to (s1, s2) on the hyperbola d1 d2 = 1 (PD area projection), by Newton on d1 = t, started
/// from the first-order projection along the constraint normal (s2, s1) (the stiff area term keeps s1 s2 near 1,
/// so that start is within O((s1 s2 - 1)^2) and two Newton steps reach round-off), or from sqrt(s1/s2) far from it.
Eigen::Vector2d area_projection(double s1, double s2) {
  const double linear = s1 - (s1 * s2 - 1.0) * s2 / (s1 * s1 + s2 * s2);
  double t = linear > 0.5 * std::sqrt(s1 / s2) ? linear : std::sqrt(s1 / s2);
  for (int it = 0; it < 20; ++it) {
    const double inv = 1.0 / t;
    const double d1 = 2.0 * (t - s1) - 2.0 * (inv - s2) * inv * inv;
    const double d2 = 2.0 + 2.0 * inv * inv * inv * inv + 4.0 * (inv - s2) * inv * inv * inv;
    // Away from the hyperbola's vertex d2 > 0; where it is not (both stretches near 2 or more), fall back on the
    // always-positive Gauss-Newton curvature so the step stays finite.
    const double step = d1 / (d2 > 1e-12 ? d2 : 2.0 + 2.0 * inv * inv * inv * inv);
    t = std::max(0.5 * t, t - step);
    if (std::abs(step) < 1e-14 * t) break;   // relative round-off level
  }
  return {t, 1.0 / t};
}

double cot(const Vec& u, const Vec& v) { return u.dot(v) / u.cross(v).norm(); }

}  // namespace

MembraneEnergy::MembraneEnergy(const Positions& rest_um, std::vector<std::array<int, 3>> triangles,
                               const EnergyModuli& moduli)
    : MembraneEnergy(rest_um, rest_um, std::move(triangles), moduli) {}

MembraneEnergy::MembraneEnergy(const Positions& rest_um, const Positions& stress_free_um,
                               std::vector<std::array<int, 3>> triangles, const EnergyModuli& moduli)
    : triangles_(std::move(triangles)), moduli_(moduli), vertex_count_(static_cast<int>(rest_um.rows())) {
  if (stress_free_um.rows() != rest_um.rows()) {
    throw std::invalid_argument("MembraneEnergy: the stress-free shape has another vertex count than the rest shape");
  }
  rest_.reserve(triangles_.size());
  for (const auto& t : triangles_) {
    const Vec e1 = row(stress_free_um, t[1]) - row(stress_free_um, t[0]);
    const Vec e2 = row(stress_free_um, t[2]) - row(stress_free_um, t[0]);
    const Vec u = e1.normalized();
    const Vec w = (e2 - e2.dot(u) * u).normalized();
    Eigen::Matrix2d r0;
    r0 << e1.norm(), e2.dot(u), 0.0, e2.dot(w);
    rest_.push_back({r0.inverse(), 0.5 * e1.cross(e2).norm()});
  }
  build_hinges(rest_um);
  rest_volume_ = volume(rest_um);
  rest_area_ = area(rest_um);
}

void MembraneEnergy::build_hinges(const Positions& rest_um) {
  std::map<std::pair<int, int>, std::pair<int, int>> edge_to_opposite;   // directed edge -> (opposite, triangle)
  for (int i = 0; i < static_cast<int>(triangles_.size()); ++i) {
    const auto& t = triangles_[i];
    for (int k = 0; k < 3; ++k) edge_to_opposite[{t[k], t[(k + 1) % 3]}] = {t[(k + 2) % 3], i};
  }
  for (const auto& [edge, opp] : edge_to_opposite) {
    if (edge.first > edge.second) continue;
    const auto twin = edge_to_opposite.find({edge.second, edge.first});
    if (twin == edge_to_opposite.end()) continue;   // open edge: validate_mesh rejects such meshes
    Hinge h;
    h.v = {edge.first, edge.second, opp.first, twin->second.first};
    const Vec x0 = row(rest_um, h.v[0]), x1 = row(rest_um, h.v[1]), x2 = row(rest_um, h.v[2]), x3 = row(rest_um, h.v[3]);
    const Vec e0 = x1 - x0, e1 = x2 - x0, e2 = x3 - x0, e3 = x2 - x1, e4 = x3 - x1;
    const double c01 = cot(e0, e1), c02 = cot(e0, e2), c03 = cot(-e0, e3), c04 = cot(-e0, e4);
    h.k << c03 + c04, c01 + c02, -c01 - c03, -c02 - c04;
    const double a0 = 0.5 * e0.cross(e1).norm();
    const double a1 = 0.5 * e0.cross(e2).norm();
    h.weight = moduli_.bending_pN_um * bending_normalisation * 3.0 / (a0 + a1);
    h.rest_norm = (h.k[0] * x0 + h.k[1] * x1 + h.k[2] * x2 + h.k[3] * x3).norm();
    hinges_.push_back(h);
  }
}

double MembraneEnergy::evaluate(const Positions& x, Positions& gradient) {
  gradient.setZero(x.rows(), 3);
  return triangle_terms(x, gradient) + bending_terms(x, gradient) + global_terms(x, gradient);
}

double MembraneEnergy::triangle_terms(const Positions& x, Positions& gradient) const {
  const double lam = moduli_.skalak_lambda_pN_um;
  const double mu = moduli_.hardening_mu_pN_um;
  const double w = moduli_.area_weight_pN_um;
  const bool neo_hookean = moduli_.law == InPlaneLaw::neo_hookean;
  const double g = 0.25 * lam;   // G_s
  auto f = [&](double s) {
    const double e2 = (s - 1.0) * (s - 1.0);
    return 0.25 * mu * e2 * e2 + 0.125 * lam * s * s * s * s - 0.25 * lam * s * s;
  };
  auto df = [&](double s) { return mu * (s - 1.0) * (s - 1.0) * (s - 1.0) + 0.5 * lam * (s * s * s - s); };
  const double f_rest = f(1.0);
  double energy = 0.0;
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    const auto& t = triangles_[i];
    const TriangleRest& r = rest_[i];
    const Vec x0 = row(x, t[0]);
    const Vec e1 = row(x, t[1]) - x0;
    const Vec e2 = row(x, t[2]) - x0;
    // 3x2 deformation gradient F = [e1 e2] R0^-1 (R0^-1 is upper triangular: the rest frame has e1 along its axis)
    const Vec f0 = e1 * r.r0_inv(0, 0);
    const Vec f1 = e1 * r.r0_inv(0, 1) + e2 * r.r0_inv(1, 1);
    Eigen::Matrix2d c;
    c << f0.squaredNorm(), f0.dot(f1), f0.dot(f1), f1.squaredNorm();
    Eigen::Vector2d eig;
    Eigen::Matrix2d v;
    sym2_eigen(c, eig, v);
    const double s1 = std::sqrt(std::max(eig[0], 1e-300));
    const double s2 = std::sqrt(std::max(eig[1], 1e-300));
    // dE/dF = F V diag(c_i) V^T with c_i = dE/ds_i / s_i; the vertex forces are dE/dF R0^-T
    double c1 = 0.0, c2 = 0.0;
    if (neo_hookean) {
      const double j2 = 1.0 / (s1 * s1 * s2 * s2);   // 1 / (area ratio)^2
      energy += r.area0 * 0.5 * g * (s1 * s1 + s2 * s2 + j2 - 3.0);
      c1 = r.area0 * g * (1.0 - j2 / (s1 * s1));
      c2 = r.area0 * g * (1.0 - j2 / (s2 * s2));
    } else {
      const Eigen::Vector2d d = area_projection(s1, s2);
      energy += r.area0 * (0.5 * (f(s1) + f(s2)) - f_rest + 0.5 * w * ((s1 - d[0]) * (s1 - d[0]) + (s2 - d[1]) * (s2 - d[1])));
      c1 = r.area0 * (0.5 * df(s1) + w * (s1 - d[0])) / s1;
      c2 = r.area0 * (0.5 * df(s2) + w * (s2 - d[1])) / s2;
    }
    const double m00 = c1 * v(0, 0) * v(0, 0) + c2 * v(0, 1) * v(0, 1);
    const double m01 = c1 * v(0, 0) * v(1, 0) + c2 * v(0, 1) * v(1, 1);
    const double m11 = c1 * v(1, 0) * v(1, 0) + c2 * v(1, 1) * v(1, 1);
    const Vec p0 = f0 * m00 + f1 * m01;
    const Vec p1 = f0 * m01 + f1 * m11;
    const Vec h0 = p0 * r.r0_inv(0, 0) + p1 * r.r0_inv(0, 1);
    const Vec h1 = p1 * r.r0_inv(1, 1);
    for (int k = 0; k < 3; ++k) {
      gradient(t[1], k) += h0[k];
      gradient(t[2], k) += h1[k];
      gradient(t[0], k) -= h0[k] + h1[k];
    }
  }
  return energy;
}

double MembraneEnergy::bending_terms(const Positions& x, Positions& gradient) const {
  double energy = 0.0;
  for (const Hinge& h : hinges_) {
    Vec kx = Vec::Zero();
    for (int j = 0; j < 4; ++j) kx += h.k[j] * row(x, h.v[j]);
    const double len = kx.norm();
    const Vec proj = len > 1e-300 ? Vec(kx * (h.rest_norm / len)) : Vec::Zero();
    const Vec residual = kx - proj;
    energy += 0.5 * h.weight * residual.squaredNorm();
    for (int j = 0; j < 4; ++j) {
      const double wk = h.weight * h.k[j];
      for (int k = 0; k < 3; ++k) gradient(h.v[j], k) += wk * residual[k];
    }
  }
  return energy;
}

void MembraneEnergy::volume_area_gradients(const Positions& x, Positions& grad_volume, Positions& grad_area) const {
  grad_volume.setZero(x.rows(), 3);
  grad_area.setZero(x.rows(), 3);
  for (const auto& t : triangles_) {
    const Vec a = row(x, t[0]), b = row(x, t[1]), c = row(x, t[2]);
    grad_volume.row(t[0]) += b.cross(c).transpose() / 6.0;
    grad_volume.row(t[1]) += c.cross(a).transpose() / 6.0;
    grad_volume.row(t[2]) += a.cross(b).transpose() / 6.0;
    const Vec n = (b - a).cross(c - a).normalized();
    grad_area.row(t[0]) += 0.5 * n.cross(c - b).transpose();
    grad_area.row(t[1]) += 0.5 * n.cross(a - c).transpose();
    grad_area.row(t[2]) += 0.5 * n.cross(b - a).transpose();
  }
}

double MembraneEnergy::global_terms(const Positions& x, Positions& gradient) {
  const double kv = moduli_.volume_modulus_pN_um2 > 0.0 ? moduli_.volume_modulus_pN_um2 / rest_volume_ : 0.0;
  const double ka = moduli_.global_area_pN_um > 0.0 ? moduli_.global_area_pN_um / rest_area_ : 0.0;
  if (kv == 0.0 && ka == 0.0) return 0.0;
  // One pass for V, A and their gradients (as volume(), area() and volume_area_gradients(), summed in one loop).
  grad_volume_.setZero(x.rows(), 3);
  grad_area_.setZero(x.rows(), 3);
  double volume6 = 0.0;
  double area2 = 0.0;
  for (const auto& t : triangles_) {
    const Vec a = row(x, t[0]), b = row(x, t[1]), c = row(x, t[2]);
    const Vec bc = b.cross(c);
    volume6 += a.dot(bc);
    const Vec normal = (b - a).cross(c - a);
    const double twice_area = normal.norm();
    area2 += twice_area;
    const Vec n = normal / twice_area;
    const Vec gv[3] = {bc, c.cross(a), a.cross(b)};
    const Vec ga[3] = {n.cross(c - b), n.cross(a - c), n.cross(b - a)};
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        grad_volume_(t[j], k) += gv[j][k];
        grad_area_(t[j], k) += ga[j][k];
      }
    }
  }
  const double dv = volume6 / 6.0 - rest_volume_;
  const double da = 0.5 * area2 - rest_area_;
  gradient += (kv * dv / 6.0) * grad_volume_ + (0.5 * ka * da) * grad_area_;
  return 0.5 * kv * dv * dv + 0.5 * ka * da * da;
}

double MembraneEnergy::volume(const Positions& x) const {
  double v = 0.0;
  for (const auto& t : triangles_) v += row(x, t[0]).dot(row(x, t[1]).cross(row(x, t[2])));
  return v / 6.0;
}

double MembraneEnergy::area(const Positions& x) const {
  double a = 0.0;
  for (const auto& t : triangles_) a += (row(x, t[1]) - row(x, t[0])).cross(row(x, t[2]) - row(x, t[0])).norm();
  return 0.5 * a;
}

Eigen::SparseMatrix<double> MembraneEnergy::stiffness_proxy(double area_fraction) const {
  std::vector<Eigen::Triplet<double>> trip;
  // The neo-Hookean small-strain energy G (e1^2 + e2^2) + G (e1 + e2)^2 is the modified Skalak one's with w = 4 G_s = lambda.
  const double area_weight =
      moduli_.law == InPlaneLaw::neo_hookean ? moduli_.skalak_lambda_pN_um : moduli_.area_weight_pN_um;
  const double w_tri =
      0.5 * (moduli_.skalak_lambda_pN_um + moduli_.hardening_mu_pN_um) + area_fraction * area_weight;
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    Eigen::Matrix<double, 3, 2> d;   // vertex weights of the two columns of F
    d << -1.0, -1.0, 1.0, 0.0, 0.0, 1.0;
    d = d * rest_[i].r0_inv;
    const Eigen::Matrix3d block = w_tri * rest_[i].area0 * d * d.transpose();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) trip.emplace_back(triangles_[i][a], triangles_[i][b], block(a, b));
  }
  for (const Hinge& h : hinges_) {
    const Eigen::Matrix4d block = h.weight * h.k * h.k.transpose();
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) trip.emplace_back(h.v[a], h.v[b], block(a, b));
  }
  Eigen::SparseMatrix<double> l(vertex_count_, vertex_count_);
  l.setFromTriplets(trip.begin(), trip.end());
  return l;
}

}  // namespace hs::resolved
