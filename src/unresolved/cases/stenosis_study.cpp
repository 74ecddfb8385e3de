// SPDX-License-Identifier: MIT
// The stenosis study's settings and axial bins.
#include "unresolved/cases/stenosis_study.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace hs::unresolved {

int StenosisStudySpec::bin_of(double x_m) const {
  if (x_m < x_lo_m || x_m > x_hi_m) return -1;
  return std::min(x_bins - 1, static_cast<int>(std::floor((x_m - x_lo_m) / bin_width_m())));
}

double StenosisStudySpec::radius_at(double x_m) const {
  const hs::common::ConstrictionProfile p{tube.radius_m, tube.throat_radius_m, tube.constriction_length_m};
  return p.half_width(x_m - throat_x_m());
}

std::vector<double> StenosisStudySpec::bin_fluid_m3() const {
  constexpr int kPanels = 64;   // even, for Simpson's rule
  std::vector<double> v;
  const double h = bin_width_m() / kPanels;
  for (int i = 0; i < x_bins; ++i) {
    const double x0 = x_lo_m + i * bin_width_m();
    double s = 0.0;
    for (int k = 0; k <= kPanels; ++k) {
      const double r = radius_at(x0 + k * h);
      const double w = (k == 0 || k == kPanels) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
      s += w * std::numbers::pi * r * r;
    }
    v.push_back(s * h / 3.0);
  }
  return v;
}

namespace {

std::array<double, 2> read_window(hs::common::ConfigSection& s, const char* key, double lo, double hi) {
  const auto w = s.numbers_in(key, lo, hi, 2);
  if (w.size() != 2 || !(w[1] > w[0])) s.fail(key, fmt::format("must be [x0, x1] (m) with x0 < x1 inside the tube [{}, {}]", lo, hi));
  return {w[0], w[1]};
}

}  // namespace

std::optional<StenosisStudySpec> parse_stenosis_study(hs::common::ConfigSection root, const hs::common::Shape& shape) {
  if (!root.has("study")) return std::nullopt;
  hs::common::ConfigSection s = root.section("study");
  const auto* tube = dynamic_cast<const hs::common::StenosedTube*>(&shape);
  if (tube == nullptr) s.fail("x_bins", "the stenosis study needs [geometry] shape = \"stenosed-tube\"");
  StenosisStudySpec c;
  c.tube = tube->spec();
  const hs::common::Vec3 d = c.tube.end_m - c.tube.start_m;
  if (!(d.x > 0.0) || d.y != 0.0 || d.z != 0.0) s.fail("x_bins", "the stenosis study bins along x: the tube must run along +x");
  c.x_lo_m = c.tube.start_m.x;
  c.x_hi_m = c.tube.end_m.x;
  c.x_bins = static_cast<int>(s.integer_in("x_bins", 2, 10000));
  c.upstream_window_m = read_window(s, "upstream_window_m", c.x_lo_m, c.x_hi_m);
  c.downstream_window_m = read_window(s, "downstream_window_m", c.x_lo_m, c.x_hi_m);
  c.wall_shear_azimuths = static_cast<int>(s.integer_in_or("wall_shear_azimuths", 1, 360, 8));
  return c;
}

}  // namespace hs::unresolved
