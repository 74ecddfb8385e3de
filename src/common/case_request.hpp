// SPDX-License-Identifier: MIT
// What `hemoscale run` hands to a case: the parsed case file and where the outputs go.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "common/config/config_file.hpp"

namespace hs::common {

struct CaseRequest {
  std::filesystem::path case_dir;                    // the case folder (holds case.toml)
  ConfigFile* config;                                // parsed case.toml; [case] type already read
  std::optional<std::filesystem::path> output_dir;   // --output; default: case_dir/runs/run-NNN
  bool resume = false;                               // --resume: continue the run in output_dir
  bool quiet = false;                                // --quiet: no progress line
  bool quick = false;                                // --quick: the coarse CI version of the case
};

/// Runs one case type; returns the process exit code (0 = ran and its checks passed).
using CaseRunner = std::function<int(const CaseRequest&)>;

/// Options shared by `hemoscale bench NAME` and `hemoscale validate NAME`.
struct TaskOptions {
  std::optional<std::filesystem::path> json_file;    // --json FILE
  bool quick = false;                                // --quick: a shorter version (CI)
  std::string extra;                                 // NAME-specific option string (e.g. --closures)
  std::string suspension_viscosity;                  // --suspension-viscosity NAME (CFD-DEM validations)
  std::optional<std::filesystem::path> dataset;       // --dataset FILE (validations that read a dataset)
  /// --tighten F (tests of the failure path only): every band divided by F, every benchmark target multiplied by F.
  double tighten = 1.0;
};
using TaskRunner = std::function<int(const TaskOptions&)>;

/// Options of `hemoscale study NAME`: a set of runs of committed case folders, then their table and figures.
struct StudyOptions {
  std::optional<std::filesystem::path> output_dir;   // --output DIR; default: the study's runs/ folder in the source tree
  bool quick = false;                                // --quick: every run --quick, no steady checks, no figures (CI)
};
using StudyRunner = std::function<int(const StudyOptions&)>;

}  // namespace hs::common
