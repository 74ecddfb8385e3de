// SPDX-License-Identifier: MIT
#include "resolved/cases/plate_cell_checks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "resolved/measure/flow_mode.hpp"

namespace hs::resolved {
namespace {

/// The flow mode is read over the run's second half, so the run must span the release transient and then at least
/// one Jeffery period to tell a tumbling cell from a tank-treading one: two periods in all.
constexpr double kJefferyPeriodsForMode = 2.0;
/// Three half turns give one full tumbling period after the first crossing (TumblingPeriod).
constexpr int kHalfTurnsForPeriod = 3;
/// How far the vertex-mean centroid may step back from the centreline between samples and still count as going
/// toward it: a membrane that changes shape moves that mean by a fraction of dx (0.1 dx per sample here, 0.1 um at
/// dx = 1 um, H = 24 um: 0.004 H) without the cell moving.
constexpr double kCentroidJitterDx = 0.1;

void check_shear(const PlateCellConfig& c, const nlohmann::json& r, const std::vector<PlateCellSample>& samples,
                 hs::common::CheckList& checks) {
  const double simulated_s = samples.empty() ? 0.0 : samples.back().time_s;
  const double jeffery_s = jeffery_period(c.shear_rate_1_s);
  // Always checked once the mode can be read: a tank-treading (or swinging) membrane of axes a1, a2 in the shear plane turns at
  // most at gamma_dot a1 a2 / (a1^2 + a2^2) <= gamma_dot / 2 (Keller & Skalak 1982; equality for a sphere).
  if (simulated_s >= kJefferyPeriodsForMode * jeffery_s &&
      (r.value("flow_mode", "") == "tank-treading" || r.value("membrane_tank_treads", false))) {
    const double rate = std::abs(r.value("marker_rate_rad_s", 0.0));
    const double bound = 0.5 * c.shear_rate_1_s;
    checks.expect("membrane rate within the Keller-Skalak bound gamma_dot / 2", rate <= bound,
                  fmt::format("{:.4g} rad/s, bound {:.4g} rad/s", rate, bound));
    // The same bound for the cell's own axes (#26): its rate over the last whole revolutions (the second half's
    // without one) against gamma_dot a1 a2 / (a1^2 + a2^2) from the DI over that window.
    const double settled_hz = r.value("tank_treading_frequency_settled_hz", 0.0);
    const double own_rate = settled_hz > 0.0 ? 2.0 * std::numbers::pi * settled_hz : rate;
    const double own_bound = r.value("keller_skalak_bound_rad_s", bound);
    checks.expect("membrane rate within the Keller-Skalak bound of the measured axes", own_rate <= own_bound,
                  fmt::format("{:.4g} rad/s, bound {:.4g} rad/s at DI {:.3f}", own_rate, own_bound,
                              r.value("di_settled", r.value("di_mean", 0.0))));
  }
  if (c.expect_flow_mode.empty()) return;
  const std::string mode_name = fmt::format("flow mode {}", c.expect_flow_mode);
  if (simulated_s < kJefferyPeriodsForMode * jeffery_s) {
    checks.skip(mode_name, fmt::format("{:.3g} s simulated, under the {:g} Jeffery periods ({:.3g} s) the mode needs",
                                       simulated_s, kJefferyPeriodsForMode, kJefferyPeriodsForMode * jeffery_s));
  } else {
    const std::string mode = r.value("flow_mode", "");
    checks.expect(mode_name, mode == c.expect_flow_mode, fmt::format("measured {}", mode));
  }
  if (c.period_over_jeffery_max <= 0.0) return;
  const std::string period_name =
      fmt::format("tumbling period / Jeffery's in [{:g}, {:g}]", c.period_over_jeffery_min, c.period_over_jeffery_max);
  const int half_turns = r.value("tumbling_half_turns", 0);
  if (half_turns < kHalfTurnsForPeriod) {
    const std::string what = fmt::format("{} half turn(s): no tumbling period to compare", half_turns);
    if (simulated_s < kJefferyPeriodsForMode * jeffery_s) {
      checks.skip(period_name, what + ", in too short a run to require one");
    } else {
      checks.expect(period_name, false, what);
    }
    return;
  }
  const double ratio = r.value("tumbling_period_over_jeffery", 0.0);
  checks.expect(period_name, ratio >= c.period_over_jeffery_min && ratio <= c.period_over_jeffery_max,
                fmt::format("{:.3f} ({} half turns, Jeffery {:.4g} s)", ratio, half_turns, jeffery_s));
}

void check_migration(const PlateCellConfig& c, const std::vector<PlateCellSample>& samples, hs::common::CheckList& checks) {
  if (!c.expect_toward_centreline) return;
  const double h = c.gap_m;
  const double spin_up_s = static_cast<double>(c.spin_up_steps) * c.numerics.dt_s;
  std::vector<double> offsets;   // |y - H/2| / H after the drive's spin-up
  for (const PlateCellSample& s : samples) {
    if (s.time_s >= spin_up_s) offsets.push_back(std::abs(s.centroid_m.y - 0.5 * h) / h);
  }
  if (offsets.size() < 2) {
    checks.skip("toward the centreline", "no samples after the drive's spin-up");
    return;
  }
  const double initial = std::abs(c.initial_height - 0.5);
  const double jitter = kCentroidJitterDx * c.numerics.dx_m / h;
  // Closer by more than the centroid's jitter: a cell that does not migrate, its centroid moved only by its shape,
  // must not pass.
  checks.expect("toward the centreline (final offset below the release offset by more than the jitter)",
                offsets.back() < initial - jitter,
                fmt::format("|y/H - 0.5|: {:.4f} at release, {:.4f} at the end (jitter {:.4f})", initial, offsets.back(),
                            jitter));
  double closest = offsets.front();
  double worst_back = 0.0;
  for (const double o : offsets) {
    worst_back = std::max(worst_back, o - closest);
    closest = std::min(closest, o);
  }
  checks.expect("without turning back (after the spin-up)", worst_back <= jitter,
                fmt::format("largest step back {:.4f} H (allowed {:.4f} H = {:g} dx)", worst_back, jitter, kCentroidJitterDx));
}

}  // namespace

hs::common::CheckList plate_cell_checks(const PlateCellConfig& c, const nlohmann::json& results,
                                        const std::vector<PlateCellSample>& samples) {
  hs::common::CheckList checks;
  if (c.flow == PlateFlow::shear) {
    check_shear(c, results, samples, checks);
  } else {
    check_migration(c, samples, checks);
  }
  return checks;
}

}  // namespace hs::resolved
