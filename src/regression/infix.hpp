// SPDX-License-Identifier: MIT
// Infix text <-> expression: print(parse(s)) and parse(print(e)) round-trip node for node.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "regression/expression.hpp"

namespace hs::regression {

/// A malformed infix expression; the message names the position and what was expected.
class ParseError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Grammar (usual precedence, binary operators left-associative, ^ right-associative):
///   expr  = term {("+" | "-") term}        term  = unary {("*" | "/") unary}
///   unary = "-" unary | power              power = primary ["^" unary]
///   primary = number | name | name "(" expr ["," expr] ")" | "(" expr ")"
/// "/" is protected division, "^" protected power, calls are the function-set names (sqrt, log, exp, min,
/// ...). "-" directly before a number (not followed by "^") is a negative constant, else neg().
/// A name must be one of `variables` (its index there is the feature index); otherwise ParseError.
[[nodiscard]] Expression parse_infix(std::string_view text, const std::vector<std::string>& variables);

/// Infix text with the fewest parentheses that keep the tree, and constants in their shortest round-trip form.
[[nodiscard]] std::string to_infix(const Expression& e, const std::vector<std::string>& variables);

}  // namespace hs::regression
