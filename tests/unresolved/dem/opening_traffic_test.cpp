// SPDX-License-Identifier: MIT
// Injection and removal at openings (unit tier): no overlaps, reproducible, bad inputs named.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "common/errors.hpp"
#include "common/io/checkpoint.hpp"
#include "open_tube_traffic.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;
using test::OpenTube;

constexpr double mean_velocity_m_s = 1e-3;   // RBC speeds in 10-100 um vessels are of order 1 mm/s

/// One run of `steps` steps in Poiseuille flow (kinematic); calls `check` after every exchange.
template <typename Check>
OpeningTraffic run(const OpenTube& tube, double ht_d, std::uint64_t seed, int steps, ParticleStore& p, Check&& check) {
  OpeningTraffic traffic(tube.spec(ht_d, seed), tube.shape, tube.domain);
  const VelocityField u = test::poiseuille(mean_velocity_m_s, tube.radius_m);
  const double q = mean_velocity_m_s * tube.area_m2();
  const double dt = 0.1 * default_particle_params().diameter_m / (2.0 * mean_velocity_m_s);   // 0.1 d per step at the axis
  for (int n = 0; n < steps; ++n) {
    test::advect(p, u, dt);
    const std::size_t before = p.n_owned();
    traffic.exchange(p, dt, {.flow_rate_m3_s = {q, 0.0}, .velocity_m_s = u});
    check(p, before, traffic);
  }
  return traffic;
}

TEST(OpeningTraffic, InjectedCellsTouchNeitherParticlesNorTheWall) {
  const OpenTube tube;
  ParticleStore p;
  std::size_t checked = 0;
  double closest_gap_m = 1e300, closest_wall_m = 1e300;
  // New cells are appended at the end of the store (removal only compacts the old ones).
  auto check = [&](const ParticleStore& s, std::size_t, const OpeningTraffic& t) {
    const std::size_t n_new = static_cast<std::size_t>(t.cells_injected()) - checked;
    checked += n_new;
    const auto& x = s.position_m();
    for (std::size_t i = s.n_owned() - n_new; i < s.n_owned(); ++i) {
      const Vec3 xi{x[0][i], x[1][i], x[2][i]};
      closest_wall_m = std::min(closest_wall_m, -tube.shape.signed_distance(xi) - s.radius_m()[i]);
      for (std::size_t j = 0; j < s.n_owned(); ++j) {
        if (j == i) continue;
        closest_gap_m = std::min(closest_gap_m, norm(xi - Vec3{x[0][j], x[1][j], x[2][j]}) - s.radius_m()[i] - s.radius_m()[j]);
      }
      const double r = s.radius_m()[i];
      EXPECT_TRUE(xi.x >= r * (1 - 1e-12) && xi.x <= 3.0 * r * (1 + 1e-12)) << xi.x;   // in the slab, depth r .. 3r
    }
  };
  const auto traffic = run(tube, 0.45, 7, 600, p, check);
  EXPECT_GT(checked, 100u);
  EXPECT_GE(closest_gap_m, 0.0);    // no overlap at all: the test is d >= r_i + r_j
  EXPECT_GE(closest_wall_m, 0.0);   // whole sphere in the fluid
}

TEST(OpeningTraffic, SameSeedSameCellsOtherSeedOtherCells) {
  const OpenTube tube;
  auto positions = [&](std::uint64_t seed) {
    ParticleStore p;
    (void)run(tube, 0.3, seed, 300, p, [](const ParticleStore&, std::size_t, const OpeningTraffic&) {});
    std::vector<double> x;
    for (std::size_t i = 0; i < p.n_owned(); ++i) {
      x.push_back(static_cast<double>(p.id()[i]));
      for (int a = 0; a < 3; ++a) x.push_back(p.position_m()[a][i]);
    }
    return x;
  };
  const auto a = positions(42), b = positions(42), c = positions(43);
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, b);   // bit for bit
  EXPECT_NE(a, c);
}

TEST(OpeningTraffic, RemovesAtTheOutletAndCountsBackflowAtTheInlet) {
  const OpenTube tube;
  OpeningTraffic traffic(tube.spec(0.3, 1), tube.shape, tube.domain);
  ParticleStore p;
  const double r = default_particle_params().radius_m();
  for (const Vec3 x : {Vec3{50e-6, 0, 0}, Vec3{100e-6 + 1e-9, 2e-6, 0}, Vec3{-1e-9, 0, 3e-6}, Vec3{100e-6 - 1e-9, 0, 0}}) {
    p.add({.position_m = x, .velocity_m_s = {}, .angular_velocity_rad_s = {}, .radius_m = r, .mass_kg = 1e-13,
           .id = static_cast<std::int64_t>(p.n_owned())});
  }
  traffic.exchange(p, 1e-3, {.flow_rate_m3_s = {0.0, 0.0}, .velocity_m_s = test::plug(0.0)});
  ASSERT_EQ(p.n_owned(), 2u);
  EXPECT_EQ(p.id()[0], 0);
  EXPECT_EQ(p.id()[1], 3);   // on the fluid side of the outlet plane: stays
  EXPECT_EQ(traffic.counters()[1].cells_out, 1);
  EXPECT_EQ(traffic.counters()[0].cells_out, 1);   // left backwards through the inlet
  EXPECT_DOUBLE_EQ(traffic.counters()[1].rbc_volume_out_m3, default_particle_params().volume_m3());
  EXPECT_EQ(traffic.cells_injected(), 0);          // no flow, no debt
  EXPECT_EQ(traffic.injector(0)->debt_m3(), 0.0);
  EXPECT_EQ(traffic.injector(1), nullptr);
}

TEST(OpeningTraffic, ResumedFromACheckpointItInjectsTheSameCells) {
  const OpenTube tube;
  const VelocityField u = test::poiseuille(mean_velocity_m_s, tube.radius_m);
  const double q = mean_velocity_m_s * tube.area_m2();
  const double dt = 0.1 * default_particle_params().diameter_m / (2.0 * mean_velocity_m_s);
  auto advance = [&](OpeningTraffic& t, ParticleStore& p, int steps) {
    for (int n = 0; n < steps; ++n) {
      test::advect(p, u, dt);
      t.exchange(p, dt, {.flow_rate_m3_s = {q, 0.0}, .velocity_m_s = u});
    }
  };
  OpeningTraffic whole(tube.spec(0.3, 11), tube.shape, tube.domain);
  ParticleStore p_whole;
  advance(whole, p_whole, 150);
  hs::common::Checkpoint cp;
  whole.write_state(cp, "traffic.");
  const ParticleStore p_saved = p_whole;   // the DEM checkpoint's part, here a copy
  const auto dir = std::filesystem::temp_directory_path() / "hs_opening_traffic_restart";
  cp.write(dir);
  advance(whole, p_whole, 150);

  OpeningTraffic resumed(tube.spec(0.3, 11), tube.shape, tube.domain);
  resumed.read_state(hs::common::Checkpoint::read(dir), "traffic.");
  std::filesystem::remove_all(dir);
  ParticleStore p_resumed = p_saved;
  advance(resumed, p_resumed, 150);

  ASSERT_EQ(p_whole.n_owned(), p_resumed.n_owned());
  EXPECT_EQ(p_whole.id(), p_resumed.id());
  for (int a = 0; a < 3; ++a) EXPECT_EQ(p_whole.position_m()[a], p_resumed.position_m()[a]);   // bit for bit
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(whole.counters()[k].cells_in, resumed.counters()[k].cells_in);
    EXPECT_EQ(whole.counters()[k].cells_out, resumed.counters()[k].cells_out);
  }
  EXPECT_EQ(whole.injector(0)->debt_m3(), resumed.injector(0)->debt_m3());

  hs::common::Checkpoint other;
  OpeningTrafficSpec renamed = tube.spec(0.3, 11);
  renamed.openings[1].name = "exit";
  OpeningTraffic(renamed, tube.shape, tube.domain).write_state(other, "traffic.");
  EXPECT_THROW(resumed.read_state(other, "traffic."), hs::common::ConfigError);
}

TEST(OpeningTraffic, BadInputsAreConfigErrorsNamingTheKey) {
  const OpenTube tube;
  auto message = [&](OpeningTrafficSpec spec) {
    try {
      OpeningTraffic t(spec, tube.shape, tube.domain);
    } catch (const hs::common::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  for (const double ht : {0.0, -0.1, 0.61, 1.0}) {
    const std::string m = message(tube.spec(ht, 1));
    EXPECT_NE(m.find("opening 'in': discharge_hematocrit"), std::string::npos) << m;
  }
  EXPECT_EQ(message(tube.spec(0.6, 1)), "no error");   // the bound itself is allowed
  auto off_wall = tube.spec(0.3, 1);
  off_wall.openings[0].centre_m = {0, 0, 12e-6};   // on the inlet face but beside the tube, in the wall
  off_wall.openings[0].radius_m = 1e-6;
  EXPECT_NE(message(off_wall).find("opening 'in': centre_m"), std::string::npos) << message(off_wall);
  auto mid_tube = tube.spec(0.3, 1);
  mid_tube.openings[1].centre_m = {50e-6, 0, 0};   // not on the domain boundary
  EXPECT_NE(message(mid_tube).find("opening 'out': centre_m"), std::string::npos);
  auto narrow = tube.spec(0.3, 1);
  narrow.openings[0].radius_m = 2e-6;   // narrower than one cell (r = 2.8 um)
  EXPECT_NE(message(narrow).find("opening 'in': radius_m"), std::string::npos) << message(narrow);
  auto short_list = tube.spec(0.3, 1);
  short_list.discharge_hematocrit = {0.3};
  EXPECT_NE(message(short_list), "no error");
  InjectionSpec outlet_as_inlet{.inlet = tube.openings()[1], .discharge_hematocrit = 0.3, .cell_radius_m = 2.8e-6, .seed = 1};
  EXPECT_THROW(CellInjector(outlet_as_inlet, tube.shape, tube.domain), hs::common::ConfigError);
}

}  // namespace
}  // namespace hs::unresolved
