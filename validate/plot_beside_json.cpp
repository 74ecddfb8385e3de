// SPDX-License-Identifier: MIT
// Drawing a validation's figure with its plot tool.
#include "validate/plot_beside_json.hpp"

#include <cstdlib>

#include <fmt/format.h>

namespace hs::validate {

void plot_beside_json(const std::string& script, const std::filesystem::path& json,
                      const std::filesystem::path& reference) {
  const std::filesystem::path tool = std::filesystem::path(HS_SOURCE_DIR) / "tools" / script;
  if (!std::filesystem::exists("/usr/bin/python3") || !std::filesystem::exists(tool)) return;
  std::filesystem::path png = json;
  png.replace_extension(".png");
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}' '{}' '{}' > /dev/null 2>&1", tool.string(),
                                      json.string(), reference.string(), png.string());
  if (std::system(cmd.c_str()) == 0) {
    fmt::print("plot: {}\n", png.string());
  } else {
    fmt::print("{} failed (matplotlib missing?): no PNG written\n", script);
  }
}

}  // namespace hs::validate
