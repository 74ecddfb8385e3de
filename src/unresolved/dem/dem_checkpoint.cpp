// SPDX-License-Identifier: MIT
// DEM checkpoint format: magic, counts, then each owned column as raw little-endian doubles, ids, inlet openings,
// springs.
#include "unresolved/dem/dem_checkpoint.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <ostream>
#include <vector>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/io/atomic_file.hpp"

namespace hs::unresolved {
namespace {

// 2: with the lift column; 3: with the inlet-opening column after the ids (2 is still read: openings = -1);
// 4: with the fluid-torque columns after the inlet openings (2 and 3 are still read: no fluid torque until the
// coupling sets it at the end of the next step).
constexpr std::array<char, 8> magic = {'H', 'S', 'D', 'E', 'M', 'C', 'K', '4'};
constexpr std::array<char, 8> magic_v3 = {'H', 'S', 'D', 'E', 'M', 'C', 'K', '3'};
constexpr std::array<char, 8> magic_v2 = {'H', 'S', 'D', 'E', 'M', 'C', 'K', '2'};

/// The columns in file order; the same list for writing and reading.
template <typename Store, typename F>
void for_each_saved_column(Store& p, F&& f) {
  for (auto* v3 : {&p.position_m(), &p.velocity_m_s(), &p.angular_velocity_rad_s(), &p.force_N(), &p.torque_Nm(),
                   &p.external_force_N(), &p.external_torque_Nm(), &p.fluid_velocity_m_s(), &p.drag_impulse_N_s(),
                   &p.lift_force_N(), &p.wall_shear_m()}) {
    for (auto& c : *v3) f(c);
  }
  for (auto* c : {&p.radius_m(), &p.mass_kg(), &p.drag_coefficient_N_s_m(), &p.deformation_index()}) f(*c);
}

/// The fluid-torque columns (rotational drag and the fluid's angular velocity), saved apart from the others so
/// that checkpoints written before they existed still read.
template <typename Store, typename F>
void for_each_torque_column(Store& p, F&& f) {
  for (auto& c : p.fluid_angular_velocity_rad_s()) f(c);
  f(p.rotational_drag_N_m_s());
}

template <typename T>
void put(std::ostream& out, const T* data, std::size_t n) {
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(n * sizeof(T)));
}

template <typename T>
void get(std::istream& in, T* data, std::size_t n, const std::filesystem::path& file) {
  in.read(reinterpret_cast<char*>(data), static_cast<std::streamsize>(n * sizeof(T)));
  if (!in) throw hs::common::ConfigError(fmt::format("{}: DEM checkpoint is truncated", file.string()));
}

/// The optional inlet-opening array (absent in checkpoints written before it existed: no_inlet_opening).
void read_inlet_openings(ParticleStore& p, const hs::common::Checkpoint& cp, const std::string& prefix) {
  if (!cp.has(prefix + "inlet_opening")) return;
  const std::vector<std::int64_t>& openings = cp.integers(prefix + "inlet_opening");
  if (openings.size() != p.n_owned()) {
    throw hs::common::ConfigError(fmt::format("checkpoint: DEM state \"{}\" has {} inlet openings for {} particles",
                                              prefix, openings.size(), p.n_owned()));
  }
  for (std::size_t i = 0; i < openings.size(); ++i) p.inlet_opening()[i] = static_cast<std::int32_t>(openings[i]);
}

}  // namespace

void write_dem_checkpoint(const DemSystem& dem, const std::filesystem::path& file) {
  const ParticleStore& p = dem.particles();
  const ContactHistory h = dem.contact_history();
  const std::uint64_t counts[2] = {p.n_owned(), h.keys.size()};
  hs::common::write_file_atomic(file, [&](std::ostream& out) {
    put(out, magic.data(), magic.size());
    put(out, counts, 2);
    for_each_saved_column(p, [&](const std::vector<double>& c) { put(out, c.data(), p.n_owned()); });
    put(out, p.id().data(), p.n_owned());
    put(out, p.inlet_opening().data(), p.n_owned());
    for_each_torque_column(p, [&](const std::vector<double>& c) { put(out, c.data(), p.n_owned()); });
    for (std::size_t k = 0; k < h.keys.size(); ++k) {
      const std::int64_t ids[2] = {h.keys[k].first, h.keys[k].second};
      put(out, ids, 2);
      put(out, h.shear_m[k].data(), 3);
    }
  });
}

void read_dem_checkpoint(DemSystem& dem, const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::array<char, 8> head{};
  if (!in) throw hs::common::ConfigError(fmt::format("{}: cannot open the DEM checkpoint", file.string()));
  get(in, head.data(), head.size(), file);
  if (head != magic && head != magic_v3 && head != magic_v2) {
    throw hs::common::ConfigError(fmt::format("{}: not a hemoscale DEM checkpoint of this version", file.string()));
  }
  std::uint64_t counts[2] = {0, 0};
  get(in, counts, 2, file);
  ParticleStore& p = dem.particles();
  p = ParticleStore{};
  for (std::uint64_t i = 0; i < counts[0]; ++i) p.add({});
  for_each_saved_column(p, [&](std::vector<double>& c) { get(in, c.data(), counts[0], file); });
  get(in, p.id().data(), counts[0], file);
  if (head != magic_v2) get(in, p.inlet_opening().data(), counts[0], file);   // v2: left at no_inlet_opening
  if (head == magic) for_each_torque_column(p, [&](std::vector<double>& c) { get(in, c.data(), counts[0], file); });
  ContactHistory h;
  for (std::uint64_t k = 0; k < counts[1]; ++k) {
    std::int64_t ids[2];
    std::array<double, 3> s{};
    get(in, ids, 2, file);
    get(in, s.data(), 3, file);
    h.keys.emplace_back(ids[0], ids[1]);
    h.shear_m.push_back(s);
  }
  dem.restore_contact_history(std::move(h));
}

void write_dem_state(const DemSystem& dem, hs::common::Checkpoint& cp, const std::string& prefix) {
  const ParticleStore& p = dem.particles();
  const std::size_t n = p.n_owned();
  std::vector<double> columns;
  for_each_saved_column(p, [&](const std::vector<double>& c) { columns.insert(columns.end(), c.begin(), c.begin() + static_cast<long>(n)); });
  cp.put(prefix + "columns", columns);
  std::vector<double> torque;
  for_each_torque_column(p, [&](const std::vector<double>& c) { torque.insert(torque.end(), c.begin(), c.begin() + static_cast<long>(n)); });
  cp.put(prefix + "torque_columns", torque);
  cp.put(prefix + "ids", std::span<const std::int64_t>(p.id().data(), n));
  const auto& openings = p.inlet_opening();
  cp.put(prefix + "inlet_opening",
         std::vector<std::int64_t>(openings.begin(), openings.begin() + static_cast<long>(n)));
  const ContactHistory h = dem.contact_history();
  std::vector<std::int64_t> keys;
  std::vector<double> shear;
  for (std::size_t k = 0; k < h.keys.size(); ++k) {
    keys.insert(keys.end(), {h.keys[k].first, h.keys[k].second});
    shear.insert(shear.end(), h.shear_m[k].begin(), h.shear_m[k].end());
  }
  cp.put(prefix + "contact_ids", keys);
  cp.put(prefix + "contact_shear", shear);
}

void read_dem_state(DemSystem& dem, const hs::common::Checkpoint& cp, const std::string& prefix) {
  const std::vector<std::int64_t>& ids = cp.integers(prefix + "ids");
  const std::vector<double>& columns = cp.doubles(prefix + "columns");
  const std::vector<std::int64_t>& keys = cp.integers(prefix + "contact_ids");
  const std::vector<double>& shear = cp.doubles(prefix + "contact_shear");
  const std::size_t n = ids.size();
  ParticleStore& p = dem.particles();
  p = ParticleStore{};
  for (std::size_t i = 0; i < n; ++i) p.add({});
  std::size_t count = 0;
  for_each_saved_column(p, [&](std::vector<double>&) { ++count; });
  if (columns.size() != count * n || keys.size() % 2 != 0 || 3 * (keys.size() / 2) != shear.size()) {
    throw hs::common::ConfigError(fmt::format("checkpoint: DEM state \"{}\" is inconsistent ({} ids, {} column values, {} contacts)",
                                              prefix, n, columns.size(), keys.size() / 2));
  }
  std::size_t at = 0;
  for_each_saved_column(p, [&](std::vector<double>& c) {
    std::copy(columns.begin() + static_cast<long>(at), columns.begin() + static_cast<long>(at + n), c.begin());
    at += n;
  });
  std::copy(ids.begin(), ids.end(), p.id().begin());
  read_inlet_openings(p, cp, prefix);
  if (cp.has(prefix + "torque_columns")) {   // absent before the fluid torque existed: none until the next step sets it
    const std::vector<double>& torque = cp.doubles(prefix + "torque_columns");
    if (torque.size() != 4 * n) {
      throw hs::common::ConfigError(fmt::format("checkpoint: DEM state \"{}\" has {} fluid-torque values for {} particles",
                                                prefix, torque.size(), n));
    }
    std::size_t t = 0;
    for_each_torque_column(p, [&](std::vector<double>& c) {
      std::copy(torque.begin() + static_cast<long>(t), torque.begin() + static_cast<long>(t + n), c.begin());
      t += n;
    });
  }
  ContactHistory h;
  for (std::size_t k = 0; k < keys.size() / 2; ++k) {
    h.keys.emplace_back(keys[2 * k], keys[2 * k + 1]);
    h.shear_m.push_back({shear[3 * k], shear[3 * k + 1], shear[3 * k + 2]});
  }
  dem.restore_contact_history(std::move(h));
}

}  // namespace hs::unresolved
