// SPDX-License-Identifier: MIT
// The two kinds of failure a user sees: bad input (exit 2) and numerical breakdown (exit 3).
#pragma once

#include <stdexcept>
#include <string>

namespace hs::common {

/// Bad user input: the message names file, key, value and what is allowed. The CLI exits with code 2.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The simulation broke down (NaN, Mach or CFL limit, exploding membrane). The CLI exits with code 3;
/// the last good checkpoint is kept.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr int exit_code_config_error    = 2;
inline constexpr int exit_code_numerical_error = 3;

}  // namespace hs::common
