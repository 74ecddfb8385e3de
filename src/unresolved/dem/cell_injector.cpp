// SPDX-License-Identifier: MIT
// Injection through an inlet: owed RBC volume, flux-weighted random proposals in a slab, overlap tests.
#include "unresolved/dem/cell_injector.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

// Points at which the largest inflow speed is sampled each time cells are placed: 8 rings x 16 directions on
// the mid-slab disc, plus the centre. For Poiseuille inflow the maximum is the centre value (sampled exactly);
// a proposal faster than the sampled maximum raises it (accepted for sure), a bias only while the flow changes.
constexpr int n_speed_rings = 8;
constexpr int n_speed_directions = 16;

[[noreturn]] void fail(const hs::common::Opening& o, std::string_view key, double value, std::string_view what) {
  throw hs::common::ConfigError(fmt::format("opening '{}': {} = {}: {}", o.name, key, value, what));
}

}  // namespace

CellInjector::CellInjector(const InjectionSpec& spec, const hs::common::Shape& shape, const Domain& domain)
    : spec_(spec), shape_(shape), domain_(domain), rng_(spec.seed) {
  const auto& o = spec_.inlet;
  if (!(spec.discharge_hematocrit > 0.0 && spec.discharge_hematocrit <= max_discharge_hematocrit)) {
    fail(o, "discharge_hematocrit", spec.discharge_hematocrit,
         fmt::format("must be in (0, {}] (normal blood: 0.37-0.53)", max_discharge_hematocrit));
  }
  if (o.kind != hs::common::OpeningKind::inlet) {
    throw hs::common::ConfigError(fmt::format("opening '{}': kind = \"outlet\": cells are injected through inlets only", o.name));
  }
  hs::common::check_openings({o}, shape, domain.box);
  if (!(spec.cell_radius_m > 0.0) || spec.cell_radius_m >= o.radius_m) {
    fail(o, "radius_m", o.radius_m, fmt::format("the opening must be wider than one cell (radius {:.4g} m)", spec.cell_radius_m));
  }
  if (spec.attempts_per_cell < 1) fail(o, "attempts_per_cell", spec.attempts_per_cell, "must be >= 1");
  if (!(spec.slab_thickness_m >= 0.0)) fail(o, "slab_thickness_m", spec.slab_thickness_m, "must be >= 0");
  slab_m_ = spec.slab_thickness_m > 0.0 ? spec.slab_thickness_m : 2.0 * spec.cell_radius_m;
  const double r = spec.cell_radius_m;
  cell_volume_m3_ = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  std::tie(t1_, t2_) = hs::common::tangent_basis(o.normal);
}

std::string CellInjector::rng_state() const {
  std::ostringstream out;
  out << rng_;
  return out.str();
}

void CellInjector::restore(double debt_m3, const std::string& rng_state) {
  std::istringstream in(rng_state);
  std::mt19937_64 rng;
  in >> rng;
  if (in.fail() || !(debt_m3 >= 0.0)) {
    throw hs::common::ConfigError(fmt::format("opening '{}': the checkpoint's injection state is unreadable", spec_.inlet.name));
  }
  rng_ = rng;
  debt_m3_ = debt_m3;
  u01_.reset();
}

Vec3 CellInjector::minimum_image(Vec3 d) const {
  for (int a = 0; a < 3; ++a) {
    if (domain_.periodic[a]) d[a] -= domain_.length_m(a) * std::round(d[a] / domain_.length_m(a));
  }
  return d;
}

CellInjector::Near CellInjector::particles_near_inlet(const ParticleStore& present) const {
  const auto& o = spec_.inlet;
  const auto& pos = present.position_m();
  const auto& rad = present.radius_m();
  double r_max = spec_.cell_radius_m;
  for (std::size_t i = 0; i < present.n_owned(); ++i) r_max = std::max(r_max, rad[i]);
  // A particle can touch a new cell only if its centre is within r + r_max of the slab.
  const double reach = spec_.cell_radius_m + r_max;
  Near near;
  for (std::size_t i = 0; i < present.n_owned(); ++i) {
    const Vec3 d = minimum_image(Vec3{pos[0][i], pos[1][i], pos[2][i]} - o.centre_m);
    const double h = dot(d, o.normal);   // < 0 inside
    const double lateral = norm(d - h * o.normal);
    if (h < -(spec_.cell_radius_m + slab_m_ + reach) || h > reach || lateral > o.radius_m + reach) continue;
    near.x.push_back(o.centre_m + d);
    near.r.push_back(rad[i]);
  }
  return near;
}

bool CellInjector::overlaps(const Near& near, const Vec3& x) const {
  for (std::size_t k = 0; k < near.x.size(); ++k) {
    const Vec3 d = minimum_image(x - near.x[k]);
    const double contact = spec_.cell_radius_m + near.r[k];
    if (dot(d, d) < contact * contact) return true;
  }
  return false;
}

double CellInjector::max_inflow_speed_m_s(const VelocityField& velocity) const {
  const auto& o = spec_.inlet;
  const Vec3 mid = o.centre_m - (spec_.cell_radius_m + 0.5 * slab_m_) * o.normal;
  double u_max = -dot(velocity(mid), o.normal);
  const double reach = o.radius_m - spec_.cell_radius_m;
  for (int ring = 1; ring <= n_speed_rings; ++ring) {
    for (int k = 0; k < n_speed_directions; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / n_speed_directions;
      const Vec3 x = mid + reach * ring / n_speed_rings * (std::cos(phi) * t1_ + std::sin(phi) * t2_);
      if (shape_.signed_distance(x) < 0.0) u_max = std::max(u_max, -dot(velocity(x), o.normal));
    }
  }
  return u_max;
}

Vec3 CellInjector::propose() {
  const auto& o = spec_.inlet;
  const double r = spec_.cell_radius_m;
  const double depth = r + slab_m_ * u01_(rng_);
  const double rho = (o.radius_m - r) * std::sqrt(u01_(rng_));   // uniform over the disc of radius R - r
  const double phi = 2.0 * std::numbers::pi * u01_(rng_);
  return o.centre_m - depth * o.normal + rho * (std::cos(phi) * t1_ + std::sin(phi) * t2_);
}

std::vector<NewCell> CellInjector::plan(const ParticleStore& present, double dt_s, double flow_rate_m3_s,
                                        const VelocityField& velocity) {
  std::vector<NewCell> cells;
  if (flow_rate_m3_s > 0.0) debt_m3_ += spec_.discharge_hematocrit * flow_rate_m3_s * dt_s;
  if (debt_m3_ < cell_volume_m3_) return cells;
  Near near = particles_near_inlet(present);
  double u_max = max_inflow_speed_m_s(velocity);
  if (!(u_max > 0.0)) return cells;   // no inflow anywhere: the debt waits
  const double r = spec_.cell_radius_m;
  while (debt_m3_ >= cell_volume_m3_) {
    bool placed = false;
    for (int attempt = 0; attempt < spec_.attempts_per_cell && !placed; ++attempt) {
      const Vec3 x = propose();
      const double keep = u01_(rng_);   // drawn every time, so the stream does not depend on the velocity branch
      if (shape_.signed_distance(x) > -r) continue;
      const Vec3 u = velocity(x);
      const double u_n = -dot(u, spec_.inlet.normal);
      if (!(u_n > 0.0)) continue;
      u_max = std::max(u_max, u_n);
      if (keep * u_max > u_n || overlaps(near, x)) continue;
      cells.push_back({.position_m = x, .velocity_m_s = u});
      near.x.push_back(x);
      near.r.push_back(r);
      debt_m3_ -= cell_volume_m3_;
      placed = true;
    }
    if (!placed) break;   // no free slot now: the debt is carried to the next step
  }
  return cells;
}

}  // namespace hs::unresolved
