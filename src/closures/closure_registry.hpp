// SPDX-License-Identifier: MIT
// Name -> factory lists for interchangeable closures (STYLE R5), filled by register_builtin().
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::closures {

/// What a learned closure does with inputs outside its validity box (the counts report them either way).
/// clamp: evaluates at the nearest point of the box, because a fitted formula is only known there and can turn
/// unphysical just outside it (the resolved-dataset DI(gamma+, u_r+) goes negative at the slip of a cell inserted
/// at rest); for drag the correction C_d Re_p / 24 is what is held (ExpressionDrag). extrapolate: the formula as
/// it is.
enum class OutsideValidity { clamp, extrapolate };

/// One closure as a case chose it: a registered name, or model "expression" with its closure file
/// (tube-pries: `[coupling] drag = "schiller_naumann" | "path/cd.toml"`, unresolved/cases/tube_pries.cpp).
struct ClosureSpec {
  std::string model;
  std::filesystem::path file;   // closure file, for model = "expression" (absolute)
  OutsideValidity outside = OutsideValidity::clamp;   // learned closures only
};

template <class T>
class ClosureRegistry {
 public:
  using Factory = std::function<std::unique_ptr<T>(const ClosureSpec&)>;

  void add(std::string name, Factory factory) { factories_[std::move(name)] = std::move(factory); }
  /// The closure `spec.model`; an unknown name is a ConfigError listing the known ones.
  [[nodiscard]] std::unique_ptr<T> create(const ClosureSpec& spec) const {
    const auto it = factories_.find(spec.model);
    if (it == factories_.end()) {
      std::string known;
      for (const auto& [name, f] : factories_) known += (known.empty() ? "" : ", ") + name;
      throw hs::common::ConfigError(fmt::format("unknown closure model \"{}\" (known: {})", spec.model, known));
    }
    return it->second(spec);
  }
  [[nodiscard]] bool has(const std::string& name) const { return factories_.count(name) > 0; }

 private:
  std::map<std::string, Factory> factories_;
};

}  // namespace hs::closures
