// SPDX-License-Identifier: MIT
// What the closures are given at a particle: the local channel (tube or channel frame), the self-mobility table of
// the self-induced correction, and the dimensionless inputs (Re_p, shear ratio, gamma+, u_r+, local hematocrit).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "common/dimensionless_groups.hpp"
#include "common/errors.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"
#include "unresolved/coupling/shear_rate.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

Vec3 particle_velocity(const ParticleStore& p, std::size_t i) {
  return {p.velocity_m_s()[0][i], p.velocity_m_s()[1][i], p.velocity_m_s()[2][i]};
}

}  // namespace

const SelfMobility& CfdDemCoupling::self_mobility(double diameter_m) {
  for (const SelfMobility& m : self_mobility_) {
    if (std::abs(m.sphere_diameter_m() - diameter_m) <= 1e-9 * diameter_m) return m;
  }
  const double ratio = diameter_m / fluid_.grid().dx_m();
  if (ratio > 1.0 && !smoothing_) {
    throw hs::common::ConfigError(fmt::format(
        "coupling: the self-induced velocity correction needs spheres no larger than a cell, but d_p / dx = {:.3g} "
        "(d_p = {:.4g} m, dx = {:.4g} m): use a coarser grid, smooth the exchange (smoothing_length_m) or switch the "
        "correction off (self_mobility.hpp)",
        ratio, diameter_m, fluid_.grid().dx_m()));
  }
  // On slabs every rank measures the table on the whole grid by itself (a one-time calibration on the run's tube):
  // the same table as one rank's, without a distributed solve.
  if (slabs_ != nullptr && !whole_grid_) whole_grid_ = std::make_unique<FvmGrid>(fluid_.grid().shape(), fluid_.grid().spec());
  const SelfMobility& m = self_mobility_.emplace_back(
      slabs_ != nullptr ? *whole_grid_ : fluid_.grid(), fluid_.fluid(), fluid_.drive(),
      TubeFrame{.axis = settings_.axis, .axis_point_m = settings_.axis_point_m, .radius_m = settings_.tube_radius_m},
      diameter_m, settings_.void_fraction_feedback ? settings_.eps_min : 0.0, settings_.smoothing_length_m);
  if (smoothing_) {
    // The correction subtracts M F with F of the step before: it follows the fluid while the sphere's own disturbance
    // stays below its Stokes velocity, beta M < 1 (without smoothing the runs with beta M = 1.2-4.6 ran away; with
    // l = d_p / 2, 0.44-0.47 at 10-20 cells across D = 30 um, stable: sphere_in_tube_drag_test).
    const double beta = 3.0 * std::numbers::pi * fluid_.fluid().density_kg_m3 * fluid_.fluid().kinematic_viscosity_m2_s * diameter_m;
    double largest = 0.0;
    for (const Vec3& v : m.mobility_m_s_N()) largest = std::max({largest, v[0], v[1], v[2]});
    if (beta * largest >= 1.0) {
      throw hs::common::ConfigError(fmt::format(
          "coupling: with smoothing_length_m = {:.4g} m the self-induced velocity correction would move a sphere of "
          "d_p = {:.4g} m by beta M = {:.3g} of its own Stokes velocity (allowed < 1): smooth over a longer length "
          "(about d_p or more) or switch the correction off (self_mobility.hpp)",
          settings_.smoothing_length_m, diameter_m, beta * largest));
    }
  }
  return m;
}

CfdDemCoupling::LocalChannel CfdDemCoupling::local_channel(const Vec3& x) {
  if (channel_) {
    const ChannelFrame::Local local = channel_->at(x);
    return {.lift_direction = channel_->wall_normal(x), .radius_m = local.channel_radius_m,
            .flow_direction = local.flow.direction, .mean_velocity_m_s = local.flow.mean_velocity_m_s};
  }
  Vec3 r = x - settings_.axis_point_m;
  r[settings_.axis] = 0.0;
  const double n = norm(r);
  Vec3 axial;
  axial[settings_.axis] = 1.0;
  return {.lift_direction = n > 0.0 ? r / n : Vec3{}, .radius_m = settings_.tube_radius_m, .flow_direction = axial,
          .mean_velocity_m_s = mean_velocity_m_s_};
}

hs::closures::ClosureInputs CfdDemCoupling::inputs(std::size_t i, const Vec3& uf, const std::array<Vec3, 3>& grad,
                                                  double local_ht, const LocalChannel& channel) const {
  const ParticleStore& p = dem_.particles();
  const double nu = fluid_.fluid().kinematic_viscosity_m2_s;
  const double d = 2.0 * p.radius_m()[i];
  const Vec3 slip = particle_velocity(p, i) - uf;
  const double gd = shear_rate(grad);
  hs::closures::ClosureInputs in;
  in.re_p = hs::common::particle_reynolds(d, norm(slip), nu);
  in.re_shear = gd * d * d / nu;   // Saffman/Mei shear Reynolds number (closure_inputs.hpp)
  in.shear_ratio = in.re_p > 0.0 ? in.re_shear / in.re_p : 0.0;
  in.gamma_plus = hs::common::shear_rate_plus(gd, channel.radius_m, nu);
  in.u_r_plus = channel.mean_velocity_m_s > 0.0
                    ? hs::common::slip_velocity_plus(dot(particle_velocity(p, i), channel.flow_direction),
                                                     dot(uf, channel.flow_direction), channel.mean_velocity_m_s)
                    : 0.0;
  in.hematocrit = local_ht;
  return in;
}

}  // namespace hs::unresolved
