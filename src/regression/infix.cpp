// SPDX-License-Identifier: MIT
// Recursive-descent infix parser and minimal-parenthesis printer for expressions.
#include "regression/infix.hpp"

#include <cctype>
#include <charconv>
#include <cstdlib>

#include <fmt/format.h>

namespace hs::regression {
namespace {

class Parser {
 public:
  Parser(std::string_view text, const std::vector<std::string>& variables) : text_(text), variables_(variables) {}

  Expression parse() {
    std::vector<Node> out;
    parse_expr(out);
    skip_space();
    if (pos_ != text_.size()) fail("end of expression");
    return Expression(std::move(out));
  }

 private:
  [[noreturn]] void fail(std::string_view expected) const {
    const std::string rest(text_.substr(pos_, 12));
    throw ParseError(fmt::format("cannot parse expression \"{}\" at position {} (\"{}\"): expected {}", text_, pos_,
                                 rest, expected));
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool accept(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!accept(c)) fail(fmt::format("'{}'", c));
  }
  // Binary operators are prefix nodes: the operator goes in front of both operands already parsed.
  static void wrap_binary(std::vector<Node>& out, std::size_t left_start, Op op) {
    out.insert(out.begin() + static_cast<std::ptrdiff_t>(left_start), Node::function(op));
  }
  void parse_expr(std::vector<Node>& out) {
    const std::size_t start = out.size();
    parse_term(out);
    while (true) {
      if (accept('+')) {
        parse_term(out);
        wrap_binary(out, start, Op::Add);
      } else if (accept('-')) {
        parse_term(out);
        wrap_binary(out, start, Op::Sub);
      } else {
        return;
      }
    }
  }
  void parse_term(std::vector<Node>& out) {
    const std::size_t start = out.size();
    parse_unary(out);
    while (true) {
      if (accept('*')) {
        parse_unary(out);
        wrap_binary(out, start, Op::Mul);
      } else if (accept('/')) {
        parse_unary(out);
        wrap_binary(out, start, Op::Div);
      } else {
        return;
      }
    }
  }
  void parse_unary(std::vector<Node>& out) {
    if (accept('-')) {
      skip_space();
      const std::size_t save = pos_;
      if (pos_ < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.')) {
        const double v = parse_number();
        skip_space();
        if (pos_ >= text_.size() || text_[pos_] != '^') {
          out.push_back(Node::constant(-v));
          return;
        }
        pos_ = save;
      }
      out.push_back(Node::function(Op::Neg));
      parse_unary(out);
      return;
    }
    parse_power(out);
  }
  void parse_power(std::vector<Node>& out) {
    const std::size_t start = out.size();
    parse_primary(out);
    if (accept('^')) {
      parse_unary(out);
      wrap_binary(out, start, Op::Pow);
    }
  }
  double parse_number() {
    const char* first = text_.data() + pos_;
    const char* last = text_.data() + text_.size();
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || ptr == first) fail("a number");
    pos_ += static_cast<std::size_t>(ptr - first);
    return v;
  }
  std::string parse_name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) ++pos_;
    return std::string(text_.substr(start, pos_ - start));
  }
  void parse_call(std::vector<Node>& out, const std::string& name) {
    const auto op = op_from_name(name);
    if (!op) fail(fmt::format("a known function instead of \"{}\"", name));
    out.push_back(Node::function(*op));
    parse_expr(out);
    if (arity(*op) == 2) {
      expect(',');
      parse_expr(out);
    }
    expect(')');
  }
  void parse_primary(std::vector<Node>& out) {
    skip_space();
    if (pos_ >= text_.size()) fail("a number, variable, function or '('");
    const char c = text_[pos_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      out.push_back(Node::constant(parse_number()));
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::string name = parse_name();
      if (accept('(')) {
        parse_call(out, name);
        return;
      }
      for (std::size_t i = 0; i < variables_.size(); ++i) {
        if (variables_[i] == name) {
          out.push_back(Node::variable(i));
          return;
        }
      }
      pos_ -= name.size();
      std::string known;
      for (const auto& v : variables_) known += (known.empty() ? "" : ", ") + v;
      fail(fmt::format("a variable (one of: {}) instead of \"{}\"", known.empty() ? "none" : known, name));
    } else if (accept('(')) {
      parse_expr(out);
      expect(')');
    } else {
      fail("a number, variable, function or '('");
    }
  }

  std::string_view text_;
  const std::vector<std::string>& variables_;
  std::size_t pos_ = 0;
};

// Precedence for printing: 1 + -, 2 * /, 3 unary minus (and negative constants), 4 ^, 5 primary.
int precedence(const Node& n) {
  switch (n.op) {
    case Op::Add:
    case Op::Sub: return 1;
    case Op::Mul:
    case Op::Div: return 2;
    case Op::Neg: return 3;
    case Op::Pow: return 4;
    case Op::Const: return n.value < 0.0 || std::signbit(n.value) ? 3 : 5;
    default: return 5;
  }
}

char symbol(Op op) {
  switch (op) {
    case Op::Add: return '+';
    case Op::Sub: return '-';
    case Op::Mul: return '*';
    case Op::Div: return '/';
    default: return '^';
  }
}

class Printer {
 public:
  Printer(const Expression& e, const std::vector<std::string>& variables) : e_(e), variables_(variables) {}

  std::string print(std::size_t i) {
    const Node& n = e_[i];
    if (n.op == Op::Const) return fmt::format("{}", n.value);
    if (n.op == Op::Var) return n.var < variables_.size() ? variables_[n.var] : fmt::format("x{}", n.var);
    const std::size_t a = i + 1;
    if (n.op == Op::Neg) return fmt::format("-{}", wrapped(a, precedence(e_[a]) <= 2 || (precedence(e_[a]) == 5 && e_[a].op == Op::Const)));
    if (arity(n.op) == 1) return fmt::format("{}({})", op_name(n.op), print(a));
    const std::size_t b = e_.subtree_end(a);
    if (n.op == Op::Min || n.op == Op::Max) return fmt::format("{}({}, {})", op_name(n.op), print(a), print(b));
    const int p = precedence(n);
    if (n.op == Op::Pow) {
      const int pb = precedence(e_[b]);
      return fmt::format("{}^{}", wrapped(a, precedence(e_[a]) <= 4), wrapped(b, pb < 4));
    }
    const bool spaced = p == 1;
    const std::string sep = spaced ? fmt::format(" {} ", symbol(n.op)) : std::string(1, symbol(n.op));
    return fmt::format("{}{}{}", wrapped(a, precedence(e_[a]) < p), sep, wrapped(b, precedence(e_[b]) <= p));
  }

 private:
  std::string wrapped(std::size_t i, bool parens) { return parens ? fmt::format("({})", print(i)) : print(i); }

  const Expression& e_;
  const std::vector<std::string>& variables_;
};

}  // namespace

Expression parse_infix(std::string_view text, const std::vector<std::string>& variables) {
  return Parser(text, variables).parse();
}

std::string to_infix(const Expression& e, const std::vector<std::string>& variables) {
  if (e.empty()) return "";
  return Printer(e, variables).print(0);
}

}  // namespace hs::regression
