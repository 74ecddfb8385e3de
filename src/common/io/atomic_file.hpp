// SPDX-License-Identifier: MIT
// Atomic file replacement (write a temporary, then rename): a killed run never leaves a half-written file.
#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string_view>

namespace hs::common {

/// Writes `content` to `file` atomically.
void write_file_atomic(const std::filesystem::path& file, std::string_view content);
/// Lets `writer` fill a binary stream, then renames the result onto `file`.
void write_file_atomic(const std::filesystem::path& file, const std::function<void(std::ostream&)>& writer);

}  // namespace hs::common
