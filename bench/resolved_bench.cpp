// SPDX-License-Identifier: MIT
// `hemoscale bench resolved`: the shipped tube-drag case (r* = 0.5, Re = 0.5, dx = 1 um, one thread as in the
// campaign) run for a fixed number of steps, three times: wall seconds per simulated millisecond, ms per lattice step
// and the shares of LBM / IBM / membrane from the run's own stage timings (medians). The campaign projection sums,
// over the 60 runs of cases/campaign/tube-re-rstar, the lattice steps each needs (its dt and Jeffery period come from
// the same reader the runs use) at the measured cost per step, divided by the campaign's concurrent jobs.
// The same is measured with the cytoplasm at the plasma's viscosity (ratio 1, one fluid), back to back with the
// shipped case, so that the cost of the inner fluid (its tau cap lowers dt) is read from one machine state.
#include <omp.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/resolved_bench.hpp"
#include "bench/bench_targets.hpp"
#include "common/config/config_file.hpp"
#include "common/run_folder.hpp"
#include "resolved/cases/tube_cell.hpp"
#include "resolved/cases/tube_cell_config.hpp"

namespace hs::bench {
namespace {

namespace fs = std::filesystem;

/// The campaign grid and its stopping rule (cases/campaign/tube-re-rstar/campaign.toml, tube-drag/case.toml).
constexpr std::array kReynolds{0.1, 0.2, 0.3, 0.4, 0.5};
constexpr std::array kRadialPositions{0.2, 0.3, 0.4, 0.5, 0.6, 0.7};
constexpr int kSetups = 2;          // drag and lift
constexpr int kCampaignJobs = 2;    // runs at once, one thread each
constexpr double kExpectedPeriods = 4.0;   // settling rule: after the membrane transient, 3 agreeing periods + ~1

std::string shipped_case_text() {
  std::ifstream in(fs::path(HS_CASES_DIR) / "resolved/tube-drag/case.toml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  if (pos == std::string::npos) throw std::runtime_error("bench resolved: '" + from + "' not in tube-drag/case.toml");
  return text.replace(pos, from.size(), to);
}

/// The shipped case, or the same with the cytoplasm at the plasma's own viscosity (rho nu of [fluid]: ratio 1). A
/// case that states cytoplasm_viscosity_Pa_s itself is rejected for the ratio-1 variant rather than silently measured.
std::string case_text(bool ratio_one) {
  std::string text = shipped_case_text();
  if (!ratio_one) return text;
  if (text.find("cytoplasm_viscosity_Pa_s") != std::string::npos) {
    throw std::runtime_error("bench resolved: tube-drag/case.toml sets cytoplasm_viscosity_Pa_s; the ratio-1 variant "
                             "inserts its own");
  }
  return with(text, "[cell]\n", "[cell]\ncytoplasm_viscosity_Pa_s = 1.025e-3\n");   // 1025 kg/m^3 x 1e-6 m^2/s
}

hs::resolved::TubeCellConfig grid_point(bool ratio_one, double reynolds, double r_star) {
  std::string text = with(case_text(ratio_one), "reynolds = 0.5 ", fmt::format("reynolds = {} ", reynolds));
  text = with(text, "radial_position = 0.5 ", fmt::format("radial_position = {} ", r_star));
  auto file = common::ConfigFile::parse(text, "tube-drag/case.toml");
  (void)file->root().section("case").string("type");
  return hs::resolved::read_tube_cell(*file, false);
}

/// Lattice steps of the whole campaign when every run goes through the membrane transient and then `periods` Jeffery
/// periods (capped by its own limit).
double campaign_steps(bool ratio_one, double periods) {
  double steps = 0.0;
  for (double re : kReynolds) {
    for (double r : kRadialPositions) {
      const auto c = grid_point(ratio_one, re, r);
      steps += kSetups * std::min(c.transient_s + periods * hs::resolved::jeffery_period_s(c), c.max_time_s) / c.dt_s;
      if (c.extrapolate_lattice_memory) {   // the half-time-step stage: a short start-up, the same periods, 2x the steps
        const auto h = hs::resolved::half_time_step_stage(c);
        steps += kSetups * std::min(h.transient_s + periods * hs::resolved::jeffery_period_s(h), h.max_time_s) / h.dt_s;
      }
    }
  }
  return steps;
}

struct Sample {
  double s_per_sim_ms;
  double ms_per_step;
  double lbm_share, ibm_share, membrane_share;
};

Sample run_once(const fs::path& dir, bool ratio_one, double max_time_s) {
  // One stage: the cost per step and per simulated ms of stage 1 (the half-time-step stage runs the same steps at half
  // the dt; campaign_steps() counts its steps).
  std::string text = with(case_text(ratio_one), "max_jeffery_periods = 6 ", fmt::format("max_time_s = {} ", max_time_s));
  if (text.find("extrapolate_lattice_memory = true ") != std::string::npos) {
    text = with(text, "extrapolate_lattice_memory = true ", "extrapolate_lattice_memory = false ");
  }
  auto file = common::ConfigFile::parse(with(text, "vtk_every_s = 0.05 ", "vtk_every_s = 0.0 "), "tube-drag/case.toml");
  (void)file->root().section("case").string("type");
  fs::remove_all(dir / "out");
  const common::CaseRequest request{.case_dir = dir, .config = file.get(), .output_dir = dir / "out", .quiet = true};
  (void)hs::resolved::run_tube_cell(request);
  std::ifstream in(dir / "out" / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  const auto& t = summary.at("timings");
  double total = 0.0;
  for (const auto& [name, stage] : t.items()) total += stage.at("seconds").get<double>();
  auto share = [&](std::initializer_list<const char*> names) {
    double s = 0.0;
    for (const char* n : names) s += t.contains(n) ? t.at(n).at("seconds").get<double>() : 0.0;
    return s / total;
  };
  const auto& numerics = summary.at("numerics");
  return {numerics.at("wall_s_per_simulated_ms").get<double>(), 1e3 * total / numerics.at("steps").get<double>(),
          share({"lbm_stream_collide", "halo_exchange", "lbm_boundaries", "body_force_ramp"}),
          share({"ibm_forcing", "markers_advect", "force_accumulate"}), share({"membrane_solve"})};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// One variant's medians and its campaign projection.
struct Measured {
  double s_per_sim_ms, ms_per_step, lbm_share, ibm_share, membrane_share, hours_expected, hours_cap, viscosity_ratio;
};

Measured measure(const fs::path& dir, bool ratio_one, double max_time_s) {
  std::vector<Sample> samples;
  for (int rep = 0; rep < 3; ++rep) samples.push_back(run_once(dir, ratio_one, max_time_s));
  auto pick = [&](double Sample::*field) {
    std::vector<double> v;
    for (const auto& s : samples) v.push_back(s.*field);
    return median(v);
  };
  const double ms_per_step = pick(&Sample::ms_per_step);
  return {pick(&Sample::s_per_sim_ms), ms_per_step, pick(&Sample::lbm_share), pick(&Sample::ibm_share),
          pick(&Sample::membrane_share), campaign_steps(ratio_one, kExpectedPeriods) * ms_per_step / 3.6e6 / kCampaignJobs,
          campaign_steps(ratio_one, 6.0) * ms_per_step / 3.6e6 / kCampaignJobs, grid_point(ratio_one, 0.5, 0.5).viscosity_ratio};
}

void print(const char* what, const Measured& m) {
  fmt::print("resolved tube-drag{} (r* 0.5, Re 0.5, dx 1 um, 1 thread, viscosity ratio {:.3g}): {:.3f} s per simulated ms, "
             "{:.2f} ms per step (LBM {:.0f} %, IBM {:.0f} %, membrane {:.0f} %)\n",
             what, m.viscosity_ratio, m.s_per_sim_ms, m.ms_per_step, 100 * m.lbm_share, 100 * m.ibm_share,
             100 * m.membrane_share);
  fmt::print("  campaign (60 runs, {} at once): {:.1f} h if every run goes the membrane transient + {} Jeffery periods, "
             "{:.1f} h at its cap\n",
             kCampaignJobs, m.hours_expected, kExpectedPeriods, m.hours_cap);
}

nlohmann::json to_json(const Measured& m) {
  return {{"viscosity_ratio", m.viscosity_ratio}, {"s_per_sim_ms", m.s_per_sim_ms}, {"ms_per_step", m.ms_per_step},
          {"lbm_share", m.lbm_share}, {"ibm_share", m.ibm_share}, {"membrane_share", m.membrane_share},
          {"campaign_hours_projected", m.hours_expected}, {"campaign_hours_at_cap", m.hours_cap}};
}

}  // namespace

int run_resolved_bench(const hs::common::TaskOptions& options) {
  omp_set_num_threads(1);   // one thread per run, as the campaign runs them (threads_per_job = 1)
  const auto dir = fs::temp_directory_path() / "hs_bench_resolved";
  fs::create_directories(dir);
  // 2 ms at Re 0.5 = 500 lattice steps (250 membrane steps) at ratio 1; --quick: 0.4 ms.
  const double max_time_s = options.quick ? 4e-4 : 2e-3;
  const Measured shipped = measure(dir, false, max_time_s);
  const bool one_fluid = shipped.viscosity_ratio == 1.0;
  const Measured plasma = one_fluid ? shipped : measure(dir, true, max_time_s);
  print("", shipped);
  if (!one_fluid) print(", cytoplasm at the plasma's viscosity", plasma);
  nlohmann::json out = to_json(shipped);
  out["benchmark"] = "resolved";
  out["expected_periods_per_run"] = kExpectedPeriods;
  out["repetitions"] = 3;
  out["viscosity_ratio_1"] = to_json(plasma);
  const double hours_expected = shipped.hours_expected;
  hs::common::CheckList checks;
  if (options.quick) {
    checks.skip("campaign_hours_projected", "--quick: 100 steps, mostly the spin-up, do not project a campaign");
  } else {
    expect_at_most(checks, options, "campaign_hours_projected", hours_expected, 4.7,
                   "issue #27: no more than the 4.7 h the capped campaign projects");
  }
  checks.write_to(out);
  out["provenance"] = hs::common::provenance();
  if (options.json_file) hs::common::write_json(*options.json_file, out);
  checks.print("bench resolved");
  return checks.exit_code();
}

}  // namespace hs::bench
