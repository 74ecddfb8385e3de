// SPDX-License-Identifier: MIT
// A validation's figure: FILE.png beside its --json FILE, drawn by one of tools/plot_*.py.
#pragma once

#include <filesystem>
#include <string>

namespace hs::validate {

/// Runs `/usr/bin/python3 tools/SCRIPT JSON REFERENCE JSON.png` when Debian's python3 and the script are there, and
/// says which PNG it wrote (or that matplotlib seems missing); a figure never changes a validation's verdict.
void plot_beside_json(const std::string& script, const std::filesystem::path& json,
                      const std::filesystem::path& reference);

}  // namespace hs::validate
