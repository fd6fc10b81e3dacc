#pragma once
// Arithmetic of parametric L-system rules (Prusinkiewicz & Lindenmayer, The Algorithmic Beauty of Plants,
// 1990, ch. 1.10): a rule's condition and the arguments of its successor's modules, e.g. `l > 1` or
// `l * 0.5`. Numbers, the predecessor's parameter names, + - * / ^, comparisons, && || !, parentheses and
// sqrt sin cos tan (radians) abs min max. Compiled once to postfix and evaluated per module.
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace snell::procedural {

/// Bad L-system input (a rule, an expression, a string grown past its limit); the message says why.
class LSystemError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Expression {
 public:
  /// Throws LSystemError for text that does not parse or names an unknown parameter.
  Expression(std::string_view text, const std::vector<std::string>& parameters);
  /// `values` holds the predecessor's parameters in the order they were named.
  double evaluate(std::span<const double> values) const;

 private:
  enum class Op : unsigned char {
    constant,
    parameter,
    negate,
    logical_not,
    add,
    subtract,
    multiply,
    divide,
    power,
    less,
    less_equal,
    greater,
    greater_equal,
    equal,
    not_equal,
    logical_and,
    logical_or,
    sqrt,
    sin,
    cos,
    tan,
    abs,
    min,
    max
  };
  struct Step {
    Op op;
    double value;  // the constant, or the parameter's index
  };
  std::vector<Step> steps_;
  friend class ExpressionParser;
};

}  // namespace snell::procedural
