// SPDX-License-Identifier: MIT
// Growth packing: Monte Carlo moves of rigid cells under a hard overlap test while their common size grows to full.
#include "resolved/cases/cell_packing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hs::resolved::placement {
namespace {

using common::Vec3;

/// The start fills this fraction of the box with shrunken cells: random sequential addition reaches 0.18 at full size
/// in the shear-suspension box, so a tenth places at once.
constexpr double kStartFill = 0.1;
/// Each failed start shrinks the cells by this factor; below the smallest size the box is hopeless.
constexpr double kStartShrink = 0.9;
constexpr double kSmallestStart = 0.2;
/// Acceptance window of the trial moves (a common choice for hard-particle Monte Carlo) and the step's change.
constexpr double kAcceptLow = 0.3;
constexpr double kAcceptHigh = 0.5;
constexpr double kStepChange = 1.2;
/// First growth step in scale, its cap (a step that large is tried only while the cells are far apart) and its floor
/// (so that a run of failed tries does not leave a step that takes as many successes to grow back).
constexpr double kFirstGrowth = 0.01;
constexpr double kMaxGrowth = 0.05;
constexpr double kMinGrowth = 1.0e-5;
/// Jammed: at the size's growth rate over the last window of sweeps (it only slows as the cells crowd), full size
/// would not be reached within the sweeps left.
constexpr long kRateWindow = 200;
/// A stream of its own, so that the packing does not depend on how many tries the full-size addition spent.
constexpr std::uint64_t kPackingStream = 0x7061636bULL;

}  // namespace

PackingResult grow_packing(const CellGeometry& g, long n, std::uint64_t seed, int attempts_per_cell, long max_sweeps) {
  PackingResult out;
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32U),
                    static_cast<std::uint32_t>(kPackingStream)};
  std::mt19937_64 rng(seq);
  const PlacementBox& box = g.box();
  double box_m3 = 1.0;
  for (int a = 0; a < 3; ++a) box_m3 *= box.upper_m[a] - box.lower_m[a];
  double scale = std::min(1.0, std::cbrt(kStartFill * box_m3 / (static_cast<double>(n) * g.cell_volume_m3())));
  for (;; scale *= kStartShrink) {
    if (scale < kSmallestStart) return out;   // not even small cells fit: incomplete, scale 0
    std::mt19937_64 trial = rng;
    out.poses = random_sequential_addition(g, n, scale, attempts_per_cell, trial, out.attempts);
    if (static_cast<long>(out.poses.size()) == n) {
      rng = trial;
      break;
    }
  }
  out.start_scale = scale;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::vector<Vec3>> x(static_cast<std::size_t>(n));
  VertexBins bins(box, g.gap_m()), scratch(box, g.gap_m());
  const auto rebuild = [&] {
    bins.clear();
    for (long i = 0; i < n; ++i) {
      (void)g.vertices_within_walls(out.poses[i], scale, x[i]);
      bins.add(static_cast<int>(i), x[i]);
    }
  };
  rebuild();
  double step = 0.1 * scale * g.radius_m();   // translation; rotation turns the rim by about as much
  double growth = kFirstGrowth;
  std::vector<double> history;   // scale after each sweep
  std::vector<Vec3> trial;
  while (out.sweeps < max_sweeps) {
    long accepted = 0;
    for (long i = 0; i < n; ++i) {
      Pose moved = out.poses[i];
      for (int a = 0; a < 3; ++a) moved.centre[a] += step * (2.0 * unit(rng) - 1.0);
      moved.centre = g.wrapped(moved.centre);
      const double cos_polar = 2.0 * unit(rng) - 1.0, azimuth = 2.0 * std::numbers::pi * unit(rng);
      const double sin_polar = std::sqrt(1.0 - cos_polar * cos_polar);
      const Vec3 axis{sin_polar * std::cos(azimuth), sin_polar * std::sin(azimuth), cos_polar};
      moved.q = turned(moved.q, axis, step / (scale * g.radius_m()) * (2.0 * unit(rng) - 1.0));
      bool ok = g.vertices_within_walls(moved, scale, trial);
      for (std::size_t v = 0; v < trial.size() && ok; ++v) ok = !bins.any_within(trial[v], static_cast<int>(i));
      for (long j = 0; j < n && ok; ++j) ok = j == i || !g.interpenetrate(moved, out.poses[j], scale);
      if (!ok) continue;
      ++accepted;
      bins.remove(static_cast<int>(i), x[i]);
      x[i] = trial;
      bins.add(static_cast<int>(i), x[i]);
      out.poses[i] = moved;
    }
    ++out.sweeps;
    const double acceptance = static_cast<double>(accepted) / static_cast<double>(n);
    if (acceptance > kAcceptHigh) step = std::min(step * kStepChange, scale * g.radius_m());
    if (acceptance < kAcceptLow) step /= kStepChange;
    const double bigger = std::min(1.0, scale + growth);
    if (all_clear(g, out.poses, bigger, scratch)) {
      scale = bigger;
      growth = std::min(2.0 * growth, kMaxGrowth);
      rebuild();
    } else {
      growth = std::max(0.5 * growth, kMinGrowth);
    }
    history.push_back(scale);
    if (scale == 1.0) break;
    if (out.sweeps > kRateWindow) {
      const double rate = (scale - history[history.size() - 1 - kRateWindow]) / kRateWindow;
      const double sweeps_needed = (1.0 - scale) / rate;
      if (rate <= 0.0 || static_cast<double>(out.sweeps) + sweeps_needed > static_cast<double>(max_sweeps)) break;
    }
  }
  out.scale = scale;
  return out;
}

}  // namespace hs::resolved::placement
