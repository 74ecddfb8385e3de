// SPDX-License-Identifier: MIT
// `run --resume` on a folder without a checkpoint: a finished run is reported complete, an unfinished one refused
// (exit 2); either way nothing in the folder changes.
#include <gtest/gtest.h>

#include "support/run_command.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

struct FileState {
  fs::file_time_type written;
  std::string contents;
  bool operator==(const FileState&) const = default;
};

std::map<std::string, FileState> snapshot(const fs::path& dir) {
  std::map<std::string, FileState> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    std::ostringstream text;
    text << std::ifstream(e.path(), std::ios::binary).rdbuf();
    out[fs::relative(e.path(), dir).string()] = {fs::last_write_time(e.path()), text.str()};
  }
  return out;
}

/// A finished quick tube-plasma run (0.5 s, no checkpoint: the unresolved stage writes none).
fs::path finished_run(const std::string& name) {
  const fs::path out = fs::temp_directory_path() / ("hs_resume_" + name);
  fs::remove_all(out);
  const auto r = hs::test::run_hemoscale(std::string("run ") + HS_SOURCE_DIR +
                                         "/cases/unresolved/tube-plasma --quick --quiet --output " + out.string());
  EXPECT_EQ(r.code, 0) << r.output;
  return out;
}

std::string resume(const fs::path& out) {
  return std::string("run ") + HS_SOURCE_DIR + "/cases/unresolved/tube-plasma --quick --quiet --resume --output " +
         out.string();
}

}  // namespace

TEST(ResumeCli, FinishedRunIsReportedCompleteAndLeftUnchanged) {
  const fs::path out = finished_run("complete");
  ASSERT_TRUE(fs::exists(out / "summary.json"));
  const auto before = snapshot(out);
  const auto r = hs::test::run_hemoscale(resume(out));
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("already complete"), std::string::npos) << r.output;
  EXPECT_TRUE(snapshot(out) == before) << "files changed by --resume of a finished run";
  fs::remove_all(out);
}

TEST(ResumeCli, UnfinishedRunWithoutCheckpointIsRefused) {
  const fs::path out = finished_run("unfinished");
  fs::remove(out / "summary.json");   // as if stopped before the end, and before any checkpoint
  const auto before = snapshot(out);
  const auto r = hs::test::run_hemoscale(resume(out));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("no checkpoint to continue from"), std::string::npos) << r.output;
  EXPECT_TRUE(snapshot(out) == before) << "files changed by a refused --resume";
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  fs::remove_all(out);
}

TEST(ResumeCli, MissingRunFolderIsRefused) {
  const auto r = hs::test::run_hemoscale(resume(fs::temp_directory_path() / "hs_resume_nonexistent"));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("no such run folder to resume"), std::string::npos) << r.output;
}
