// SPDX-License-Identifier: MIT
// tube-pries' end time follows the run (issue #25): past end_time_s it goes on until Ht_d and mu_rel are steady,
// at most to max_end_time_s. The stop is checked against the rule recomputed here from the time series with a
// least-squares line of this file's own, and a run that cannot become steady is capped and judged unsteady.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "unresolved/cases/short_tube_case.hpp"
#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "common/case_request.hpp"
#include "unresolved/cases/tube_pries.hpp"

namespace {

using hs::unresolved::TubePriesSample;

constexpr double kDt = 2e-4;   // short_tube_case's CFD step
constexpr int kFirst = 20;     // end_time_s in steps: checks every 2 steps from step 20 on

/// The small tube at Ht_c 0.05 (a few rigid spheres, Stokes drag): the flow develops from rest over ~50 steps
/// (the plasma relaxes by ~0.86 a step on this grid), then Ht_d and mu_rel level off.
hs::unresolved::TubePriesConfig config(int max_steps, const std::string& steady_tolerance) {
  const std::string tail = "max_end_time_s = " + std::to_string(kDt * max_steps) + "\nsteady_tolerance = " + steady_tolerance + "\n";
  std::string text = hs::test::short_tube_case("0.05", "drag = \"stokes\"\n", "125", std::to_string(kDt * kFirst));
  text += tail;   // appended to [numerics], the last section
  auto file = hs::common::ConfigFile::parse(text, "case.toml");
  (void)file->root().section("case").string("type");
  return hs::unresolved::parse_tube_pries(*file, false);
}

/// |change of the least-squares line over the window| / mean, for y over the samples [from, to).
double relative_trend(const std::vector<double>& t, const std::vector<double>& y, std::size_t from, std::size_t to) {
  double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
  for (std::size_t i = from; i < to; ++i) {
    n += 1;
    st += t[i];
    sy += y[i];
    stt += t[i] * t[i];
    sty += t[i] * y[i];
  }
  const double slope = (n * sty - st * sy) / (n * stt - st * st);
  return std::abs(slope * (t[to - 1] - t[from]) / (sy / n));
}

/// The rule of docs/case-files.md on the first k samples: over the second half, both trends below the tolerance.
bool steady_after(const std::vector<TubePriesSample>& s, std::size_t k, double q_plasma, double tolerance) {
  std::vector<double> t, ht_d, mu_rel;
  for (std::size_t i = 0; i < k; ++i) {
    t.push_back(s[i].time_s);
    ht_d.push_back(s[i].ht_d);
    mu_rel.push_back(q_plasma / s[i].q_blood_m3_s);
  }
  const auto from = static_cast<std::size_t>(0.5 * static_cast<double>(k));
  return relative_trend(t, ht_d, from, k) <= tolerance && relative_trend(t, mu_rel, from, k) <= tolerance;
}

TEST(TubePriesEndTime, GoesOnUntilSteadyAndStopsAtTheFirstCheckThatSaysSo) {
  constexpr int kMax = 400;
  constexpr double kTolerance = 0.02;   // the default: below the 5 % band
  std::vector<TubePriesSample> s;
  const auto r = hs::unresolved::simulate_tube_pries(config(kMax, "0.02"), [&](const TubePriesSample& x) { s.push_back(x); });
  const auto& res = r.summary["results"];
  const double q_plasma = res["flow_rate_plasma_only_m3_s"].get<double>();
  const std::size_t n = s.size();
  RecordProperty("stopped_at_step", static_cast<int>(n));   // 26 when written (2026-12-03)
  ASSERT_GT(n, static_cast<std::size_t>(kFirst));   // the flow is still developing at end_time_s: it must go on
  ASSERT_LT(n, static_cast<std::size_t>(kMax)) << "never steady within the cap";
  EXPECT_TRUE(res["stopped_when_steady"].get<bool>());
  EXPECT_TRUE(res["steady"].get<bool>());
  EXPECT_NEAR(res["end_time_s"].get<double>(), kDt * static_cast<double>(n), 1e-12);
  constexpr std::size_t kEvery = kFirst / 10;
  EXPECT_EQ((n - kFirst) % kEvery, 0u);
  EXPECT_TRUE(steady_after(s, n, q_plasma, kTolerance));
  EXPECT_TRUE(steady_after(s, n - kEvery, q_plasma, kTolerance));
  for (std::size_t k = kFirst; k < n; k += kEvery) {   // no earlier check had two steady windows in a row
    EXPECT_FALSE(steady_after(s, k, q_plasma, kTolerance) && steady_after(s, k - kEvery, q_plasma, kTolerance)) << "step " << k;
  }
}

TEST(TubePriesEndTime, ARunThatNeverSettlesIsCappedAndJudgedUnsteady) {
  // A tolerance no noisy series meets: the run must end at the cap, unsteady, and say it was not stopped by the rule.
  constexpr int kMax = 30;
  const auto r = hs::unresolved::simulate_tube_pries(config(kMax, "1e-12"), [](const TubePriesSample&) {});
  const auto& res = r.summary["results"];
  EXPECT_NEAR(res["end_time_s"].get<double>(), kDt * kMax, 1e-12);
  EXPECT_FALSE(res["stopped_when_steady"].get<bool>());
  EXPECT_FALSE(res["steady"].get<bool>());
  EXPECT_NEAR(r.summary["numerics"]["max_end_time_s"].get<double>(), kDt * kMax, 1e-12);
}

TEST(TubePriesEndTime, ARunStoppedWhenSteadyStillWritesItsFinalFrame) {
  // Without [output] vtk_every_s only the last step's frame is written: the step the rule stopped at must count.
  namespace fs = std::filesystem;
  const fs::path out = fs::temp_directory_path() / "hs_tube_pries_end_time_frames";
  fs::remove_all(out);
  std::string text = hs::test::short_tube_case("0.05", "drag = \"stokes\"\n", "125", std::to_string(kDt * kFirst));
  text += "max_end_time_s = " + std::to_string(kDt * 400) + "\n";
  auto file = hs::common::ConfigFile::parse(text, "case.toml");
  (void)file->root().section("case").string("type");
  const hs::common::CaseRequest request{.case_dir = fs::temp_directory_path(), .config = file.get(), .output_dir = out,
                                        .resume = false, .quiet = true, .quick = false};
  (void)hs::unresolved::run_tube_pries(request);   // steady, but not within 5 % of Pries: exit 1 by design
  int frames = 0;
  for (const auto& f : fs::directory_iterator(out / "vtk")) frames += f.path().extension() == ".vti" ? 1 : 0;
  EXPECT_EQ(frames, 1);
  fs::remove_all(out);
}

TEST(TubePriesEndTime, AMaximumBelowTheShortestRunIsAConfigErrorNamingTheKey) {
  std::string text = hs::test::short_tube_case("0.05", "", "125", "2e-3") + "max_end_time_s = 1e-3\n";
  auto file = hs::common::ConfigFile::parse(text, "case.toml");
  (void)file->root().section("case").string("type");
  try {
    (void)hs::unresolved::parse_tube_pries(*file, false);
    ADD_FAILURE() << "no ConfigError";
  } catch (const hs::common::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("max_end_time_s"), std::string::npos) << e.what();
  }
}

}  // namespace
