// SPDX-License-Identifier: MIT
// The explicit lists the CLI dispatches on (STYLE R5): case types, benchmarks, validations, studies.
#pragma once

#include <map>
#include <string>

#include "common/case_request.hpp"

namespace hs::app {

struct Entry {
  std::string help;
  hs::common::CaseRunner run;
};
struct TaskEntry {
  std::string help;
  hs::common::TaskRunner run;
};
struct StudyEntry {
  std::string help;
  hs::common::StudyRunner run;
};

/// case.toml [case] type -> runner. One line per case type, in app/register_cases.cpp.
std::map<std::string, Entry> case_types();
/// `hemoscale bench NAME` -> benchmark, in bench/register_benches.cpp.
std::map<std::string, TaskEntry> benchmarks();
/// `hemoscale validate NAME` -> validation, in validate/register_validations.cpp.
std::map<std::string, TaskEntry> validations();
/// `hemoscale study NAME` -> study (several runs, one table), in study/register_studies.cpp.
std::map<std::string, StudyEntry> studies();

}  // namespace hs::app
