// SPDX-License-Identifier: MIT
// Floats in TOML text as a person wrote them: toml++ (as Debian builds it with GCC) prints a double with 17 significant
// digits, so 1e-05 comes out as 1.0000000000000001e-05; this rewrites each float of a toml++ document with the
// shortest digits that read back to the same double (std::to_chars), so case.resolved.toml quotes 1e-05 as written.
#pragma once

#include <string>
#include <string_view>

namespace hs::common {

/// `toml_text` (as toml++ prints a table) with every float value in its shortest round-trip form; strings, comments,
/// keys, integers and dates are left as they are.
[[nodiscard]] std::string with_shortest_floats(std::string_view toml_text);

}  // namespace hs::common
