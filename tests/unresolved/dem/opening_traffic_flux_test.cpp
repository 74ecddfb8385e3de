// SPDX-License-Identifier: MIT
// Injection and removal over whole runs (verification tier): exact cell bookkeeping and the injected RBC volume
// flux against Ht_d Q over more than 10 transit times, with particles moved by a prescribed velocity field or
// by the DEM integrator.
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>
#include <set>

#include "open_tube_traffic.hpp"
#include "unresolved/dem/dem_system.hpp"

namespace hs::unresolved {
namespace {

using test::OpenTube;

constexpr double mean_velocity_m_s = 1e-3;

struct FluxRun {
  double injected_over_owed = 0.0;   // RBC volume injected / (Ht_d Q T)
  double worst_lag_cells = 0.0;      // largest (owed - injected) / V_cell seen at any step
  double worst_lead_cells = 0.0;     // largest (injected - owed) / V_cell: > 0 would be a burst
  double final_debt_cells = 0.0;
  std::int64_t cells_in = 0;
  std::int64_t cells_out = 0;
  std::size_t present = 0;
  bool bookkeeping_exact = true;
  bool ids_unique = true;
};

FluxRun run_kinematic(double ht_d, const VelocityField& u, double transits) {
  const OpenTube tube;
  OpeningTraffic traffic(tube.spec(ht_d, 2024), tube.shape, tube.domain);
  ParticleStore p;
  const double q = mean_velocity_m_s * tube.area_m2();
  const double v_cell = default_particle_params().volume_m3();
  const double dt = 0.1 * default_particle_params().diameter_m / (2.0 * mean_velocity_m_s);   // 0.1 d per step at the axis
  const auto steps = static_cast<int>(transits * tube.length_m / mean_velocity_m_s / dt);
  FluxRun out;
  std::set<std::int64_t> ids;
  for (int n = 1; n <= steps; ++n) {
    test::advect(p, u, dt);
    traffic.exchange(p, dt, {.flow_rate_m3_s = {q, 0.0}, .velocity_m_s = u});
    const double owed = ht_d * q * dt * n;
    const double in = traffic.counters()[0].rbc_volume_in_m3;
    out.worst_lag_cells = std::max(out.worst_lag_cells, (owed - in) / v_cell);
    out.worst_lead_cells = std::max(out.worst_lead_cells, (in - owed) / v_cell);
    if (traffic.cells_injected() != traffic.cells_removed() + static_cast<std::int64_t>(p.n_owned())) out.bookkeeping_exact = false;
    for (std::size_t i = 0; i < p.n_owned(); ++i) ids.insert(p.id()[i]);
  }
  out.ids_unique = static_cast<std::int64_t>(ids.size()) == traffic.cells_injected();
  out.injected_over_owed = traffic.counters()[0].rbc_volume_in_m3 / (ht_d * q * dt * steps);
  out.final_debt_cells = traffic.injector(0)->debt_cells();
  out.cells_in = traffic.counters()[0].cells_in;
  out.cells_out = traffic.counters()[1].cells_out;
  out.present = p.n_owned();
  return out;
}

void report(const std::string& name, const FluxRun& r) {
  std::printf("%s: injected/owed = %.5f, lag <= %.2f cells, lead <= %.2f cells, in %lld, out %lld, present %zu\n",
              name.c_str(), r.injected_over_owed, r.worst_lag_cells, r.worst_lead_cells, static_cast<long long>(r.cells_in),
              static_cast<long long>(r.cells_out), r.present);
}

TEST(OpeningTrafficFlux, PlugFlowBookkeepingExactAndFluxWithinTwoPercent) {
  const OpenTube tube;
  for (const double ht : {0.1, 0.3}) {
    const FluxRun r = run_kinematic(ht, test::plug(mean_velocity_m_s), 12.0);
    report("plug Ht_d=" + std::to_string(ht), r);
    EXPECT_TRUE(r.bookkeeping_exact);
    EXPECT_TRUE(r.ids_unique);
    EXPECT_EQ(r.cells_in, r.cells_out + static_cast<std::int64_t>(r.present));   // nothing leaves by the inlet here
    // Acceptance of #21: the injected RBC volume flux within 2% of Ht_d Q over >= 10 transit times.
    EXPECT_NEAR(r.injected_over_owed, 1.0, 0.02);
    // No start-up burst: never ahead of what is owed (whole cells only when the debt covers one) ...
    EXPECT_LE(r.worst_lead_cells, 1e-9);
    // ... and never more than 2 cells behind (1 for the whole-cell rounding, 1 for a slot not free this step).
    EXPECT_LT(r.worst_lag_cells, 2.0);
  }
}

TEST(OpeningTrafficFlux, PoiseuilleFlowFluxWeightedInjectionUpToNormalHematocrit) {
  const OpenTube tube;
  for (const double ht : {0.3, 0.45}) {
    const FluxRun r = run_kinematic(ht, test::poiseuille(mean_velocity_m_s, tube.radius_m), 12.0);
    report("poiseuille Ht_d=" + std::to_string(ht), r);
    EXPECT_TRUE(r.bookkeeping_exact);
    EXPECT_TRUE(r.ids_unique);
    EXPECT_NEAR(r.injected_over_owed, 1.0, 0.02);   // the acceptance of #21, as above
    EXPECT_LE(r.worst_lead_cells, 1e-9);
    // Behind by at most a few cells: measured 1.0 (0.3) and 3.3 (0.45); slots near the slow wall free up late.
    EXPECT_LT(r.worst_lag_cells, 6.0);
  }
}

TEST(OpeningTrafficFlux, AboveTheRandomPackingLimitTheDebtShows) {
  // In plug flow the inflow is a random sequential packing that never shears apart; it jams at a tube
  // hematocrit of ~0.37 here (RSA of spheres: ~0.38). Asked for 0.45, the inlet falls behind, and says so.
  const FluxRun r = run_kinematic(0.45, test::plug(mean_velocity_m_s), 12.0);
  report("plug Ht_d=0.45 (beyond jamming)", r);
  EXPECT_TRUE(r.bookkeeping_exact);   // bookkeeping stays exact even so
  EXPECT_LT(r.injected_over_owed, 0.9);
  EXPECT_GT(r.final_debt_cells, 100.0);
}

/// The same open tube with the DEM integrator: every cell dragged (Stokes, plasma 1.2 mPa s) towards a uniform
/// fluid velocity; removal and injection between steps through DemSystem's spring-keeping edits.
TEST(OpeningTrafficFlux, DemRunBookkeepingExact) {
  const OpenTube tube;
  ParticleParams params = default_particle_params();
  DemSystem dem({.params = params, .domain = tube.domain, .time_step_s = 1e-7}, &tube.shape);
  OpeningTraffic traffic(tube.spec(0.3, 5), tube.shape, tube.domain);
  const double u = 0.02;   // fast (the default impact-speed bound) to cross 100 um in 5e4 steps
  const double beta = 3.0 * std::numbers::pi * 1.2e-3 * params.diameter_m;
  const VelocityField field = test::plug(u);
  const double q = u * tube.area_m2();
  const int steps = static_cast<int>(1.5 * tube.length_m / u / dem.time_step_s());
  for (int n = 0; n < steps; ++n) {
    auto& p = dem.particles();
    auto& b = p.drag_coefficient_N_s_m();
    auto& uf = p.fluid_velocity_m_s();
    for (std::size_t i = 0; i < p.n_owned(); ++i) {
      b[i] = beta;
      uf[0][i] = u;
      uf[1][i] = uf[2][i] = 0.0;
    }
    dem.step();
    traffic.exchange(dem, dem.time_step_s(), {.flow_rate_m3_s = {q, 0.0}, .velocity_m_s = field});
    ASSERT_EQ(traffic.cells_injected(), traffic.cells_removed() + static_cast<std::int64_t>(dem.particles().n_owned()))
        << "step " << n;
  }
  std::printf("DEM run: %d steps, in %lld, out %lld, present %zu, debt %.2f cells\n", steps,
              static_cast<long long>(traffic.cells_injected()), static_cast<long long>(traffic.cells_removed()),
              dem.particles().n_owned(), traffic.injector(0)->debt_cells());
  EXPECT_GT(traffic.cells_removed(), 20);   // cells went all the way through
  EXPECT_EQ(dem.stats().pair_contacts, 0u);   // co-moving cells injected apart never touch
}

}  // namespace
}  // namespace hs::unresolved
