// SPDX-License-Identifier: MIT
// `hemoscale bench NAME` exits 1 when a measured value misses its documented target and 0 when it meets it, shown
// end to end. lbm: its --quick run measures its target's own case on any machine (the 128^3 box, in-place AA kernel,
// 2 threads, vs the triad roofline); the target is moved with --tighten (a test-only option) to where the outcome does
// not depend on the machine: a kernel does not run 8x faster than its memory traffic allows, so a target of
// 0.82 x 10 = 8.2 must fail; 0.82 x 0.01 = 0.0082 is 35x under the 0.28 measured on this 2-core machine with three
// builds running beside it (2026-12-02), so it must pass. dem and fvm: their targets are speed-ups over a peer code
// (LIGGGHTS, icoFoam) that CI does not install; a stand-in peer reporting an impossible or an absurdly slow timing
// decides the outcome while the bench's own timing stays real. regression and cfddem: their targets need minutes of
// every core (the full search budget; the 1e6-cell tube, ~2.5 GiB); the benches judge their committed full runs, read
// back through an environment variable (the regression models judged anew, the cfddem 1e6 size taken as measured).
#include <gtest/gtest.h>

#include "support/run_command.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

hs::test::CommandResult run(const std::string& args) { return hs::test::run_hemoscale(args); }

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

}  // namespace

TEST(BenchExit, AMissedTargetIsExitOneAndNamedInTheJson) {
  const fs::path dir = fs::temp_directory_path() / "hs_bench_exit_missed";
  fs::remove_all(dir);
  const auto r = run("bench lbm --quick --tighten 10 --json " + (dir / "lbm.json").string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("FAILED  roofline_fraction"), std::string::npos) << r.output;
  const nlohmann::json j = read_json(dir / "lbm.json");
  EXPECT_FALSE(j.at("passed").get<bool>());
  EXPECT_EQ(j.at("checks_failed").get<int>(), 1);
}

TEST(BenchExit, AMetTargetIsExitZero) {
  const fs::path dir = fs::temp_directory_path() / "hs_bench_exit_met";
  fs::remove_all(dir);
  const auto r = run("bench lbm --quick --tighten 0.01 --json " + (dir / "lbm.json").string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(read_json(dir / "lbm.json").at("passed").get<bool>());
}

namespace {

/// A stand-in for a peer code: `program` on PATH (doing nothing) and HS_SHARED_DIR/`script` printing `result_line`, the
/// line the shared script prints after a real run. The bench's own timing stays real; only the peer's number is chosen,
/// so the exit code of a speed-up target is shown end to end on a machine without the peer. Returns the `env` prefix.
std::string with_fake_peer(const fs::path& dir, const std::string& program, const std::string& script,
                           const std::string& result_line) {
  fs::remove_all(dir);
  fs::create_directories(dir / "bin");
  fs::create_directories((dir / "shared" / script).parent_path());
  {
    std::ofstream bin(dir / "bin" / program);
    bin << "#!/bin/sh\nexit 0\n";
  }
  {
    std::ofstream out(dir / "shared" / script);
    out << "#!/bin/sh\necho \"" << result_line << "\"\n";
  }
  fs::permissions(dir / "bin" / program, fs::perms::owner_all, fs::perm_options::add);
  return "env PATH=\"" + (dir / "bin").string() + ":$PATH\" HS_SHARED_DIR=\"" + (dir / "shared").string() + "\" ";
}

std::string with_fake_liggghts(const fs::path& dir, double ns_per_particle_step) {
  return with_fake_peer(dir, "liggghts", "bench/liggghts/run_rbcpack.sh",
                        "RESULT liggghts (test stand-in) ns/particle-step=" + std::to_string(ns_per_particle_step));
}

std::string with_fake_icofoam(const fs::path& dir, double ns_per_cell_step) {
  return with_fake_peer(dir, "icoFoam", "bench/openfoam/run_cavity3d.sh",
                        "RESULT icoFoam (test stand-in) ns/cell/step=" + std::to_string(ns_per_cell_step) +
                            " p_iters/step=10");
}

}  // namespace

TEST(BenchExit, DemMissesItsTargetAgainstAFasterPeerAndMeetsItAgainstASlowerOne) {
  // `bench dem` compares against LIGGGHTS only when it is installed (not in CI): otherwise its check is skipped, never
  // met. With a stand-in peer the target (speed-up >= 2, issue #28) is judged on the bench's real DEM timing: a peer
  // at 1e-3 ns per particle-step is beyond any machine (a particle-step moves tens of bytes: >= 0.1 ns at 100 GB/s),
  // so the speed-up is < 0.01 and the bench must exit 1; a peer at 1e12 ns (1000 s a particle-step) must be beaten.
  const fs::path fast = fs::temp_directory_path() / "hs_bench_exit_dem_fast_peer";
  const auto missed = hs::test::run_shell(with_fake_liggghts(fast, 1e-3) + HS_BIN + " bench dem --quick --json " +
                                          (fast / "dem.json").string());
  EXPECT_EQ(missed.code, 1) << missed.output;
  EXPECT_NE(missed.output.find("FAILED  speedup_vs_liggghts"), std::string::npos) << missed.output;
  EXPECT_EQ(read_json(fast / "dem.json").at("checks_failed").get<int>(), 1);

  const fs::path slow = fs::temp_directory_path() / "hs_bench_exit_dem_slow_peer";
  const auto met = hs::test::run_shell(with_fake_liggghts(slow, 1e12) + HS_BIN + " bench dem --quick --json " +
                                       (slow / "dem.json").string());
  EXPECT_EQ(met.code, 0) << met.output;
  EXPECT_TRUE(read_json(slow / "dem.json").at("passed").get<bool>());
}

TEST(BenchExit, FvmMissesItsTargetAgainstAFasterPeerAndMeetsItAgainstASlowerOne) {
  // `bench fvm` against a stand-in icoFoam (the same reasoning as the DEM test): a cell-step of a PISO step (two
  // pressure correctors, three momentum solves) moves hundreds of bytes, so 1e-3 ns is beyond any machine and the
  // speed-up target (>= 3, issue #28) must fail; a peer at 1e12 ns per cell-step must be beaten.
  const fs::path fast = fs::temp_directory_path() / "hs_bench_exit_fvm_fast_peer";
  const auto missed = hs::test::run_shell(with_fake_icofoam(fast, 1e-3) + HS_BIN + " bench fvm --quick --json " +
                                          (fast / "fvm.json").string());
  EXPECT_EQ(missed.code, 1) << missed.output;
  EXPECT_NE(missed.output.find("FAILED  speedup_vs_openfoam"), std::string::npos) << missed.output;
  EXPECT_EQ(read_json(fast / "fvm.json").at("checks_failed").get<int>(), 1);

  const fs::path slow = fs::temp_directory_path() / "hs_bench_exit_fvm_slow_peer";
  const auto met = hs::test::run_shell(with_fake_icofoam(slow, 1e12) + HS_BIN + " bench fvm --quick --json " +
                                       (slow / "fvm.json").string());
  EXPECT_EQ(met.code, 0) << met.output;
  EXPECT_TRUE(read_json(slow / "fvm.json").at("passed").get<bool>());
}

TEST(BenchExit, ResolvedJudgesItsCampaignProjectionBothWays) {
  // `bench resolved` in full (three 2 ms runs of the campaign's tube-drag case, ~11 s of one core; --quick skips the
  // target): the projected campaign hours against issue #27's 4.7 h. --tighten 100 asks for 0.047 h, two jobs at once
  // over the campaign's ~1.4e7 lattice steps: 25 us a step of the 50^3-node box, 0.2 ns a node, whose D3Q19 update
  // moves ~300 bytes (1.5 TB/s, beyond any CPU's memory): exit 1. --tighten 0.001 allows 4700 h, 165x the 28.4 h
  // measured on this loaded machine (2026-12-02): exit 0.
  const fs::path dir = fs::temp_directory_path() / "hs_bench_exit_resolved";
  fs::remove_all(dir);
  const auto missed = run("bench resolved --tighten 100 --json " + (dir / "missed.json").string());
  EXPECT_EQ(missed.code, 1) << missed.output;
  EXPECT_NE(missed.output.find("FAILED  campaign_hours_projected"), std::string::npos) << missed.output;
  EXPECT_EQ(read_json(dir / "missed.json").at("checks_failed").get<int>(), 1);
  const auto met = run("bench resolved --tighten 0.001 --json " + (dir / "met.json").string());
  EXPECT_EQ(met.code, 0) << met.output;
  EXPECT_TRUE(read_json(dir / "met.json").at("passed").get<bool>());
}

namespace {

/// `hemoscale bench NAME ARGS` reading an earlier full run through `archive_env` (the committed JSON under
/// bench/results/) instead of searching or measuring; `timeout` turns a run that started working (an archive no longer
/// read) into a failed test instead of minutes.
hs::test::CommandResult run_on_archive(const std::string& env, const std::string& args) {
  return hs::test::run_shell("env " + env + " timeout 120 " + std::string(HS_BIN) + " bench " + args);
}

}  // namespace

TEST(BenchExit, RegressionJudgesTheCommittedFullRunBothWays) {
  // `bench regression` at the full budget takes minutes of every core; its target (exact_full >= 10 of the ten
  // equations, issue #29) is judged here on the committed full run of 2026-12-02: the bench re-reads each equation's
  // two models (full engine, gplearn) and judges them with the same recovery judge as a fresh search (parse, canonical
  // forms, 1000 fresh points). That run recovered 9 of 10 (I.29.16 missed): exit 1 at the target. --tighten 0.9 puts
  // the floor at 9, exactly what the run holds: exit 0, so the verdict turns on the count itself.
  const fs::path dir = fs::temp_directory_path() / "hs_bench_exit_regression";
  fs::remove_all(dir);
  const std::string env = "HS_BENCH_REGRESSION_ARCHIVE=" + std::string(HS_SOURCE_DIR) + "/bench/results/2026-12-02_regression.json";
  const auto missed = run_on_archive(env, "regression --json " + (dir / "missed.json").string());
  ASSERT_NE(missed.code, 124) << "the bench searched instead of reading the archive";
  EXPECT_EQ(missed.code, 1) << missed.output;
  EXPECT_NE(missed.output.find("FAILED  exact_full"), std::string::npos) << missed.output;
  const nlohmann::json a = read_json(dir / "missed.json");
  EXPECT_EQ(a.at("equations_searched_this_run").get<int>(), 0);
  EXPECT_EQ(a.at("exact_full").get<int>(), 9);
  EXPECT_EQ(a.at("missed_full"), nlohmann::json::array({"I.29.16"}));
  EXPECT_EQ(a.at("checks_failed").get<int>(), 1);

  const auto met = run_on_archive(env, "regression --tighten 0.9 --json " + (dir / "met.json").string());
  EXPECT_EQ(met.code, 0) << met.output;
  EXPECT_TRUE(read_json(dir / "met.json").at("passed").get<bool>());
}

TEST(BenchExit, CfddemJudgesTheCommittedMillionCellRunBothWays) {
  // `bench cfddem`'s targets (issue #28: <= 2 s per CFD step and <= 4 GiB at 1e6 RBCs) need the 1e6 size: ~2.5 GiB and
  // minutes. They are judged here on the committed run of 2026-12-02 (bench/results/2026-12-02_cfddem_speed.json:
  // 10.4 s per step, 2.52 GiB, measured on the loaded machine), the only size asked for (HS_BENCH_CFDDEM_SIZES), taken
  // from the archive. At the target: exit 1, the time named, the memory met. --tighten 0.19 allows 2 / 0.19 = 10.5 s
  // (and 21 GiB): exit 0; --tighten 0.2 allows 10.0 s: exit 1. The verdict turns within 1% of the archived time.
  const fs::path dir = fs::temp_directory_path() / "hs_bench_exit_cfddem";
  fs::remove_all(dir);
  const std::string env = "HS_BENCH_CFDDEM_SIZES=1000000 HS_BENCH_CFDDEM_ARCHIVE=" + std::string(HS_SOURCE_DIR) +
                          "/bench/results/2026-12-02_cfddem_speed.json";
  const auto missed = run_on_archive(env, "cfddem --json " + (dir / "missed.json").string());
  ASSERT_NE(missed.code, 124) << "the bench measured instead of reading the archive";
  EXPECT_EQ(missed.code, 1) << missed.output;
  EXPECT_NE(missed.output.find("FAILED  cfddem_1e6_s_per_cfd_step"), std::string::npos) << missed.output;
  const nlohmann::json a = read_json(dir / "missed.json");
  EXPECT_EQ(a.at("archived_sizes"), nlohmann::json::array({"cfddem_1e6"}));
  EXPECT_EQ(a.at("checks_failed").get<int>(), 1);   // the time; the memory (2.52 GiB) is met

  const auto just_missed = run_on_archive(env, "cfddem --tighten 0.2 --json " + (dir / "just_missed.json").string());
  EXPECT_EQ(just_missed.code, 1) << just_missed.output;
  const auto met = run_on_archive(env, "cfddem --tighten 0.19 --json " + (dir / "met.json").string());
  EXPECT_EQ(met.code, 0) << met.output;
  EXPECT_TRUE(read_json(dir / "met.json").at("passed").get<bool>());
}
