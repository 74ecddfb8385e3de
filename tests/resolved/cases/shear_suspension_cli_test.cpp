// SPDX-License-Identifier: MIT
// The shear-suspension case through `hemoscale run`: a hematocrit the box cannot hold, and more than one cell on
// two MPI ranks, stop before the run with exit 2 and one message.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

#include <sys/wait.h>

#include "resolved/cases/cli_case_helpers.hpp"

namespace {

TEST(ShearSuspensionCli, AHematocritTheBoxCannotHoldIsABadInput) {
  const auto dir = hs::test::write_case_variant("shear-suspension", "shear_suspension_full",
                                                "hematocrit = 0.1 ", "hematocrit = 0.55 ");
  const auto r = hs::test::run_hemoscale("run " + dir.string() + " --quick --output " + (dir / "out").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("[cells] hematocrit = 0.55"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("lower the hematocrit or enlarge the box"), std::string::npos) << r.output;
}

TEST(ShearSuspensionCli, ManyCellsRefuseMoreThanOneRank) {
  const auto dir = hs::test::write_case_variant("shear-suspension", "shear_suspension_np2", "seed = 1 ", "seed = 1 ");
  const std::string cmd = std::string(HS_MPIEXEC) + " -n 2 " + HS_MPIEXEC_FLAGS + " " + HS_BIN + " run --quick " +
                          dir.string() + " --output " + (dir / "out").string() + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  std::string out;
  while (fgets(buf.data(), buf.size(), pipe) != nullptr) out += buf.data();
  const int status = pclose(pipe);
  // mpiexec returns the ranks' exit code (both ranks refuse the same way, before any output folder is made).
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2) << out;
  EXPECT_NE(out.find("runs more than one cell on one rank only"), std::string::npos) << out;
}

}  // namespace
