// SPDX-License-Identifier: MIT
// One case folder against summary.json's schema (#31): runs `hemoscale run CASE --quick` into a scratch folder and
// checks its summary.json with common::summary_schema_problems (the rule the writer applies) and that it says quick.
// Usage: summary_schema_check HEMOSCALE CASE_DIR SCRATCH_DIR [OLD NEW]
//   OLD NEW: run a copy of the case whose case.toml has the text OLD replaced by NEW (it must occur), for a folder
//   whose --quick run is too long for CI; the replacement must keep the case type and its code path.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "common/summary_schema.hpp"

namespace fs = std::filesystem;

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "summary_schema_check: %s\n", message.c_str());
  return 1;
}

std::string slurp(const fs::path& file) {
  std::ostringstream text;
  text << std::ifstream(file).rdbuf();
  return text.str();
}

/// A copy of `from` (without runs/) with `old_text` replaced by `new_text` in its case.toml; empty path when the text
/// does not occur.
fs::path edited_copy(const fs::path& from, const fs::path& to, const std::string& old_text, const std::string& new_text) {
  fs::create_directories(to);
  for (const auto& entry : fs::directory_iterator(from)) {
    if (entry.path().filename() == "runs") continue;
    fs::copy(entry.path(), to / entry.path().filename(), fs::copy_options::recursive);
  }
  std::string text = slurp(to / "case.toml");
  const auto at = text.find(old_text);
  if (at == std::string::npos) return {};
  text.replace(at, old_text.size(), new_text);
  std::ofstream(to / "case.toml") << text;
  return to;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 && argc != 6) return fail("usage: summary_schema_check HEMOSCALE CASE_DIR SCRATCH_DIR [OLD NEW]");
  const std::string hemoscale = argv[1];
  fs::path case_dir = argv[2];
  const fs::path scratch = argv[3];
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  if (argc == 6) {
    case_dir = edited_copy(case_dir, scratch / "case", argv[4], argv[5]);
    if (case_dir.empty()) return fail(std::string("the case.toml has no text '") + argv[4] + "' to replace");
  }
  const fs::path run = scratch / "run";
  const std::string command = "'" + hemoscale + "' run '" + case_dir.string() + "' --quick --quiet --output '" +
                              run.string() + "' > '" + (scratch / "output.txt").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code != 0) return fail("hemoscale run --quick exited " + std::to_string(code) + ":\n" + slurp(scratch / "output.txt"));
  const auto summary = nlohmann::json::parse(slurp(run / "summary.json"), nullptr, /*allow_exceptions=*/false);
  int problems = 0;
  for (const std::string& p : hs::common::summary_schema_problems(summary)) {
    std::fprintf(stderr, "%s/summary.json: %s\n", run.c_str(), p.c_str());
    ++problems;
  }
  if (problems == 0 && summary.at("quick") != true) return fail("summary.json does not say quick = true");
  if (problems > 0) return 1;
  std::printf("%s: summary.json follows schema %d (%zu checks, %zu results, %zu groups, %zu timed stages)\n",
              argv[2], hs::common::kSummarySchemaVersion, summary.at("checks").size(), summary.at("results").size(),
              summary.at("groups").size(), summary.at("timings").size());
  fs::remove_all(scratch);
  return 0;
}
