// SPDX-License-Identifier: MIT
// SHA-256 of a file, for the dataset hash in closure provenance (FIPS 180-4).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace hs::closures {

/// Lower-case hex SHA-256 of `data`.
[[nodiscard]] std::string sha256_hex(std::string_view data);
/// Lower-case hex SHA-256 of a file's bytes; ConfigError if it cannot be read.
[[nodiscard]] std::string sha256_file(const std::filesystem::path& file);

}  // namespace hs::closures
