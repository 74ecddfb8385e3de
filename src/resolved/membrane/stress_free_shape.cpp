// SPDX-License-Identifier: MIT
// Oblate stress-free shape: the spheroid of a given reduced volume and the axisymmetric equal-area map onto it.
#include "resolved/membrane/stress_free_shape.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace hs::resolved {
namespace {

using hs::common::Vec3;

/// Area between the pole (t = 0) and t_i of the surface of revolution (rho(t), z(t)), t in [0, pi/2], summed over
/// conical frustums on `n` steps: exact for the polygonal profile, so a rim where dz/drho is unbounded is harmless.
std::vector<double> cumulative_cap_area(const std::function<void(double, double&, double&)>& profile, int n) {
  std::vector<double> area(static_cast<std::size_t>(n) + 1, 0.0);
  double rho0 = 0.0;
  double z0 = 0.0;
  profile(0.0, rho0, z0);
  for (int i = 1; i <= n; ++i) {
    double rho1 = 0.0;
    double z1 = 0.0;
    profile(0.5 * std::numbers::pi * i / n, rho1, z1);
    area[i] = area[i - 1] + std::numbers::pi * (rho0 + rho1) * std::hypot(rho1 - rho0, z1 - z0);
    rho0 = rho1;
    z0 = z1;
  }
  return area;
}

/// The parameter t (of the table's uniform grid on [0, pi/2]) where the cumulative area reaches `target`.
double parameter_at_area(const std::vector<double>& area, double target) {
  const auto it = std::lower_bound(area.begin(), area.end(), target);
  if (it == area.begin()) return 0.0;
  if (it == area.end()) return 0.5 * std::numbers::pi;
  const auto i = static_cast<double>(it - area.begin());
  const double frac = (target - *(it - 1)) / (*it - *(it - 1));
  return 0.5 * std::numbers::pi * (i - 1.0 + frac) / static_cast<double>(area.size() - 1);
}

/// The cumulative area at parameter t in [0, pi/2], interpolated linearly in the table.
double area_at_parameter(const std::vector<double>& area, double t) {
  const double x = std::clamp(t / (0.5 * std::numbers::pi), 0.0, 1.0) * static_cast<double>(area.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(x), area.size() - 2);
  const double frac = x - static_cast<double>(i);
  return area[i] + frac * (area[i + 1] - area[i]);
}

}  // namespace

double oblate_spheroid_reduced_volume(double axis_ratio) {
  if (!(axis_ratio > 0.0 && axis_ratio <= 1.0)) {
    throw std::invalid_argument(fmt::format("oblate spheroid axis ratio {} is not in (0, 1]", axis_ratio));
  }
  if (axis_ratio > 1.0 - 1e-12) return 1.0;
  const double e = std::sqrt(1.0 - axis_ratio * axis_ratio);
  const double area_over_2pi_a2 = 1.0 + (1.0 - e * e) / e * std::atanh(e);   // A = 2 pi a^2 (1 + (1-e^2)/e atanh e)
  const double r_a = std::sqrt(2.0 * std::numbers::pi * area_over_2pi_a2 / (4.0 * std::numbers::pi));   // per a
  return axis_ratio / (r_a * r_a * r_a);   // V = 4/3 pi a^2 c against 4/3 pi R_A^3
}

double oblate_spheroid_axis_ratio(double reduced_volume) {
  if (!(reduced_volume > 0.2 && reduced_volume <= 1.0)) {
    throw std::invalid_argument(fmt::format("oblate spheroid reduced volume {} is not in (0.2, 1]", reduced_volume));
  }
  double lo = 1e-3;
  double hi = 1.0;
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {   // v rises with c/a: bisection
    const double mid = 0.5 * (lo + hi);
    (oblate_spheroid_reduced_volume(mid) < reduced_volume ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

std::vector<Vec3> oblate_stress_free_vertices(const TriangleMesh& biconcave, const EvansFungShape& shape,
                                              double reduced_volume) {
  constexpr int table_steps = 20000;   // profile steps per quarter: the table's area error ~1e-8, far below the mesh's
  const double r0 = 0.5 * shape.diameter_m();
  const auto biconcave_area = cumulative_cap_area(
      [&](double t, double& rho, double& z) {
        rho = r0 * std::sin(t);
        z = shape.half_thickness_m(rho);
      },
      table_steps);
  const double c_over_a = oblate_spheroid_axis_ratio(reduced_volume);
  const auto spheroid_area = cumulative_cap_area(   // per unit equatorial radius
      [&](double s, double& rho, double& z) {
        rho = std::sin(s);
        z = c_over_a * std::cos(s);
      },
      table_steps);
  std::vector<Vec3> out;
  out.reserve(biconcave.vertices_m.size());
  for (const Vec3& v : biconcave.vertices_m) {
    const double rho = std::hypot(v.x, v.y);
    const double t = std::asin(std::min(1.0, rho / r0));
    const double fraction = area_at_parameter(biconcave_area, t) / biconcave_area.back();
    const double s = parameter_at_area(spheroid_area, spheroid_area.back() * fraction);
    const double azimuth = std::atan2(v.y, v.x);
    const double z = c_over_a * std::cos(s);
    out.push_back(Vec3{std::sin(s) * std::cos(azimuth), std::sin(s) * std::sin(azimuth), v.z > 0.0 ? z : -z});
  }
  const TriangleMesh spheroid{out, biconcave.triangles};
  const double scale = std::sqrt(mesh_area_m2(biconcave) / mesh_area_m2(spheroid));
  for (Vec3& p : out) p = p * scale;
  return out;
}

}  // namespace hs::resolved
