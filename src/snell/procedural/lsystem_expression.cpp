// Recursive descent over the expression grammar (lowest to highest precedence: || && comparisons + - * /
// unary ^ atoms), emitting postfix steps that a small stack machine evaluates.
#include "snell/procedural/lsystem_expression.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace snell::procedural {

class ExpressionParser {
 public:
  static constexpr int kMaxDepth = 64;

  ExpressionParser(std::string_view text, const std::vector<std::string>& names, Expression& out)
      : text_(text), names_(names), out_(out) {}

  void parse() {
    parse_or();
    skip_space();
    if (pos_ != text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "'");
  }

 private:
  using Op = Expression::Op;

  [[noreturn]] void fail(const std::string& why) const {
    throw LSystemError("in expression \"" + std::string(text_) + "\": " + why);
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool take(std::string_view token) {
    skip_space();
    if (text_.substr(pos_, token.size()) != token) return false;
    pos_ += token.size();
    return true;
  }
  void emit(Op op, double value = 0) {
    out_.steps_.push_back({op, value});
    // Track the evaluation stack's depth so evaluate() can use a fixed array.
    if (op == Op::constant || op == Op::parameter) {
      if (++depth_ > kMaxDepth) fail("the expression nests too deeply");
    } else if (op != Op::negate && op != Op::logical_not && op < Op::sqrt) {
      --depth_;
    } else if (op == Op::min || op == Op::max) {
      --depth_;
    }
  }

  void parse_or() {
    parse_and();
    while (take("||")) parse_and(), emit(Op::logical_or);
  }
  void parse_and() {
    parse_comparison();
    while (take("&&")) parse_comparison(), emit(Op::logical_and);
  }
  void parse_comparison() {
    parse_sum();
    static const std::pair<std::string_view, Op> comparisons[] = {
        {"<=", Op::less_equal}, {">=", Op::greater_equal}, {"==", Op::equal}, {"!=", Op::not_equal},
        {"<", Op::less},        {">", Op::greater},        {"=", Op::equal}};
    for (const auto& [token, op] : comparisons)
      if (take(token)) {
        parse_sum();
        emit(op);
        return;
      }
  }
  void parse_sum() {
    parse_product();
    for (;;) {
      if (take("+"))
        parse_product(), emit(Op::add);
      else if (take("-"))
        parse_product(), emit(Op::subtract);
      else
        return;
    }
  }
  void parse_product() {
    parse_unary();
    for (;;) {
      if (take("*"))
        parse_unary(), emit(Op::multiply);
      else if (take("/"))
        parse_unary(), emit(Op::divide);
      else
        return;
    }
  }
  void parse_unary() {
    if (take("-")) return parse_unary(), emit(Op::negate);
    if (take("+")) return parse_unary();
    if (take("!")) return parse_unary(), emit(Op::logical_not);
    parse_power();
  }
  void parse_power() {
    parse_atom();
    if (take("^")) parse_unary(), emit(Op::power);  // right-associative
  }
  void parse_atom() {
    skip_space();
    if (pos_ >= text_.size()) fail("the expression ends too early");
    const char c = text_[pos_];
    if (take("(")) {
      parse_or();
      if (!take(")")) fail("expected ')'");
      return;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const std::string rest(text_.substr(pos_));
      char* end = nullptr;
      const double value = std::strtod(rest.c_str(), &end);
      if (end == rest.c_str()) fail("bad number");
      pos_ += static_cast<std::size_t>(end - rest.c_str());
      return emit(Op::constant, value);
    }
    if (!std::isalpha(static_cast<unsigned char>(c)) && c != '_')
      fail("unexpected '" + std::string(1, c) + "'");
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      ++pos_;
    const std::string name(text_.substr(start, pos_ - start));
    for (std::size_t i = 0; i < names_.size(); ++i)
      if (names_[i] == name) return emit(Op::parameter, static_cast<double>(i));
    parse_call(name);
  }
  void parse_call(const std::string& name) {
    static const std::pair<std::string_view, Op> unary[] = {
        {"sqrt", Op::sqrt}, {"sin", Op::sin}, {"cos", Op::cos}, {"tan", Op::tan}, {"abs", Op::abs}};
    static const std::pair<std::string_view, Op> binary[] = {{"min", Op::min}, {"max", Op::max}};
    const auto arguments = [&](int count) {
      if (!take("(")) fail("'" + name + "' needs its arguments in parentheses");
      for (int i = 0; i < count; ++i) {
        if (i > 0 && !take(",")) fail("'" + name + "' takes " + std::to_string(count) + " arguments");
        parse_or();
      }
      if (!take(")")) fail("expected ')' after the arguments of '" + name + "'");
    };
    for (const auto& [fn, op] : unary)
      if (name == fn) return arguments(1), emit(op);
    for (const auto& [fn, op] : binary)
      if (name == fn) return arguments(2), emit(op);
    fail("unknown name '" + name + "' (not a parameter of the rule's predecessor)");
  }

  std::string_view text_;
  const std::vector<std::string>& names_;
  Expression& out_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

Expression::Expression(std::string_view text, const std::vector<std::string>& parameters) {
  ExpressionParser(text, parameters, *this).parse();
}

double Expression::evaluate(std::span<const double> values) const {
  double stack[ExpressionParser::kMaxDepth];
  int top = 0;
  for (const Step& s : steps_) {
    if (s.op == Op::constant) {
      stack[top++] = s.value;
      continue;
    }
    if (s.op == Op::parameter) {
      stack[top++] = values[static_cast<std::size_t>(s.value)];
      continue;
    }
    double& a = stack[top - 1];
    switch (s.op) {
      case Op::negate:
        a = -a;
        continue;
      case Op::logical_not:
        a = a == 0 ? 1 : 0;
        continue;
      case Op::sqrt:
        a = std::sqrt(a);
        continue;
      case Op::sin:
        a = std::sin(a);
        continue;
      case Op::cos:
        a = std::cos(a);
        continue;
      case Op::tan:
        a = std::tan(a);
        continue;
      case Op::abs:
        a = std::abs(a);
        continue;
      default:
        break;
    }
    const double b = stack[--top];
    double& l = stack[top - 1];
    switch (s.op) {
      case Op::add:
        l = l + b;
        break;
      case Op::subtract:
        l = l - b;
        break;
      case Op::multiply:
        l = l * b;
        break;
      case Op::divide:
        l = l / b;
        break;
      case Op::power:
        l = std::pow(l, b);
        break;
      case Op::less:
        l = l < b;
        break;
      case Op::less_equal:
        l = l <= b;
        break;
      case Op::greater:
        l = l > b;
        break;
      case Op::greater_equal:
        l = l >= b;
        break;
      case Op::equal:
        l = l == b;
        break;
      case Op::not_equal:
        l = l != b;
        break;
      case Op::logical_and:
        l = (l != 0 && b != 0);
        break;
      case Op::logical_or:
        l = (l != 0 || b != 0);
        break;
      case Op::min:
        l = std::min(l, b);
        break;
      case Op::max:
        l = std::max(l, b);
        break;
      default:
        break;
    }
  }
  return top > 0 ? stack[top - 1] : 0;
}

}  // namespace snell::procedural
