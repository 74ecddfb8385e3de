// SPDX-License-Identifier: MIT
// Committed closure sets a case names instead of a path (`drag = "resolved"`), so a copied case folder still finds them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "closures/closure_registry.hpp"

namespace hs::closures {

enum class ClosureKind { drag, lift, deformation };

/// The registered set names, each a folder of data/closures/ (data/closures/README.md) holding one closure file per
/// kind: drag_coefficient/, lift_coefficient/, deformation_index/.
[[nodiscard]] const std::vector<std::string>& closure_set_names();
[[nodiscard]] bool is_closure_set(const std::string& name);
/// The data folders searched for the committed sets, in order (docs/closures.md, "Named closure sets"): $HS_DATA_DIR,
/// then share/hemoscale/data beside the executable's bin/ (an installed hemoscale), then the source tree's data/ it
/// was built from. The first that holds closures/NAME wins.
[[nodiscard]] std::vector<std::filesystem::path> closure_data_dirs();
/// The folder of set `name` (DATA/closures/NAME): ConfigError listing every place looked when none holds it.
[[nodiscard]] std::filesystem::path closure_set_dir(const std::string& name);
/// The closure file of `kind` in set `name`: the first *.toml (by name) in its kind folder. ConfigError naming the
/// folder when the set is unknown or the folder holds no closure file.
[[nodiscard]] std::filesystem::path named_closure_file(const std::string& name, ClosureKind kind);
/// `spec` with a set name replaced by model "expression" and the set's file of `kind` (so a run records the file);
/// any other spec unchanged.
[[nodiscard]] ClosureSpec resolve_closure_set(const ClosureSpec& spec, ClosureKind kind);

}  // namespace hs::closures
