// SPDX-License-Identifier: MIT
// Structure-of-arrays particle storage: adding, sorting and the periodic-image (ghost) halo.
#include "unresolved/dem/particle_store.hpp"

#include <bit>
#include <stdexcept>
#include <tuple>
#include <type_traits>

namespace hs::unresolved {

template <typename F>
void ParticleStore::for_each_column(F&& f) {
  for (auto* v3 : {&pos_, &vel_, &omega_, &force_, &torque_, &ext_force_, &ext_torque_, &fluid_vel_,
                   &drag_impulse_, &lift_, &wall_shear_, &fluid_omega_}) {
    for (auto& c : *v3) f(c);
  }
  for (auto* c : {&radius_, &mass_, &drag_beta_, &di_, &rot_drag_}) f(*c);
}

template <typename F>
void ParticleStore::for_each_any_column(F&& f) {
  for_each_column(f);
  f(id_);
  f(inlet_opening_);
}

void ParticleStore::resize(std::size_t n) {
  for_each_column([n](Column& c) { c.resize(n, 0.0); });
  id_.resize(n, 0);
  inlet_opening_.resize(n, no_inlet_opening);
}

namespace {

/// Writes a ParticleState into row i (kinematics, size, mass, id, inlet opening).
void write_state(ParticleStore& store, std::size_t i, const ParticleState& p) {
  for (int a = 0; a < 3; ++a) {
    store.position_m()[a][i] = p.position_m[a];
    store.velocity_m_s()[a][i] = p.velocity_m_s[a];
    store.angular_velocity_rad_s()[a][i] = p.angular_velocity_rad_s[a];
  }
  store.radius_m()[i] = p.radius_m;
  store.mass_kg()[i] = p.mass_kg;
  store.id()[i] = p.id;
  store.inlet_opening()[i] = p.inlet_opening;
}

}  // namespace

std::size_t ParticleStore::add(const ParticleState& p) {
  clear_ghosts();
  const std::size_t i = n_owned_;
  resize(i + 1);
  ++n_owned_;
  write_state(*this, i, p);
  return i;
}

ParticleState ParticleStore::state(std::size_t i) const {
  ParticleState p;
  for (int a = 0; a < 3; ++a) {
    p.position_m[a] = pos_[a][i];
    p.velocity_m_s[a] = vel_[a][i];
    p.angular_velocity_rad_s[a] = omega_[a][i];
  }
  p.radius_m = radius_[i];
  p.mass_kg = mass_[i];
  p.id = id_[i];
  p.inlet_opening = inlet_opening_[i];
  return p;
}

void ParticleStore::permute_owned(const std::vector<std::size_t>& order) {
  if (n_ghost() != 0 || order.size() != n_owned_) throw std::logic_error("permute_owned: ghosts present or bad order");
  // One scratch column per element type, reused by swapping (large allocations would fault in fresh pages).
  std::tuple<Column, std::vector<std::int64_t>, std::vector<std::int32_t>> scratch;
  for_each_any_column([&](auto& c) {
    auto& tmp = std::get<std::remove_reference_t<decltype(c)>>(scratch);
    tmp.resize(n_owned_);
    for (std::size_t k = 0; k < n_owned_; ++k) tmp[k] = c[order[k]];
    c.swap(tmp);
  });
}

std::size_t ParticleStore::remove_owned(const std::vector<bool>& remove) {
  if (remove.size() != n_owned_) throw std::logic_error("remove_owned: one flag per owned particle expected");
  clear_ghosts();
  std::size_t kept = 0;
  for_each_any_column([&](auto& c) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < n_owned_; ++i) {
      if (!remove[i]) c[k++] = c[i];
    }
    kept = k;
  });
  const std::size_t removed = n_owned_ - kept;
  n_owned_ = kept;
  resize(kept);
  return removed;
}

void ParticleStore::clear_ghosts() {
  resize(n_owned_);
  ghost_owner_.clear();
  ghost_shift_.clear();
}

std::size_t ParticleStore::add_ghost(std::size_t owner, const hs::common::Vec3& shift_m) {
  const std::size_t g = size();
  resize(g + 1);
  ghost_owner_.push_back(owner);
  ghost_shift_.push_back(shift_m);
  radius_[g] = radius_[owner];
  mass_[g] = mass_[owner];
  id_[g] = id_[owner];
  inlet_opening_[g] = inlet_opening_[owner];
  for (int a = 0; a < 3; ++a) pos_[a][g] = pos_[a][owner] + shift_m[a];
  return g;
}

std::size_t ParticleStore::add_remote_ghost(const ParticleState& p, const GhostCoupling& coupling) {
  const std::size_t g = size();
  resize(g + 1);
  ghost_owner_.push_back(remote_owner);
  ghost_shift_.push_back({});
  write_state(*this, g, p);
  drag_beta_[g] = coupling.drag_N_s_m;
  rot_drag_[g] = coupling.rotational_drag_N_m_s;
  for (int a = 0; a < 3; ++a) {
    fluid_vel_[a][g] = coupling.fluid_velocity_m_s[a];
    ext_force_[a][g] = coupling.external_force_N[a];
  }
  return g;
}

namespace {
// A particle's columns travel as doubles; the id's 64 bits are carried as they are.
double as_double(double v) { return v; }
double as_double(std::int64_t v) { return std::bit_cast<double>(v); }
double as_double(std::int32_t v) { return static_cast<double>(v); }
template <typename T>
T from_double(double v) {
  if constexpr (std::is_same_v<T, std::int64_t>) {
    return std::bit_cast<std::int64_t>(v);
  } else {
    return static_cast<T>(v);
  }
}
}  // namespace

void ParticleStore::pack_owned(std::size_t i, std::vector<double>& out) {
  for_each_any_column([&](auto& c) { out.push_back(as_double(c[i])); });
}

std::size_t ParticleStore::packed_size() {
  std::size_t n = 0;
  for_each_any_column([&](auto&) { ++n; });
  return n;
}

std::size_t ParticleStore::add_packed(const double* packed) {
  clear_ghosts();
  const std::size_t i = n_owned_;
  resize(i + 1);
  ++n_owned_;
  std::size_t k = 0;
  for_each_any_column([&](auto& c) { c[i] = from_double<typename std::remove_reference_t<decltype(c)>::value_type>(packed[k++]); });
  return i;
}

void ParticleStore::update_ghosts() {
  const std::size_t n_ghosts = n_ghost();
  for (std::size_t k = 0; k < n_ghosts; ++k) {
    const std::size_t g = n_owned_ + k;
    const std::size_t o = ghost_owner_[k];
    if (o == remote_owner) continue;
    for (int a = 0; a < 3; ++a) {
      pos_[a][g] = pos_[a][o] + ghost_shift_[k][a];
      vel_[a][g] = vel_[a][o];
      omega_[a][g] = omega_[a][o];
    }
  }
}

void ParticleStore::fold_ghost_forces() {
  const std::size_t n_ghosts = n_ghost();
  for (std::size_t k = 0; k < n_ghosts; ++k) {
    const std::size_t g = n_owned_ + k;
    const std::size_t o = ghost_owner_[k];
    if (o == remote_owner) continue;
    for (int a = 0; a < 3; ++a) {
      force_[a][o] += force_[a][g];
      torque_[a][o] += torque_[a][g];
      force_[a][g] = 0.0;
      torque_[a][g] = 0.0;
    }
  }
}

}  // namespace hs::unresolved
