// SPDX-License-Identifier: MIT
// The CFD-DEM coupling step: particle forces from the fluid, DEM sub-steps, grid fields and the exchange.
#include "unresolved/coupling/cfd_dem_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <mpi.h>

#include "common/dimensionless_groups.hpp"
#include "common/errors.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

// Below this many particles the per-particle loops run on one thread (an OpenMP region costs more).
constexpr std::int64_t kParallelParticles = 4096;

Vec3 particle_position(const ParticleStore& p, std::size_t i) {
  return {p.position_m()[0][i], p.position_m()[1][i], p.position_m()[2][i]};
}
Vec3 particle_velocity(const ParticleStore& p, std::size_t i) {
  return {p.velocity_m_s()[0][i], p.velocity_m_s()[1][i], p.velocity_m_s()[2][i]};
}


}  // namespace

CfdDemCoupling::CfdDemCoupling(FvmSolver& fluid, DemSystem& dem, CouplingSettings settings, CouplingClosures closures)
    : fluid_(fluid), dem_(dem), slabs_(dem.slabs()), settings_(settings), closures_(std::move(closures)),
      map_(fluid.grid()), eps_old_(fluid.grid().cells(), 1.0), lift_reaction_N_(fluid.grid().cells(), Vec3{}) {
  if (!closures_.drag) throw hs::common::ConfigError("coupling: a drag closure is required");
  if ((slabs_ != nullptr) != (fluid_.grid().slabs() != nullptr)) {
    throw std::logic_error("coupling: the fluid's grid and the DEM must both be on slabs, or neither");
  }
  const double ratio = fluid_.settings().dt_s / dem_.time_step_s();
  if (settings_.n_coupling < 1 || std::abs(ratio - settings_.n_coupling) > 1e-9 * ratio) {
    throw hs::common::ConfigError(fmt::format("coupling: dt_CFD / dt_DEM = {:.6g} must equal n_coupling = {}",
                                              ratio, settings_.n_coupling));
  }
  if (settings_.suspension_viscosity != SuspensionViscosity::none && !settings_.void_fraction_feedback) {
    throw hs::common::ConfigError("coupling: a suspension viscosity needs the void-fraction feedback (it is a function of eps)");
  }
  if (settings_.self_induced_correction && !settings_.two_way) {   // one-way: nothing to correct
    throw hs::common::ConfigError("coupling: the self-induced velocity correction needs two-way coupling");
  }
  if (settings_.self_induced_correction && settings_.closure_frame != ClosureFrame::tube) {
    throw hs::common::ConfigError("coupling: the self-induced velocity correction is measured in a straight tube: it needs the tube frame");
  }
  if (settings_.closure_frame == ClosureFrame::channel) channel_ = std::make_unique<ChannelFrame>(fluid_);
  if (settings_.smoothing_length_m < 0.0 || !std::isfinite(settings_.smoothing_length_m)) {
    throw hs::common::ConfigError(fmt::format("coupling: smoothing length {} m must be >= 0 (0: no smoothing)",
                                              settings_.smoothing_length_m));
  }
  if (settings_.smoothing_length_m > 0.0) {
    smoothing_ = std::make_unique<DiffusionSmoothing>(fluid_.grid(), settings_.smoothing_length_m);
  }
  if (settings_.self_induced_correction && !(settings_.tube_radius_m > 0.0)) {
    throw hs::common::ConfigError("coupling: the self-induced velocity correction needs the tube radius (tube_radius_m > 0)");
  }
}

void CfdDemCoupling::particle_forces() {
  ParticleStore& p = dem_.particles();
  const std::size_t n = p.n_owned();
  const bool correct = settings_.self_induced_correction && settings_.two_way;
  lift_reaction_N_.fill(Vec3{});
  // The particles have not moved since particles_to_grid located them (the fluid step moves none): its map holds.
  if (!located_since_dem_) map_.locate(p);
  located_since_dem_ = false;
  if (channel_) channel_->new_step();
  if (settings_.buoyancy_over_footprint) sum_over_footprints();
  // The rows sampled here: the owned ones; on slabs those (owned or remote ghosts) whose centre is in this block,
  // every other row's values zero, so that sending the ghosts' values to their owners adds each value to zeros.
  SampledColumns out{.external_force_N = p.external_force_N(), .fluid_velocity_m_s = p.fluid_velocity_m_s(),
                     .lift_force_N = p.lift_force_N(), .fluid_angular_velocity_rad_s = p.fluid_angular_velocity_rad_s(),
                     .drag_coefficient_N_s_m = p.drag_coefficient_N_s_m(),
                     .rotational_drag_N_m_s = p.rotational_drag_N_m_s(), .deformation_index = p.deformation_index()};
  std::vector<ParticleStore::Column*> columns;   // all of them, for the exchange
  for (auto* v : {&out.external_force_N, &out.fluid_velocity_m_s, &out.lift_force_N, &out.fluid_angular_velocity_rad_s}) {
    for (ParticleStore::Column& column : *v) columns.push_back(&column);
  }
  columns.insert(columns.end(), {&out.drag_coefficient_N_s_m, &out.rotational_drag_N_m_s, &out.deformation_index});
  std::vector<std::size_t> rows;
  if (slabs_ == nullptr) {
    rows.resize(n);
    std::iota(rows.begin(), rows.end(), std::size_t{0});
  } else {
    if (correct) lift_before_ = out.lift_force_N;   // the correction reads the last step's lift
    for (ParticleStore::Column* column : columns) std::fill(column->begin(), column->end(), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (map_.centred_here(i)) rows.push_back(i);
    }
  }
  // What the threaded loop below must not do itself: the channel frame's memo and the self-mobility tables are
  // filled here, on one thread, in particle order (on slabs, every rank's sections first, together).
  std::vector<LocalChannel> channels;
  if (channel_) {
    if (slabs_ != nullptr) {
      std::vector<Vec3> xs;
      xs.reserve(rows.size());
      for (const std::size_t i : rows) xs.push_back(particle_position(p, i));
      channel_->prepare_sections(xs);
    }
    channels.resize(rows.empty() ? 0 : rows.back() + 1);
    for (const std::size_t i : rows) channels[i] = local_channel(particle_position(p, i));
  }
  if (correct) {   // the tables, measured on first use, on one thread; a refusal stops every rank
    std::string refused;
    try {
      for (const std::size_t i : rows) (void)self_mobility(2.0 * p.radius_m()[i]);
    } catch (const hs::common::ConfigError& e) {
      refused = e.what();
    }
    if (slabs_ != nullptr ? slabs_->any(!refused.empty()) : !refused.empty()) {
      throw hs::common::ConfigError(refused.empty() ? "coupling: another rank refused the self-induced velocity correction" : refused);
    }
  }
  // A bad drag coefficient is reported for the first row that had one, after the loop (an exception must not leave
  // an OpenMP region), on every rank (a rank left behind would wait in the next exchange).
  const auto n_rows = static_cast<std::int64_t>(rows.size());
  std::int64_t bad = n_rows;
  std::string bad_message;
#pragma omp parallel for schedule(static) if (n_rows > kParallelParticles)
  for (std::int64_t q = 0; q < n_rows; ++q) {
    std::string message;
    if (sample_fluid_at(rows[static_cast<std::size_t>(q)], correct, channels, out, message)) continue;
#pragma omp critical(coupling_bad_drag)
    if (q < bad) {
      bad = q;
      bad_message = std::move(message);
    }
  }
  const bool failed = slabs_ != nullptr ? slabs_->any(bad < n_rows) : bad < n_rows;
  if (failed) {
    throw hs::common::NumericalError(bad < n_rows ? bad_message : "coupling: the drag closure failed on another rank");
  }
  if (slabs_ != nullptr) {   // the values go to the owners, and the owners' to every copy
    slabs_->fold_ghost_columns(p, columns);
    slabs_->update_ghost_columns(p, columns);
  }
  if (closures_.lift) {   // the fluid gets minus the lift, spread over the sphere's markers
    const auto& lift_col = p.lift_force_N();
    map_.for_each_cell([&](std::size_t c, std::size_t i, int markers) {
      lift_reaction_N_[c] -= (static_cast<double>(markers) / kMarkersPerSphere) * Vec3{lift_col[0][i], lift_col[1][i], lift_col[2][i]};
    });
  }
}

bool CfdDemCoupling::sample_fluid_at(std::size_t i, bool correct, const std::vector<LocalChannel>& channels,
                                     SampledColumns& out, std::string& message) {
  // The columns are taken writable once, before the threaded loop (taking them switches terms on in the store).
  const ParticleStore& p = dem_.particles();
  const double rho = fluid_.fluid().density_kg_m3;
  const double mu = rho * fluid_.fluid().kinematic_viscosity_m2_s;
  auto& ext = out.external_force_N;
  auto& beta = out.drag_coefficient_N_s_m;
  auto& uf_col = out.fluid_velocity_m_s;
  auto& di = out.deformation_index;
  auto& beta_r = out.rotational_drag_N_m_s;
  auto& omega_col = out.fluid_angular_velocity_rad_s;
  auto& lift_col = out.lift_force_N;
  const double dt = fluid_.settings().dt_s;
  const BlockField<double>& eps = fluid_.void_fraction();
  const Vec3 x = particle_position(p, i);
  const double d = 2.0 * p.radius_m()[i];
  Vec3 uf = fluid_.velocity_at(x);
  if (correct) {
    // What this sphere gave the fluid in the step just made: minus its drag impulse per time, minus its lift.
    const Vec3 j{p.drag_impulse_N_s()[0][i], p.drag_impulse_N_s()[1][i], p.drag_impulse_N_s()[2][i]};
    const auto& before = slabs_ != nullptr ? lift_before_ : lift_col;   // on slabs the columns were cleared
    const Vec3 lift_before{before[0][i], before[1][i], before[2][i]};
    // M is measured in plasma; a suspension viscosity mu_plasma f(eps) at the sphere scales it by 1 / f (a Stokes
    // flow's response is inversely proportional to the viscosity, and the smoothed force sits within ~l of the
    // sphere, where f is the local one: an approximation where f varies over l, e.g. at the cell-free layer).
    const double factor = settings_.suspension_viscosity != SuspensionViscosity::none
                              ? fluid_.viscosity_factor()[map_.cell(i, 0)] : 1.0;
    uf = uf - (1.0 / factor) * self_mobility(d).induced_velocity(x, -1.0 * (j / dt + lift_before));
  }
  const auto grad = fluid_.velocity_gradient_at(x);
  if (settings_.fluid_torque) {
    // Omega_f = curl(u) / 2 with grad[a][b] = du_a / dx_b; beta_r = pi mu d^3 (a sphere in Stokes flow).
    omega_col[0][i] = 0.5 * (grad[2][1] - grad[1][2]);
    omega_col[1][i] = 0.5 * (grad[0][2] - grad[2][0]);
    omega_col[2][i] = 0.5 * (grad[1][0] - grad[0][1]);
    beta_r[i] = std::numbers::pi * mu * d * d * d;
  }
  const LocalChannel channel = channel_ ? channels[i] : local_channel(x);
  hs::closures::ClosureInputs in = inputs(i, uf, grad, 1.0 - eps[map_.cell(i, 0)], channel);
  // DI = (L - B)/(L + B) lies in [0, 1) by definition; a learned DI evaluated outside its training range can
  // leave it (e.g. u_r+ > 0 in a transient), and a negative DI then fed back into C_d(DI) runs away.
  if (closures_.deformation) in.di = std::clamp(closures_.deformation->deformation_index(in), 0.0, 0.999);
  di[i] = in.di;
  const double vp = std::numbers::pi / 6.0 * d * d * d;
  const double k_wall = hs::closures::wall_correction_factor(settings_.wall_correction, d, 2.0 * channel.radius_m);
  beta[i] = 3.0 * std::numbers::pi * mu * d * closures_.drag->correction(in) * k_wall;
  if (!(beta[i] >= 0.0) || !std::isfinite(beta[i])) {
    message = fmt::format("coupling: the drag closure gave beta = {:.4g} N s/m (Re_p = {:.4g}, DI = {:.4g}, "
                          "gamma+ = {:.4g}, u_r+ = {:.4g}): a drag coefficient must be finite and >= 0",
                          beta[i], in.re_p, in.di, in.gamma_plus, in.u_r_plus);
    return false;
  }
  Vec3 f{};
  Vec3 lift{};
  if (settings_.buoyancy_over_footprint) {
    const Vec3 sum{footprint_sum_[0][i], footprint_sum_[1][i], footprint_sum_[2][i]};
    f = f + (vp / kMarkersPerSphere) * sum;
  } else {
    if (settings_.pressure_force) f = f - vp * fluid_.pressure_gradient_at(x);
    if (settings_.viscous_force) f = f + vp * fluid_.viscous_force_density_at(x);
  }
  if (closures_.lift) {
    // A C_l fitted on the fluid velocity (the resolved RBC dataset) takes that velocity and its Re_p.
    const bool flow = closures_.lift->reference_velocity() == hs::closures::LiftVelocity::flow;
    const double ur = flow ? norm(uf) : norm(uf - particle_velocity(p, i));
    hs::closures::LiftInputs lift_in = in;
    if (flow) {
      lift_in.re_p = hs::common::particle_reynolds(d, ur, fluid_.fluid().kinematic_viscosity_m2_s);
      lift_in.shear_ratio = lift_in.re_p > 0.0 ? lift_in.re_shear / lift_in.re_p : 0.0;
    }
    lift = (std::numbers::pi / 8.0 * rho * d * d * closures_.lift->lift_coefficient(lift_in) * ur * ur) * channel.lift_direction;
    f = f + lift;
  }
  for (int a = 0; a < 3; ++a) {
    ext[static_cast<std::size_t>(a)][i] = f[a];
    uf_col[static_cast<std::size_t>(a)][i] = uf[a];
    lift_col[static_cast<std::size_t>(a)][i] = lift[a];
  }
  return true;
}

void CfdDemCoupling::sum_over_footprints() {
  fill_buoyancy_density();
  const ParticleStore& p = dem_.particles();
  for (ParticleStore::Column& column : footprint_sum_) column.assign(p.size(), 0.0);
  // Each row adds the markers in this block's cells, in marker order (on one rank: all of them, as a loop over the
  // markers would); on slabs the parts summed by the neighbours go to the owner, and the whole to every copy.
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int m = 0; m < kMarkersPerSphere; ++m) {
      const std::size_t c = map_.cell(i, m);
      if (c == DividedMap::kElsewhere) continue;
      for (int a = 0; a < 3; ++a) footprint_sum_[static_cast<std::size_t>(a)][i] += buoyancy_density_[c][a];
    }
  }
  if (slabs_ != nullptr) {
    ParticleStore& writable = dem_.particles();
    const std::vector<ParticleStore::Column*> columns{&footprint_sum_[0], &footprint_sum_[1], &footprint_sum_[2]};
    slabs_->fold_ghost_columns(writable, columns);
    slabs_->update_ghost_columns(writable, columns);
  }
}

void CfdDemCoupling::fill_buoyancy_density() {
  const FvmGrid& grid = fluid_.grid();
  const auto& nc = grid.cells();
  if (buoyancy_density_.data().empty()) buoyancy_density_ = BlockField<Vec3>(nc, Vec3{});
  buoyancy_density_.fill(Vec3{});
  for (int k = 0; k < nc[2]; ++k) {
    for (int j = 0; j < nc[1]; ++j) {
      for (int i = 0; i < nc[0]; ++i) {
        const std::size_t c = buoyancy_density_.index(i, j, k);
        if (grid.fluid_fractions()[c] <= 0.0) continue;
        const Vec3 x = grid.cell_centre_m(i, j, k);
        Vec3 q{};
        if (settings_.pressure_force) q = q - fluid_.pressure_gradient_at(x);
        if (settings_.viscous_force) q = q + fluid_.viscous_force_density_at(x);
        buoyancy_density_[c] = q;
      }
    }
  }
  // The smoothing is self-adjoint in the fluid-volume inner product, so averaging the smoothed field over a sphere's
  // markers is the transpose of smoothing the volume its markers deposit: the same footprint both ways.
  if (smoothing_) smoothing_->smooth(buoyancy_density_);
}

void CfdDemCoupling::fill_fields() {
  ParticleStore& p = dem_.particles();
  map_.locate(p);
  located_since_dem_ = true;
  const bool refresh = steps_ % settings_.refresh_every == 0;
  const double dt = fluid_.settings().dt_s;
  if (refresh && settings_.void_fraction_feedback) {
    BlockField<double>& eps = fluid_.void_fraction();
    stats_.lost_solid_volume_m3 = summed(map_.void_fraction(p, settings_.eps_min, eps, smoothing_.get()));
    BlockField<double>& rate = fluid_.void_fraction_rate_1_s();
    for (std::size_t c = 0; c < eps.data().size(); ++c) {
      // No rate on the first coupling step: eps_old is not a state of this run (methods note sec. 8, item 6).
      rate[c] = steps_ == 0 || !settings_.void_fraction_rate ? 0.0 : (eps[c] - eps_old_[c]) / (dt * settings_.refresh_every);
    }
    eps_old_ = eps;
    if (settings_.suspension_viscosity != SuspensionViscosity::none) {
      fill_cell_field_ghosts(fluid_.grid(), eps);
      fill_viscosity_factor(fluid_.grid(), settings_.suspension_viscosity, eps, fluid_.viscosity_factor());
    }
  }
  BlockField<double> weight(fluid_.grid().cells(), 0.0);
  BlockField<double> ksl(fluid_.grid().cells(), 0.0);
  BlockField<Vec3>& us = fluid_.particle_velocity_m_s();
  us.fill(Vec3{});
  const ParticleStore& cp = p;
  map_.for_each_cell([&](std::size_t c, std::size_t i, int markers) {
    const double w = static_cast<double>(markers) / kMarkersPerSphere;   // the sphere's share in the cell
    weight[c] += w;
    us[c] += w * particle_velocity(cp, i);
    ksl[c] += w * cp.drag_coefficient_N_s_m()[i] / map_.fluid_volume_m3(c);
  });
  if (smoothing_) {
    // Ksl and the momentum density Ksl Us are what the implicit drag puts on the grid: smooth both (conserved), and
    // Us becomes their ratio, so Ksl (Us - u) keeps its total.
    BlockField<Vec3> momentum(fluid_.grid().cells(), Vec3{});
    map_.for_each_cell([&](std::size_t c, std::size_t i, int markers) {
      const double w = static_cast<double>(markers) / kMarkersPerSphere;
      momentum[c] += w * cp.drag_coefficient_N_s_m()[i] / map_.fluid_volume_m3(c) * particle_velocity(cp, i);
    });
    smoothing_->smooth_together({&ksl}, {&momentum});   // one solve for the four columns
    for (std::size_t c = 0; c < ksl.data().size(); ++c) us[c] = ksl[c] > 0.0 ? momentum[c] / ksl[c] : Vec3{};
  } else {
    for (std::size_t c = 0; c < weight.data().size(); ++c) {
      if (weight[c] > 0.0) us[c] = us[c] / weight[c];
    }
  }
  fill_cell_field_ghosts(fluid_.grid(), us);
  if (refresh && settings_.fluid_drag == FluidDrag::implicit && settings_.two_way) {
    fluid_.implicit_coefficient_kg_m3_s() = ksl;
  }
  if (refresh) fluid_.coupling_fields_changed();
}

void CfdDemCoupling::exchange_drag() {
  ParticleStore& p = dem_.particles();
  const FvmGrid& grid = fluid_.grid();
  const double dt = fluid_.settings().dt_s;
  BlockField<Vec3>& f = fluid_.explicit_force_density_N_m3();
  f.fill(Vec3{});
  stats_.drag_impulse_particles_N_s = {};
  const auto& imp = p.drag_impulse_N_s();
  for (std::size_t i = 0; i < map_.size(); ++i) stats_.drag_impulse_particles_N_s += Vec3{imp[0][i], imp[1][i], imp[2][i]};
  stats_.drag_impulse_particles_N_s = summed(stats_.drag_impulse_particles_N_s);
  const long particles = summed(static_cast<long>(map_.size()));
  // Each cell adds its markers' impulses first, then the share of the imbalance of earlier steps given back through
  // the particles' cells: the order of the serial loops this replaces.
  const Vec3 share = particles > 0 ? stats_.pending_N_s / static_cast<double>(particles * kMarkersPerSphere) : Vec3{};
  map_.for_each_cell([&](std::size_t c, std::size_t i, int markers) {
    f[c] -= (static_cast<double>(markers) / kMarkersPerSphere) * Vec3{imp[0][i], imp[1][i], imp[2][i]} / (map_.fluid_volume_m3(c) * dt);
  });
  if (particles > 0) {
    map_.for_each_cell([&](std::size_t c, std::size_t, int markers) {
      f[c] -= static_cast<double>(markers) * share / (map_.fluid_volume_m3(c) * dt);
    });
  }
  const BlockField<double>& ksl = fluid_.implicit_coefficient_kg_m3_s();
  const BlockField<Vec3>& us = fluid_.particle_velocity_m_s();
  const auto& n = grid.cells();
  if (smoothing_) {   // the explicit exchange (drag impulses, given-back imbalance, lift reaction), smoothed, conserved
    for (int k = 0; k < n[2]; ++k) {
      for (int jj = 0; jj < n[1]; ++jj) {
        for (int i = 0; i < n[0]; ++i) {
          const std::size_t c = f.index(i, jj, k);
          if (grid.fluid_fractions()[c] > 0.0) f[c] += lift_reaction_N_[c] / map_.fluid_volume_m3(c);
        }
      }
    }
    smoothing_->smooth(f);
  }
  stats_.explicit_to_fluid_N_s = {};
  for (int k = 0; k < n[2]; ++k) {
    for (int jj = 0; jj < n[1]; ++jj) {
      for (int i = 0; i < n[0]; ++i) {
        const std::size_t c = f.index(i, jj, k);
        if (grid.fluid_fractions()[c] <= 0.0) continue;
        if (!smoothing_) f[c] += lift_reaction_N_[c] / map_.fluid_volume_m3(c);
        if (settings_.fluid_drag == FluidDrag::implicit && ksl[c] > 0.0) {
          f[c] -= ksl[c] * (us[c] - fluid_.cell_velocity(i, jj, k));   // the implicit part's explicit remainder
        }
        stats_.explicit_to_fluid_N_s += (map_.fluid_volume_m3(c) * dt) * f[c];
      }
    }
  }
  stats_.explicit_to_fluid_N_s = summed(stats_.explicit_to_fluid_N_s);
}

void CfdDemCoupling::dem_substeps() {
  if (steps_ == 0) {
    if (slabs_ != nullptr) dem_.initialize();   // the ghosts, whose markers and fluid samples count too
    particle_forces();
  }
  located_since_dem_ = false;   // the DEM moves, re-sorts and migrates the particles
  ParticleStore& p = dem_.particles();
  for (auto& col : p.drag_impulse_N_s()) std::fill(col.begin(), col.end(), 0.0);
  const double dt = fluid_.settings().dt_s;
  int n = settings_.n_coupling;
  if (settings_.dem_substeps == DemSubsteps::drag_limited) {
    last_drag_limited_ = dem_.drag_limited_step();
    if (last_drag_limited_.applies) {
      const double wanted = std::ceil(dt / last_drag_limited_.time_step_s);
      n = static_cast<int>(std::clamp(wanted, 1.0, static_cast<double>(settings_.n_coupling)));
    }
  }
  dem_.set_time_step_s(dt / n);
  for (int s = 0; s < n; ++s) dem_.step();
  last_substeps_ = n;
  total_substeps_ += n;
}

void CfdDemCoupling::refresh_ghosts() {
  if (slabs_ == nullptr) return;
  ParticleStore& p = dem_.particles();
  slabs_->update_ghosts(p);   // the last step's second half kick moved the owners' velocities
  std::vector<ParticleStore::Column*> columns{&p.drag_coefficient_N_s_m()};
  for (auto* v : {&p.drag_impulse_N_s(), &p.lift_force_N()}) {
    for (ParticleStore::Column& column : *v) columns.push_back(&column);
  }
  slabs_->update_ghost_columns(p, columns);
}

void CfdDemCoupling::particles_to_grid() {
  // Here, not at the end of the sub-steps: a case may edit the particles in between (cells in and out at openings),
  // and on slabs the DEM's rebuild after an edit makes ghosts without the sub-steps' impulses and lifts.
  refresh_ghosts();
  fill_fields();
  if (settings_.two_way) exchange_drag();
  fill_cell_field_ghosts(fluid_.grid(), fluid_.explicit_force_density_N_m3());
}

void CfdDemCoupling::fluid_step() {
  fluid_.step();
  stats_.received_by_fluid_N_s = received_by_fluid_N_s();
  if (settings_.two_way) stats_.pending_N_s += stats_.received_by_fluid_N_s + stats_.drag_impulse_particles_N_s;
  ++steps_;
}

}  // namespace hs::unresolved
