// SPDX-License-Identifier: MIT
// Postfix compilation and block-wise evaluation of expressions.
#include "regression/compiled_program.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace hs::regression {
namespace {

// One vectorisable loop per binary op: d[i] = f(d[i], s[i]).
template <class F>
inline void binary_loop(double* __restrict d, const double* __restrict s, std::size_t n, F f) {
  for (std::size_t i = 0; i < n; ++i) d[i] = f(d[i], s[i]);
}
template <class F>
inline void unary_loop(double* __restrict d, std::size_t n, F f) {
  for (std::size_t i = 0; i < n; ++i) d[i] = f(d[i]);
}

void run_binary(Op op, double* d, const double* s, std::size_t n) {
  switch (op) {
    case Op::Add: binary_loop(d, s, n, [](double a, double b) { return a + b; }); break;
    case Op::Sub: binary_loop(d, s, n, [](double a, double b) { return a - b; }); break;
    case Op::Mul: binary_loop(d, s, n, [](double a, double b) { return a * b; }); break;
    case Op::Div:
      binary_loop(d, s, n, [](double a, double b) { return std::abs(b) > protect_threshold ? a / b : 1.0; });
      break;
    case Op::Min: binary_loop(d, s, n, [](double a, double b) { return b < a ? b : a; }); break;
    case Op::Max: binary_loop(d, s, n, [](double a, double b) { return a < b ? b : a; }); break;
    default: binary_loop(d, s, n, [op](double a, double b) { return apply(op, a, b); }); break;
  }
}

void run_unary(Op op, double* d, std::size_t n) {
  switch (op) {
    case Op::Neg: unary_loop(d, n, [](double a) { return -a; }); break;
    case Op::Abs: unary_loop(d, n, [](double a) { return std::abs(a); }); break;
    case Op::Sqrt: unary_loop(d, n, [](double a) { return std::sqrt(std::abs(a)); }); break;
    case Op::Inv: unary_loop(d, n, [](double a) { return std::abs(a) > protect_threshold ? 1.0 / a : 0.0; }); break;
    default: unary_loop(d, n, [op](double a) { return apply(op, a, 0.0); }); break;
  }
}

}  // namespace

CompiledProgram::CompiledProgram(const Expression& e) {
  if (e.empty() || !e.well_formed()) throw std::invalid_argument("CompiledProgram: malformed expression");
  code_.reserve(e.size());
  // Children first, then the op; the first argument lands in `slot`, the second in `slot + 1`.
  auto compile = [&](auto&& self, std::size_t i, std::size_t slot) -> std::size_t {
    stack_depth_ = std::max(stack_depth_, slot + 1);
    const Node& n = e[i];
    std::size_t end = i + 1;
    if (arity(n.op) >= 1) end = self(self, end, slot);
    if (arity(n.op) == 2 && e[end].op == Op::Var) {   // fused: the op reads the feature column in place
      code_.push_back({n.op, e[end].var, static_cast<std::uint16_t>(slot), 0.0, true});
      return end + 1;
    }
    if (arity(n.op) == 2) end = self(self, end, slot + 1);
    if (n.op == Op::Const) constant_slots_.push_back(code_.size());
    code_.push_back({n.op, n.var, static_cast<std::uint16_t>(slot), n.value, false});
    return end;
  };
  compile(compile, 0, 0);
}

void CompiledProgram::set_constants(std::span<const double> values) {
  if (values.size() != constant_slots_.size()) throw std::invalid_argument("CompiledProgram: wrong constant count");
  for (std::size_t k = 0; k < values.size(); ++k) code_[constant_slots_[k]].value = values[k];
}

void CompiledProgram::evaluate_block(const DataView& data, std::size_t row0, std::size_t len, double* stack,
                                     double* out) const {
  for (const Instruction& in : code_) {
    double* d = stack + static_cast<std::size_t>(in.dst) * block_rows;
    switch (in.op) {
      case Op::Const: std::fill(d, d + len, in.value); break;
      case Op::Var: std::memcpy(d, data.columns[in.var] + row0, len * sizeof(double)); break;
      default:
        if (in.var_operand) {
          run_binary(in.op, d, data.columns[in.var] + row0, len);
        } else if (arity(in.op) == 2) {
          run_binary(in.op, d, d + block_rows, len);
        } else {
          run_unary(in.op, d, len);
        }
    }
  }
  std::memcpy(out, stack, len * sizeof(double));
}

void CompiledProgram::evaluate(const DataView& data, std::span<double> out) const {
  if (out.size() < data.rows) throw std::invalid_argument("CompiledProgram::evaluate: output too short");
  std::vector<double> stack(stack_depth_ * block_rows);
  for (std::size_t row0 = 0; row0 < data.rows; row0 += block_rows) {
    const std::size_t len = std::min(block_rows, data.rows - row0);
    evaluate_block(data, row0, len, stack.data(), out.data() + row0);
  }
}

double CompiledProgram::evaluate_point(const double* x) const {
  constexpr std::size_t small = 32;
  double local[small] = {};
  std::vector<double> heap;
  double* s = local;
  if (stack_depth_ > small) {
    heap.resize(stack_depth_);
    s = heap.data();
  }
  for (const Instruction& in : code_) {
    double& d = s[in.dst];
    if (in.op == Op::Const) {
      d = in.value;
    } else if (in.op == Op::Var) {
      d = x[in.var];
    } else {
      d = apply(in.op, d, in.var_operand ? x[in.var] : arity(in.op) == 2 ? s[in.dst + 1] : 0.0);
    }
  }
  return s[0];
}

}  // namespace hs::regression
