// SPDX-License-Identifier: MIT
// What does not run on z-slabs (open-geometry with a [study] or with an inlet that does not face along z; tube-plasma,
// tube-pries, tube-open, open-geometry along z, the Pries tables and bench cfddem do: distributed_cli_test.cpp) on two
// MPI ranks: it stops at once with exit code 2 and says what to do (issue 21), instead of running the whole problem on
// every rank.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/run_command.hpp"

namespace fs = std::filesystem;

namespace {

/// `mpiexec -n 2 hemoscale ARGS`.
hs::test::CommandResult run_on_two_ranks(const std::string& args) {
  return hs::test::run_shell(std::string(HS_MPIEXEC) + " -n 2 " + HS_MPIEXEC_FLAGS + " " + HS_BIN + " " + args);
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + what.size())) ++n;
  return n;
}

/// Exit 2, the message once (rank 0 prints it) naming the run, the rank count and the remedy.
void expect_refused(const hs::test::CommandResult& r, const std::string& what) {
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_EQ(count(r.output, "error: " + what + ": started on 2 MPI ranks"), 1u) << r.output;
  EXPECT_NE(r.output.find("runs on one rank only"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("mpirun -np 1"), std::string::npos) << r.output;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("hs_mpi_guard_" + name);
  fs::remove_all(dir);
  return dir;
}

TEST(MpiGuard, OpenGeometryWithAnInletAlongXStopsAndNamesTheRemedy) {
  // open-geometry runs on z-slabs (distributed_cli_test.cpp), but its cells enter on the slab holding their inlet: the
  // committed Y bifurcation's inlet faces along -x, so two ranks stop before the run folder, naming the opening.
  const fs::path out = fresh_dir("open_geometry");
  const fs::path case_dir = fs::path(HS_SOURCE_DIR) / "cases/unresolved/y-bifurcation";
  const auto r = run_on_two_ranks("run --quiet --quick " + case_dir.string() + " --output " + out.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_EQ(count(r.output, "[openings.inlet]: on 2 MPI ranks"), 1u) << r.output;
  EXPECT_NE(r.output.find("axis = \"z\""), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(MpiGuard, AStudyOnTwoRanksStops) {
  // The stenosis and bifurcation studies' measurements run on one rank.
  const fs::path out = fresh_dir("stenosis_study");
  const fs::path case_dir = fs::path(HS_SOURCE_DIR) / "cases/unresolved/stenosis/throat-85um";
  const auto r = run_on_two_ranks("run --quiet --quick " + case_dir.string() + " --output " + out.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_EQ(count(r.output, "[study]: the stenosis and bifurcation studies' measurements run on one rank only"), 1u)
      << r.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
