// SPDX-License-Identifier: MIT
// The three explicit lists the CLI dispatches on (STYLE R5): case types, benchmarks, validations.
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

/// case.toml [case] type -> runner. One line per case type, in app/register_cases.cpp.
std::map<std::string, Entry> case_types();
/// `hemoscale bench NAME` -> benchmark, in bench/register_benches.cpp.
std::map<std::string, TaskEntry> benchmarks();
/// `hemoscale validate NAME` -> validation, in validate/register_validations.cpp.
std::map<std::string, TaskEntry> validations();

}  // namespace hs::app
