// SPDX-License-Identifier: MIT
// `hemoscale fit --check FILE`: a closure file evaluated against the reference table written beside it.
#pragma once

#include <filesystem>
#include <string>

namespace hs::closures {

/// Loads a closure file (ConfigError if it is bad) and, when `<name>.reference.csv` lies beside it, checks
/// that the compiled expression reproduces that table to 1e-12 relative. Returns a one-paragraph summary;
/// throws hs::common::NumericalError on a mismatch. Needs the expression evaluator only, not the GP engine.
std::string check_closure(const std::filesystem::path& file);

}  // namespace hs::closures
