// SPDX-License-Identifier: MIT
#include "common/config/toml_floats.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <system_error>

namespace hs::common {
namespace {

/// Where a value starts in toml++'s output: after "= ", "[" or ", " (arrays).
bool value_may_start_after(char c) { return c == '=' || c == ' ' || c == '[' || c == ','; }
bool value_may_end_at(char c) { return c == ',' || c == ']' || c == ' ' || c == '\n' || c == '}' || c == '\r'; }

/// The float token `token` in its shortest round-trip form; `token` itself when it is no float (an integer, a date).
std::string shortest(std::string_view token) {
  if (token.find_first_of(".eE") == std::string_view::npos) return std::string(token);   // an integer
  const char* first = token.data();
  if (*first == '+') ++first;
  double value = 0.0;
  const auto [end, error] = std::from_chars(first, token.data() + token.size(), value);
  if (error != std::errc{} || end != token.data() + token.size()) return std::string(token);   // a date, a time
  char buf[32];
  const auto written = std::to_chars(buf, buf + sizeof buf, value);
  std::string out(buf, written.ptr);
  if (out.find_first_of(".eE") == std::string::npos && out.find_first_of("in") == std::string::npos) out += ".0";
  return out;
}

/// The length of the quoted string at text[i] (basic "..." with escapes, or literal '...').
std::size_t string_length(std::string_view text, std::size_t i) {
  const char quote = text[i];
  std::size_t k = i + 1;
  while (k < text.size() && text[k] != quote && text[k] != '\n') k += (quote == '"' && text[k] == '\\') ? 2 : 1;
  return k + 1 - i;
}

}  // namespace

std::string with_shortest_floats(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '"' || c == '\'') {
      const std::size_t n = std::min(string_length(text, i), text.size() - i);
      out.append(text.substr(i, n));
      i += n;
    } else if (c == '#') {   // a comment, to the end of its line
      const std::size_t end = std::min(text.find('\n', i), text.size());
      out.append(text.substr(i, end - i));
      i = end;
    } else if ((std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+') && i > 0 &&
               value_may_start_after(text[i - 1])) {
      std::size_t end = i + 1;
      while (end < text.size() && !value_may_end_at(text[end])) ++end;
      std::size_t next = end;
      while (next < text.size() && text[next] == ' ') ++next;
      const bool is_key = next < text.size() && (text[next] == '=' || text[next] == '.');   // a bare key "1e5 = 2"
      out += is_key ? std::string(text.substr(i, end - i)) : shortest(text.substr(i, end - i));
      i = end;
    } else {
      out += c;
      ++i;
    }
  }
  return out;
}

}  // namespace hs::common
