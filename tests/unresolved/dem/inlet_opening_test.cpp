// SPDX-License-Identifier: MIT
// The opening a particle came in by: set at injection, kept through sorting, removal, ghosts, checkpoints and .vtp.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "common/io/checkpoint.hpp"
#include "open_tube_traffic.hpp"
#include "unresolved/dem/dem_checkpoint.hpp"
#include "unresolved/dem/particle_output.hpp"

namespace hs::unresolved {
namespace {

using test::OpenTube;

std::map<std::int64_t, std::int32_t> openings_by_id(const ParticleStore& p) {
  std::map<std::int64_t, std::int32_t> m;
  for (std::size_t i = 0; i < p.n_owned(); ++i) m[p.id()[i]] = p.inlet_opening()[i];
  return m;
}

TEST(ParticleStore, InletOpeningFollowsPermuteRemovalAndGhosts) {
  ParticleStore s;
  for (int k = 0; k < 4; ++k) {
    s.add({.position_m = {1.0 * k, 0, 0}, .velocity_m_s = {}, .angular_velocity_rad_s = {}, .radius_m = 0.1,
           .mass_kg = 1.0, .id = 10 + k, .inlet_opening = k - 1});
  }
  EXPECT_EQ(s.state(0).inlet_opening, no_inlet_opening);
  s.permute_owned({3, 1, 2, 0});
  EXPECT_EQ(s.inlet_opening()[0], 2);
  EXPECT_EQ(s.inlet_opening()[3], -1);
  EXPECT_EQ(s.inlet_opening()[s.add_ghost(0, {5.0, 0, 0})], 2);   // a periodic image is the same cell
  s.remove_owned({false, true, false, false});
  EXPECT_EQ(openings_by_id(s), (std::map<std::int64_t, std::int32_t>{{10, -1}, {12, 1}, {13, 2}}));
}

/// An open tube with three particles placed by hand (volume insertion: no opening), then cells injected at its
/// inlet (opening 0) by OpeningTraffic on a DemSystem, one particle removed at the outlet, a few DEM steps.
struct InjectedRun {
  OpenTube tube;
  DemSettings settings{.params = default_particle_params(), .domain = tube.domain, .time_step_s = 1.5e-7};   // below 0.1 t_Rayleigh = 1.67e-7 s
  DemSystem dem{settings, &tube.shape};

  InjectedRun() {
    const double r = settings.params.radius_m();
    dem.add_particle({0.5 * tube.length_m, 0.5 * tube.radius_m, 0}, {}, 0);
    dem.add_particle({0.3 * tube.length_m, -0.5 * tube.radius_m, 0}, {}, 1);
    dem.add_particle({tube.length_m + 0.5 * r, 0, 0}, {}, 2);   // past the outlet plane: removed at the exchange
    OpeningTraffic traffic(tube.spec(0.45, 3), tube.shape, tube.domain);
    const double mean_m_s = 1e-3;
    const double q = mean_m_s * tube.area_m2();
    // One exchange over a long interval: the debt covers ~6 cells (0.45 Q dt / 94 um^3), placed at once.
    const double dt = 6.0 * settings.params.volume_m3() / (0.45 * q);
    traffic.exchange(dem, dt, {.flow_rate_m3_s = {q, 0.0}, .velocity_m_s = test::plug(mean_m_s)});
    for (int n = 0; n < 5; ++n) dem.step();   // the first step rebuilds: wrap, cell sort, ghosts
  }
};

TEST(OpeningTraffic, InjectedCellsCarryTheirOpeningThroughSortAndCheckpoints) {
  InjectedRun run;
  const ParticleStore& p = run.dem.particles();
  ASSERT_GE(p.n_owned(), 4u);   // the two kept by hand and at least two injected
  bool sorted = false;          // the cell sort must have moved someone, or this test does not test it
  for (std::size_t i = 0; i < p.n_owned(); ++i) sorted = sorted || p.id()[i] != static_cast<std::int64_t>(i);
  EXPECT_TRUE(sorted);
  const auto expected = openings_by_id(p);
  EXPECT_EQ(expected.count(2), 0u);
  for (const auto& [id, opening] : expected) EXPECT_EQ(opening, id < 2 ? no_inlet_opening : 0) << "id " << id;

  const auto dir = std::filesystem::temp_directory_path() / "hs_inlet_opening_test";
  std::filesystem::create_directories(dir);
  hs::common::Checkpoint cp;
  write_dem_state(run.dem, cp, "dem.");
  cp.write(dir);
  DemSystem from_state(run.settings, &run.tube.shape);
  read_dem_state(from_state, hs::common::Checkpoint::read(dir), "dem.");
  EXPECT_EQ(openings_by_id(from_state.particles()), expected);
  write_dem_checkpoint(run.dem, dir / "dem.bin");
  DemSystem from_file(run.settings, &run.tube.shape);
  read_dem_checkpoint(from_file, dir / "dem.bin");
  from_file.step();
  EXPECT_EQ(openings_by_id(from_file.particles()), expected);

  // A checkpoint written before the column existed (the same arrays less "inlet_opening") reads as -1.
  hs::common::Checkpoint old;
  for (const char* name : {"dem.ids", "dem.contact_ids"}) old.put(name, cp.integers(name));
  for (const char* name : {"dem.columns", "dem.contact_shear"}) old.put(name, cp.doubles(name));
  DemSystem from_old(run.settings, &run.tube.shape);
  read_dem_state(from_old, old, "dem.");
  for (const auto& [id, opening] : openings_by_id(from_old.particles())) EXPECT_EQ(opening, no_inlet_opening);
  std::filesystem::remove_all(dir);
}

TEST(OpeningTraffic, VersionTwoDemCheckpointReadsWithoutOpenings) {
  InjectedRun run;
  const auto file = std::filesystem::temp_directory_path() / "hs_inlet_opening_v2.bin";
  write_dem_checkpoint(run.dem, file);
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Version 3 = magic, counts {n, springs}, the double columns, n ids, n int32 openings, springs (40 bytes each).
  // Version 2 is the same without the openings: cut them out and put back the old magic.
  std::uint64_t counts[2];
  std::memcpy(counts, bytes.data() + 8, sizeof counts);
  const std::size_t n = counts[0], springs_bytes = 40 * counts[1];
  const std::size_t openings_at = bytes.size() - springs_bytes - 4 * n;
  bytes.erase(openings_at, 4 * n);
  bytes[7] = '2';
  std::ofstream(file, std::ios::binary) << bytes;
  DemSystem old(run.settings, &run.tube.shape);
  read_dem_checkpoint(old, file);
  std::filesystem::remove(file);
  ASSERT_EQ(old.particles().n_owned(), n);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(old.particles().id()[i], run.dem.particles().id()[i]);   // the columns before the cut are intact
    EXPECT_EQ(old.particles().inlet_opening()[i], no_inlet_opening);
  }
}

TEST(OpeningTraffic, VtpHasTheInletOpeningAsInt32) {
  InjectedRun run;
  const ParticleStore& p = run.dem.particles();
  const auto file = std::filesystem::temp_directory_path() / "hs_inlet_opening_test.vtp";
  write_particles_vtp(p, file);
  std::ifstream in(file, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::filesystem::remove(file);
  const std::string text = buffer.str();
  const std::string tag =
      "<DataArray type=\"Int32\" Name=\"inlet_opening\" NumberOfComponents=\"1\" format=\"appended\" offset=\"";
  const auto at = text.find(tag);
  ASSERT_NE(at, std::string::npos);
  // Appended raw data: after "_", each array is a UInt64 byte count and its values; read this one back.
  const std::size_t offset = std::stoul(text.substr(at + tag.size()));
  const std::size_t data = text.find("<AppendedData encoding=\"raw\">");
  const std::size_t start = text.find('_', data) + 1 + offset;
  std::uint64_t nbytes = 0;
  std::memcpy(&nbytes, text.data() + start, sizeof nbytes);
  ASSERT_EQ(nbytes, p.n_owned() * sizeof(std::int32_t));
  std::vector<std::int32_t> values(p.n_owned());
  std::memcpy(values.data(), text.data() + start + sizeof nbytes, nbytes);
  const auto& openings = p.inlet_opening();
  EXPECT_EQ(values, std::vector<std::int32_t>(openings.begin(), openings.begin() + static_cast<long>(p.n_owned())));
}

}  // namespace
}  // namespace hs::unresolved
