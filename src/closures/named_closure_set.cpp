// SPDX-License-Identifier: MIT
// Committed closure sets a case names instead of a path (`drag = "resolved"`), so a copied case folder still finds them.
#include "closures/named_closure_set.hpp"

#include <algorithm>
#include <cstdlib>
#include <system_error>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::closures {
namespace {

const char* kind_folder(ClosureKind kind) {
  switch (kind) {
    case ClosureKind::drag: return "drag_coefficient";
    case ClosureKind::lift: return "lift_coefficient";
    case ClosureKind::deformation: return "deformation_index";
  }
  return "";
}

}  // namespace

const std::vector<std::string>& closure_set_names() {
  // One line per set. "resolved": fitted on the resolved campaign's 30-row dataset (data/closures/README.md).
  static const std::vector<std::string> names{"resolved"};
  return names;
}

std::vector<std::filesystem::path> closure_data_dirs() {
  std::vector<std::filesystem::path> dirs;
  if (const char* env = std::getenv("HS_DATA_DIR"); env != nullptr && *env != '\0') dirs.emplace_back(env);
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) dirs.push_back(exe.parent_path().parent_path() / "share" / "hemoscale" / "data");
  dirs.emplace_back(HS_SOURCE_DATA_DIR);
  return dirs;
}

std::filesystem::path closure_set_dir(const std::string& name) {
  std::string looked;
  for (const auto& data : closure_data_dirs()) {
    const std::filesystem::path dir = data / "closures" / name;
    if (std::filesystem::is_directory(dir)) return dir;
    looked += (looked.empty() ? "" : ", ") + dir.string();
  }
  throw hs::common::ConfigError(fmt::format("closure set \"{}\" not found; looked in {} (set HS_DATA_DIR to the folder "
                                            "holding closures/, or give the closure file's path)", name, looked));
}

bool is_closure_set(const std::string& name) {
  const auto& n = closure_set_names();
  return std::find(n.begin(), n.end(), name) != n.end();
}

std::filesystem::path named_closure_file(const std::string& name, ClosureKind kind) {
  if (!is_closure_set(name)) throw hs::common::ConfigError(fmt::format("\"{}\" is not a committed closure set", name));
  const std::filesystem::path dir = closure_set_dir(name) / kind_folder(kind);
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(dir)) {
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      if (e.path().extension() == ".toml") files.push_back(e.path());
    }
  }
  if (files.empty()) {
    throw hs::common::ConfigError(fmt::format("closure set \"{}\": no closure file (*.toml) in {}", name, dir.string()));
  }
  return *std::min_element(files.begin(), files.end());
}

ClosureSpec resolve_closure_set(const ClosureSpec& spec, ClosureKind kind) {
  if (!is_closure_set(spec.model)) return spec;
  return {.model = "expression", .file = named_closure_file(spec.model, kind), .outside = spec.outside};
}

}  // namespace hs::closures
