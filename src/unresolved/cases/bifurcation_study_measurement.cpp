// SPDX-License-Identifier: MIT
// The bifurcation study's per-step counts.
#include "unresolved/cases/bifurcation_study_measurement.hpp"
#include "unresolved/cases/closure_validity_report.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

namespace hs::unresolved {
namespace {

/// Bin of x among n equal bins of [lo, hi] (x = hi in the last): -1 below, n above.
int bin_of(double x, double lo, double hi, int n) {
  if (x < lo) return -1;
  if (x > hi) return n;
  return std::min(n - 1, static_cast<int>(std::floor((x - lo) / (hi - lo) * n)));
}

}  // namespace

BifurcationStudyMeasurement::BifurcationStudyMeasurement(const OpenGeometryConfig& c, BifurcationStudySpec spec)
    : base_(c), spec_(std::move(spec)), fluid_stores_(c.model.void_fraction_rate) {
  for (const auto& o : c.openings) {
    if (o.type == hs::common::OpeningFlowType::flow_rate_inlet) inlets_.push_back(o.opening.name);
  }
  for (int b = 1; b <= 2; ++b) bin_fluid_m3_.push_back(spec_.cut_bin_fluid_m3(b));
}

std::vector<std::string> BifurcationStudyMeasurement::columns() const {
  std::vector<std::string> cols = base_.columns();
  for (int b = 1; b <= 2; ++b) {
    const std::string& name = spec_.branches[static_cast<std::size_t>(b)].name;
    cols.push_back(name + "_cut_ht");
    for (int i = 0; i < spec_.profile_bins; ++i) cols.push_back(fmt::format("{}_cut_rbc_m3_bin_{}", name, i));
  }
  for (const auto& br : spec_.branches) {
    for (const char* what : {"_cells", "_di_sum", "_di_below", "_di_above"}) cols.push_back(br.name + what);
    for (int i = 0; i < spec_.di_bins; ++i) cols.push_back(fmt::format("{}_di_bin_{}", br.name, i));
  }
  return cols;
}

std::vector<double> BifurcationStudyMeasurement::sample(const CfdDemSolvers& run) {
  std::vector<double> row = base_.sample(run);
  const ParticleStore& p = run.dem().particles();
  const auto bins = static_cast<std::size_t>(spec_.profile_bins);
  const auto di_bins = static_cast<std::size_t>(spec_.di_bins);
  std::vector<std::vector<double>> cut(2, std::vector<double>(bins, 0.0));
  // Per branch: cells, DI sum, below, above, then the DI bins.
  std::vector<std::vector<double>> di(3, std::vector<double>(4 + di_bins, 0.0));
  for (std::size_t i = 0; i < p.n_owned(); ++i) {
    const hs::common::Vec3 x{p.position_m()[0][i], p.position_m()[1][i], p.position_m()[2][i]};
    const double d = p.deformation_index()[i];
    auto& h = di[static_cast<std::size_t>(spec_.branch_of(x))];
    h[0] += 1.0;
    h[1] += d;
    const int k = bin_of(d, spec_.di_lo, spec_.di_hi, spec_.di_bins);
    h[k < 0 ? 2 : (k >= spec_.di_bins ? 3 : 4 + static_cast<std::size_t>(k))] += 1.0;
    for (int b = 1; b <= 2; ++b) {
      if (const auto w = spec_.cut_coordinate(b, x)) {
        const int j = bin_of(*w, 0.0, 1.0, spec_.profile_bins);
        cut[static_cast<std::size_t>(b - 1)][static_cast<std::size_t>(j)] += 4.0 / 3.0 * std::numbers::pi * std::pow(p.radius_m()[i], 3);
      }
    }
  }
  for (std::size_t b = 0; b < 2; ++b) {
    double volume = 0.0;
    double fluid = 0.0;
    for (std::size_t k = 0; k < bins; ++k) {
      volume += cut[b][k];
      fluid += bin_fluid_m3_[b][k];
    }
    row.push_back(volume / fluid);
    row.insert(row.end(), cut[b].begin(), cut[b].end());
  }
  for (const auto& h : di) row.insert(row.end(), h.begin(), h.end());
  return row;
}

nlohmann::json BifurcationStudyMeasurement::summary(const CfdDemSolvers& run, const std::vector<std::vector<double>>& rows) const {
  nlohmann::json j = base_.summary(run, rows);
  nlohmann::json names = nlohmann::json::array();
  for (const auto& br : spec_.branches) names.push_back(br.name);
  j["results"]["study_layout"] = {{"branches", names}, {"profile_bins", spec_.profile_bins}, {"cut_bin_fluid_m3", bin_fluid_m3_},
                                  {"cut_distance_m", spec_.cut_distance_m}, {"cut_thickness_m", spec_.cut_thickness_m},
                                  {"di_range", {spec_.di_lo, spec_.di_hi}}, {"di_bins", spec_.di_bins},
                                  {"di_threshold", spec_.di_threshold}, {"inlets", inlets_},
                                  {"fluid_stores", fluid_stores_}, {"dt_s", run.fluid().settings().dt_s}};
  // How often the closures saw inputs outside their validity box (clamped there): issue 22's acceptance asks it.
  j["results"]["closure_validity"] = closure_validity_report(run.coupling().closures());
  return j;
}

}  // namespace hs::unresolved
