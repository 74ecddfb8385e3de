// SPDX-License-Identifier: MIT
// `hemoscale bench NAME` exits 1 when a measured value misses its documented target and 0 when it meets it, shown
// end to end. lbm: its --quick run measures its target's own case on any machine (the 128^3 box, in-place AA kernel,
// 2 threads, vs the triad roofline); the target is moved with --tighten (a test-only option) to where the outcome does
// not depend on the machine: a kernel does not run 8x faster than its memory traffic allows, so a target of
// 0.82 x 10 = 8.2 must fail; 0.82 x 0.01 = 0.0082 is 35x under the 0.28 measured on this 2-core machine with three
// builds running beside it (2026-12-02), so it must pass. dem and fvm: their targets are speed-ups over a peer code
// (LIGGGHTS, icoFoam) that CI does not install; a stand-in peer reporting an impossible or an absurdly slow timing
// decides the outcome while the bench's own timing stays real.
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
