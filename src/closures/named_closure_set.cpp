// SPDX-License-Identifier: MIT
// Committed closure sets a case names instead of a path (`drag = "resolved"`), so a copied case folder still finds them.
#include "closures/named_closure_set.hpp"

#include <algorithm>

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

bool is_closure_set(const std::string& name) {
  const auto& n = closure_set_names();
  return std::find(n.begin(), n.end(), name) != n.end();
}

std::filesystem::path named_closure_file(const std::string& name, ClosureKind kind) {
  if (!is_closure_set(name)) throw hs::common::ConfigError(fmt::format("\"{}\" is not a committed closure set", name));
  const std::filesystem::path dir = std::filesystem::path(HS_CLOSURE_DATA_DIR) / name / kind_folder(kind);
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
