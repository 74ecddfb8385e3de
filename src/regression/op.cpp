// SPDX-License-Identifier: MIT
// Names and arities of the expression operations.
#include "regression/op.hpp"

#include <array>
#include <utility>

namespace hs::regression {
namespace {

struct OpInfo {
  Op op;
  std::string_view name;
  int arity;
};

constexpr std::array<OpInfo, 19> table{{
    {Op::Const, "const", 0}, {Op::Var, "var", 0},   {Op::Add, "add", 2},   {Op::Sub, "sub", 2},
    {Op::Mul, "mul", 2},     {Op::Div, "div", 2},   {Op::Pow, "pow", 2},   {Op::Min, "min", 2},
    {Op::Max, "max", 2},     {Op::Sqrt, "sqrt", 1}, {Op::Log, "log", 1},   {Op::Exp, "exp", 1},
    {Op::Neg, "neg", 1},     {Op::Inv, "inv", 1},   {Op::Abs, "abs", 1},   {Op::Sin, "sin", 1},
    {Op::Cos, "cos", 1},     {Op::Tanh, "tanh", 1},  {Op::Asin, "asin", 1},
}};

}  // namespace

int arity(Op op) { return table[static_cast<std::size_t>(op)].arity; }

std::string_view op_name(Op op) { return table[static_cast<std::size_t>(op)].name; }

std::optional<Op> op_from_name(std::string_view name) {
  for (const auto& info : table) {
    if (info.arity > 0 && info.name == name) return info.op;
  }
  return std::nullopt;
}

std::vector<Op> all_functions() {
  std::vector<Op> out;
  for (const auto& info : table) {
    if (info.arity > 0) out.push_back(info.op);
  }
  return out;
}

}  // namespace hs::regression
