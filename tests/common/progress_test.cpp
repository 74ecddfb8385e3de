// SPDX-License-Identifier: MIT
// Progress in a log (stderr not a terminal): dated lines a person can read hours later; nothing in CI.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "common/progress.hpp"

namespace {

/// Runs `body` with stderr sent to a file and the CI variable as given; returns what was written.
template <class Body>
std::string stderr_of(Body body, bool ci) {
  // A file of its own per test: ctest runs the tests of this binary as parallel processes.
  const auto file = std::filesystem::temp_directory_path() /
                    (std::string("hs_progress_") + ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                     (ci ? "_ci" : "") + ".txt");
  std::fflush(stderr);
  std::FILE* sink = std::fopen(file.c_str(), "w");
  if (sink == nullptr) {
    ADD_FAILURE() << "cannot write " << file;
    return "";
  }
  const char* old_ci = std::getenv("CI");
  const std::optional<std::string> saved = old_ci ? std::optional<std::string>(old_ci) : std::nullopt;
  if (ci) setenv("CI", "true", 1); else unsetenv("CI");
  const int kept = dup(STDERR_FILENO);
  dup2(fileno(sink), STDERR_FILENO);
  body();
  std::fflush(stderr);
  dup2(kept, STDERR_FILENO);
  close(kept);
  std::fclose(sink);
  if (saved) setenv("CI", saved->c_str(), 1); else unsetenv("CI");
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

int count_lines(const std::string& text) {
  int n = 0;
  for (const char c : text) n += c == '\n' ? 1 : 0;
  return n;
}

}  // namespace

TEST(Progress, LogGetsADatedLinePerStepWhenAskedAndTheNews) {
  const std::string log = stderr_of([] {
    hs::common::Progress p("campaign x", 3, true, std::chrono::seconds(0));
    p.update(1);
    p.note("run a: done after 5.0s");
    p.update(2);
    p.update(2);   // no progress: no line
  }, false);
  EXPECT_EQ(count_lines(log), 3) << log;   // 1/3, the note, 2/3; at the end nothing new to say
  EXPECT_NE(log.find("campaign x  33.3%  1/3"), std::string::npos) << log;
  EXPECT_NE(log.find("run a: done after 5.0s"), std::string::npos) << log;
  EXPECT_NE(log.find("ETA"), std::string::npos) << log;
  EXPECT_EQ(log.find('\r'), std::string::npos) << "a log has no carriage returns: " << log;
  EXPECT_EQ(log.substr(0, 2), "20") << "lines start with the date: " << log;
}

TEST(Progress, LogIsThrottledButEndsWithWhereTheRunStopped) {
  const std::string log = stderr_of([] {
    hs::common::Progress p("tube-cell", 1000, true, std::chrono::seconds(3600));
    for (long s = 0; s <= 400; ++s) p.update(s);   // stops early (settled): well short of the total
  }, false);
  EXPECT_EQ(count_lines(log), 1) << log;
  EXPECT_NE(log.find("400/1000"), std::string::npos) << log;
}

TEST(Progress, SilentInCiAndWhenDisabled) {
  EXPECT_EQ(stderr_of([] {
              hs::common::Progress p("x", 2, true, std::chrono::seconds(0));
              p.update(1);
              p.note("news");
              p.update(2);
            }, true),
            "");
  EXPECT_EQ(stderr_of([] {
              hs::common::Progress p("x", 2, false, std::chrono::seconds(0));
              p.update(2);
            }, false),
            "");
}

TEST(Progress, TheCallersEstimateReplacesTheRateSinceTheStart) {
  const std::string log = stderr_of([] {
    hs::common::Progress p("campaign x", 10, true, std::chrono::seconds(0));
    p.set_eta_estimate([](long done) { return done < 2 ? -1.0 : 3661.0; });
    p.update(1);   // no estimate yet
    p.update(2);
  }, false);
  EXPECT_NE(log.find("1/10  elapsed 0.0s  ETA --"), std::string::npos) << log;
  EXPECT_NE(log.find("ETA 1h01m"), std::string::npos) << log;
}
