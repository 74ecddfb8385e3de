// SPDX-License-Identifier: MIT
// Particle traffic between z-slabs: migration, ghost copies, their refresh and their forces' way back.
#include "unresolved/dem/dem_slabs.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::unresolved {
namespace {

// position, velocity, angular velocity, radius, mass, id, inlet opening; drag, rotational drag, fluid velocity,
// external force (GhostCoupling)
constexpr int kGhostDoubles = 21;
constexpr int kSpringDoubles = 5;   // the pair's two ids and its tangential spring

}  // namespace

DemSlabs::DemSlabs(const hs::common::CartesianDecomposition& slabs, const Domain& domain, double dx_m)
    : slabs_(slabs), block_(domain) {
  const auto& dims = slabs.ranks_per_axis();
  if (dims[0] != 1 || dims[1] != 1) throw std::logic_error("DemSlabs: the decomposition must split z only");
  const int global = slabs.global_nodes()[2];
  if (std::abs(global * dx_m - domain.length_m(2)) > 1e-9 * domain.length_m(2)) {
    throw std::logic_error(fmt::format("DemSlabs: {} planes of {:.6g} m do not span the DEM box's {:.6g} m along z",
                                       global, dx_m, domain.length_m(2)));
  }
  const int first = slabs.offset()[2];
  const int planes = slabs.layout().n[2];
  lo_m_ = domain.box.lo.z + first * dx_m;
  // The top slab ends exactly at the box (no round-off gap a particle could fall into).
  hi_m_ = first + planes == global ? domain.box.hi.z : domain.box.lo.z + (first + planes) * dx_m;
  length_m_ = domain.length_m(2);
  periodic_ = domain.periodic[2];
  block_.box.lo.z = lo_m_;
  block_.box.hi.z = hi_m_;
  block_.periodic[2] = false;
}

double DemSlabs::shift_to(int side) const {
  if (!periodic_) return 0.0;
  const bool bottom = slabs_.offset()[2] == 0;
  const bool top = slabs_.offset()[2] + slabs_.layout().n[2] == slabs_.global_nodes()[2];
  if (side == 0 && bottom) return length_m_;
  if (side == 1 && top) return -length_m_;
  return 0.0;
}

void DemSlabs::check_thickness(double cutoff_m) const {
  const double thinnest = min(hi_m_ - lo_m_);
  if (thinnest < cutoff_m) {
    throw hs::common::ConfigError(fmt::format(
        "DEM on {} ranks: the thinnest z-slab is {:.4g} m, below the neighbour cut-off {:.4g} m (d_max + skin): run on "
        "fewer ranks", slabs_.size(), thinnest, cutoff_m));
  }
}

ContactHistory DemSlabs::migrate(ParticleStore& particles, const ContactHistory& history) const {
  if (particles.n_ghost() != 0) throw std::logic_error("DemSlabs::migrate: ghosts present");
  const std::size_t n = particles.n_owned();
  const auto& z = particles.position_m()[2];
  std::vector<bool> leaves(n, false);
  std::unordered_map<std::int64_t, int> side_of;   // id -> side, of the particles that leave
  std::array<std::vector<double>, 2> out;
  for (std::size_t i = 0; i < n; ++i) {
    const int side = z[i] < lo_m_ ? 0 : (z[i] >= hi_m_ ? 1 : -1);
    if (side < 0 || neighbour(side) == MPI_PROC_NULL) continue;   // past a wall: the openings deal with it
    particles.position_m()[2][i] += shift_to(side);
    leaves[i] = true;
    side_of[particles.id()[i]] = side;
    particles.pack_owned(i, out[static_cast<std::size_t>(side)]);
  }
  // The springs of the pairs a leaving particle computes (it has the smaller id) go with it.
  ContactHistory kept;
  std::array<std::vector<double>, 2> springs;
  for (std::size_t k = 0; k < history.keys.size(); ++k) {
    const auto it = side_of.find(history.keys[k].first);
    if (it == side_of.end()) {
      kept.keys.push_back(history.keys[k]);
      kept.shear_m.push_back(history.shear_m[k]);
      continue;
    }
    auto& s = springs[static_cast<std::size_t>(it->second)];
    s.push_back(std::bit_cast<double>(history.keys[k].first));
    s.push_back(std::bit_cast<double>(history.keys[k].second));
    s.insert(s.end(), history.shear_m[k].begin(), history.shear_m[k].end());
  }
  particles.remove_owned(leaves);
  std::array<std::vector<double>, 2> in;
  exchange(out, in, false, 10);
  std::array<std::vector<double>, 2> springs_in;
  exchange(springs, springs_in, false, 20);
  const std::size_t packed = particles.packed_size();
  for (int side = 0; side < 2; ++side) {
    const auto& p = in[static_cast<std::size_t>(side)];
    for (std::size_t at = 0; at + packed <= p.size(); at += packed) particles.add_packed(p.data() + at);
    const auto& sp = springs_in[static_cast<std::size_t>(side)];
    for (std::size_t at = 0; at + kSpringDoubles <= sp.size(); at += kSpringDoubles) {
      kept.keys.emplace_back(std::bit_cast<std::int64_t>(sp[at]), std::bit_cast<std::int64_t>(sp[at + 1]));
      kept.shear_m.push_back({sp[at + 2], sp[at + 3], sp[at + 4]});
    }
  }
  // ContactHistory's keys are sorted.
  std::vector<std::size_t> order(kept.keys.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return kept.keys[a] < kept.keys[b]; });
  ContactHistory sorted;
  for (const std::size_t k : order) {
    sorted.keys.push_back(kept.keys[k]);
    sorted.shear_m.push_back(kept.shear_m[k]);
  }
  return sorted;
}

void DemSlabs::exchange_ghosts(ParticleStore& particles, double width_m) {
  const std::size_t n = particles.size();
  std::array<std::vector<double>, 2> out;
  for (int side = 0; side < 2; ++side) {
    auto& sent = sent_[static_cast<std::size_t>(side)];
    sent.clear();
    if (neighbour(side) == MPI_PROC_NULL) continue;
    const double shift = shift_to(side);
    const auto& pos = particles.position_m();
    for (std::size_t i = 0; i < n; ++i) {
      const bool near = side == 0 ? pos[2][i] < lo_m_ + width_m : pos[2][i] >= hi_m_ - width_m;
      if (!near) continue;
      sent.push_back(i);
      auto& o = out[static_cast<std::size_t>(side)];
      o.insert(o.end(), {pos[0][i], pos[1][i], pos[2][i] + shift});
      for (const auto* v : {&particles.velocity_m_s(), &particles.angular_velocity_rad_s()}) {
        o.insert(o.end(), {(*v)[0][i], (*v)[1][i], (*v)[2][i]});
      }
      o.insert(o.end(), {particles.radius_m()[i], particles.mass_kg()[i], std::bit_cast<double>(particles.id()[i]),
                         static_cast<double>(particles.inlet_opening()[i])});
      const ParticleStore& read = particles;   // the const columns: reading must not switch the drag on
      const std::size_t c = read.coupling_row(i);
      o.insert(o.end(), {read.drag_coefficient_N_s_m()[c], read.rotational_drag_N_m_s()[c]});
      for (const auto* v : {&read.fluid_velocity_m_s(), &read.external_force_N()}) {
        o.insert(o.end(), {(*v)[0][c], (*v)[1][c], (*v)[2][c]});
      }
    }
  }
  std::array<std::vector<double>, 2> in;
  exchange(out, in, false, 30);
  for (int side = 0; side < 2; ++side) {
    const auto& from = in[static_cast<std::size_t>(side)];
    received_first_[static_cast<std::size_t>(side)] = particles.size();
    received_count_[static_cast<std::size_t>(side)] = from.size() / kGhostDoubles;
    for (std::size_t at = 0; at + kGhostDoubles <= from.size(); at += kGhostDoubles) {
      const double* g = from.data() + at;
      (void)particles.add_remote_ghost({.position_m = {g[0], g[1], g[2]},
                                        .velocity_m_s = {g[3], g[4], g[5]},
                                        .angular_velocity_rad_s = {g[6], g[7], g[8]},
                                        .radius_m = g[9],
                                        .mass_kg = g[10],
                                        .id = std::bit_cast<std::int64_t>(g[11]),
                                        .inlet_opening = static_cast<std::int32_t>(g[12])},
                                       {.drag_N_s_m = g[13],
                                        .rotational_drag_N_m_s = g[14],
                                        .fluid_velocity_m_s = {g[15], g[16], g[17]},
                                        .external_force_N = {g[18], g[19], g[20]}});
    }
  }
}

void DemSlabs::update_ghosts(ParticleStore& particles) const {
  auto& pos = particles.position_m();
  auto& vel = particles.velocity_m_s();
  auto& omega = particles.angular_velocity_rad_s();
  std::array<std::vector<double>, 2> out;
  std::array<std::vector<double>, 2> in;
  for (int side = 0; side < 2; ++side) {
    const auto s = static_cast<std::size_t>(side);
    const double shift = shift_to(side);
    out[s].reserve(9 * sent_[s].size());
    for (const std::size_t i : sent_[s]) {
      out[s].insert(out[s].end(), {pos[0][i], pos[1][i], pos[2][i] + shift, vel[0][i], vel[1][i], vel[2][i],
                                   omega[0][i], omega[1][i], omega[2][i]});
    }
    in[s].resize(9 * received_count_[s]);
  }
  exchange(out, in, true, 40);
  for (std::size_t s = 0; s < 2; ++s) {
    for (std::size_t k = 0; k < received_count_[s]; ++k) {
      const double* g = in[s].data() + 9 * k;
      const std::size_t at = received_first_[s] + k;
      for (int a = 0; a < 3; ++a) {
        pos[a][at] = g[a];
        vel[a][at] = g[3 + a];
        omega[a][at] = g[6 + a];
      }
    }
  }
}

void DemSlabs::fold_ghost_forces(ParticleStore& particles) const {
  auto& f = particles.force_N();
  auto& t = particles.torque_Nm();
  // To each neighbour go the forces on the ghosts it sent; from it come those on the ghosts sent to it.
  std::array<std::vector<double>, 2> out;
  std::array<std::vector<double>, 2> in;
  for (std::size_t s = 0; s < 2; ++s) {
    out[s].reserve(6 * received_count_[s]);
    for (std::size_t g = received_first_[s]; g < received_first_[s] + received_count_[s]; ++g) {
      out[s].insert(out[s].end(), {f[0][g], f[1][g], f[2][g], t[0][g], t[1][g], t[2][g]});
      for (int a = 0; a < 3; ++a) f[a][g] = t[a][g] = 0.0;
    }
    in[s].resize(6 * sent_[s].size());
  }
  exchange(out, in, true, 50);
  for (std::size_t s = 0; s < 2; ++s) {
    for (std::size_t k = 0; k < sent_[s].size(); ++k) {
      const std::size_t i = sent_[s][k];
      for (int a = 0; a < 3; ++a) {
        f[a][i] += in[s][6 * k + a];
        t[a][i] += in[s][6 * k + 3 + a];
      }
    }
  }
}

void DemSlabs::fold_values(std::vector<double>& value) const {
  std::array<std::vector<double>, 2> out;
  std::array<std::vector<double>, 2> in;
  for (std::size_t s = 0; s < 2; ++s) {
    const auto first = static_cast<std::ptrdiff_t>(received_first_[s]);
    out[s].assign(value.begin() + first, value.begin() + first + static_cast<std::ptrdiff_t>(received_count_[s]));
    std::fill(value.begin() + first, value.begin() + first + static_cast<std::ptrdiff_t>(received_count_[s]), 0.0);
    in[s].resize(sent_[s].size());
  }
  exchange(out, in, true, 60);
  for (std::size_t s = 0; s < 2; ++s) {
    for (std::size_t k = 0; k < sent_[s].size(); ++k) value[sent_[s][k]] += in[s][k];
  }
}

void DemSlabs::update_ghost_columns(const ParticleStore& particles,
                                    const std::vector<ParticleStore::Column*>& columns) const {
  const std::size_t width = columns.size();
  std::array<std::vector<double>, 2> out;
  std::array<std::vector<double>, 2> in;
  for (std::size_t s = 0; s < 2; ++s) {
    out[s].reserve(width * sent_[s].size());
    for (const std::size_t i : sent_[s]) {
      const std::size_t c = particles.coupling_row(i);
      for (const ParticleStore::Column* column : columns) out[s].push_back((*column)[c]);
    }
    in[s].resize(width * received_count_[s]);
  }
  exchange(out, in, true, 70);
  for (std::size_t s = 0; s < 2; ++s) {
    for (std::size_t k = 0; k < received_count_[s]; ++k) {
      for (std::size_t j = 0; j < width; ++j) (*columns[j])[received_first_[s] + k] = in[s][width * k + j];
    }
  }
}

void DemSlabs::fold_ghost_columns(const ParticleStore& particles,
                                  const std::vector<ParticleStore::Column*>& columns) const {
  const std::size_t width = columns.size();
  std::array<std::vector<double>, 2> out;
  std::array<std::vector<double>, 2> in;
  for (std::size_t s = 0; s < 2; ++s) {
    out[s].reserve(width * received_count_[s]);
    for (std::size_t g = received_first_[s]; g < received_first_[s] + received_count_[s]; ++g) {
      for (ParticleStore::Column* column : columns) {
        out[s].push_back((*column)[g]);
        (*column)[g] = 0.0;
      }
    }
    in[s].resize(width * sent_[s].size());
  }
  exchange(out, in, true, 80);
  for (std::size_t s = 0; s < 2; ++s) {
    for (std::size_t k = 0; k < sent_[s].size(); ++k) {
      const std::size_t c = particles.coupling_row(sent_[s][k]);
      for (std::size_t j = 0; j < width; ++j) (*columns[j])[c] += in[s][width * k + j];
    }
  }
}

void DemSlabs::exchange(const std::array<std::vector<double>, 2>& out, std::array<std::vector<double>, 2>& in,
                        bool sizes_known, int tag) const {
  // A message sent towards side s has tag + s; the neighbour on side s sent this rank its message towards 1 - s.
  // Both directions at once: one synchronisation a call (two with the sizes), which matters when ranks outnumber
  // cores.
  const MPI_Comm c = comm();
  std::array<MPI_Request, 4> requests{};
  if (!sizes_known) {
    std::array<long, 2> n_out{static_cast<long>(out[0].size()), static_cast<long>(out[1].size())};
    std::array<long, 2> n_in{0, 0};
    for (int s = 0; s < 2; ++s) {
      MPI_Irecv(&n_in[static_cast<std::size_t>(s)], 1, MPI_LONG, neighbour(s), tag + 1 - s, c, &requests[static_cast<std::size_t>(s)]);
      MPI_Isend(&n_out[static_cast<std::size_t>(s)], 1, MPI_LONG, neighbour(s), tag + s, c, &requests[static_cast<std::size_t>(2 + s)]);
    }
    MPI_Waitall(4, requests.data(), MPI_STATUSES_IGNORE);
    for (std::size_t s = 0; s < 2; ++s) in[s].assign(static_cast<std::size_t>(n_in[s]), 0.0);
  }
  for (int s = 0; s < 2; ++s) {
    const auto k = static_cast<std::size_t>(s);
    MPI_Irecv(in[k].data(), static_cast<int>(in[k].size()), MPI_DOUBLE, neighbour(s), tag + 3 - s, c, &requests[k]);
    MPI_Isend(out[k].data(), static_cast<int>(out[k].size()), MPI_DOUBLE, neighbour(s), tag + 2 + s, c, &requests[2 + k]);
  }
  MPI_Waitall(4, requests.data(), MPI_STATUSES_IGNORE);
}

bool DemSlabs::any(bool mine) const {
  int local = mine ? 1 : 0;
  int all = 0;
  MPI_Allreduce(&local, &all, 1, MPI_INT, MPI_MAX, comm());
  return all != 0;
}

double DemSlabs::max(double mine) const {
  double all = 0.0;
  MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_MAX, comm());
  return all;
}

double DemSlabs::min(double mine) const {
  double all = 0.0;
  MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_MIN, comm());
  return all;
}

}  // namespace hs::unresolved
