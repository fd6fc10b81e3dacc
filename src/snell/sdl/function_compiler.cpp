// `function { ... }`: POV-Ray's user-defined functions (POV-Ray 3.7 reference, "User-Defined Functions",
// "functions.inc"). The body is compiled once, as its tokens arrive, into a function::Program; declared
// floats are folded in as constants at compile time, as POV-Ray does. The function language has the float
// operators + - * / (no `^`: POV-Ray 3.7 rejects it), comparisons, & | ! and the float built-ins; there is
// no `?:` (POV-Ray rejects it too; select() takes its place).
#include <span>

#include "snell/function/builtins.hpp"
#include "snell/function/internals.hpp"
#include "snell/sdl/parser.hpp"

namespace snell::sdl {

namespace {

// select(a, b, c): b if a < 0 else c; select(a, b, c, d): b if a < 0, c if a == 0, d if a > 0.
const std::shared_ptr<const function::Function>& select3() {
  static const auto f =
      function::Function::native("select", 3, [](const double* a) { return a[0] < 0 ? a[1] : a[2]; });
  return f;
}
const std::shared_ptr<const function::Function>& select4() {
  static const auto f = function::Function::native(
      "select", 4, [](const double* a) { return a[0] < 0 ? a[1] : (a[0] == 0 ? a[2] : a[3]); });
  return f;
}

}  // namespace

/// Recursive descent over the body's tokens with the precedence of ordinary float expressions.
class FunctionCompiler {
 public:
  FunctionCompiler(Parser& parser, const std::vector<std::string>& parameters)
      : p_(parser), parameters_(parameters) {}

  void expression() { logical_or(); }
  function::Program finish() { return out_.finish(); }

 private:
  void logical_or() {
    logical_and();
    while (p_.peek().is_symbol("|")) {
      p_.raw_next();
      logical_and();
      out_.op(function::Op::logical_or);
    }
  }

  void logical_and() {
    comparison();
    while (p_.peek().is_symbol("&")) {
      p_.raw_next();
      comparison();
      out_.op(function::Op::logical_and);
    }
  }

  void comparison() {
    additive();
    for (;;) {
      const Token& t = p_.peek();
      function::Op op;
      if (t.is_symbol("<"))
        op = function::Op::less;
      else if (t.is_symbol("<="))
        op = function::Op::less_equal;
      else if (t.is_symbol("="))
        op = function::Op::equal;
      else if (t.is_symbol("!="))
        op = function::Op::not_equal;
      else if (t.is_symbol(">="))
        op = function::Op::greater_equal;
      else if (t.is_symbol(">"))
        op = function::Op::greater;
      else
        return;
      p_.raw_next();
      additive();
      out_.op(op);
    }
  }

  void additive() {
    multiplicative();
    for (;;) {
      const Token& t = p_.peek();
      if (!t.is_symbol("+") && !t.is_symbol("-")) return;
      const bool add = t.is_symbol("+");
      p_.raw_next();
      multiplicative();
      out_.op(add ? function::Op::add : function::Op::subtract);
    }
  }

  void multiplicative() {
    unary();
    for (;;) {
      const Token& t = p_.peek();
      if (!t.is_symbol("*") && !t.is_symbol("/")) return;
      const bool multiply = t.is_symbol("*");
      p_.raw_next();
      unary();
      out_.op(multiply ? function::Op::multiply : function::Op::divide);
    }
  }

  void unary() {
    const Token& t = p_.peek();
    if (t.is_symbol("-")) {
      p_.raw_next();
      unary();
      out_.op(function::Op::negate);
    } else if (t.is_symbol("+")) {
      p_.raw_next();
      unary();
    } else if (t.is_symbol("!")) {
      p_.raw_next();
      unary();
      out_.op(function::Op::logical_not);
    } else {
      primary();
    }
  }

  /// `( a, b, ... )`: compiles each argument, returns how many.
  std::uint32_t arguments(const std::string& what) {
    p_.expect("(", what.c_str());
    std::uint32_t n = 0;
    if (p_.accept(")")) return 0;
    for (;;) {
      expression();
      ++n;
      if (p_.accept(")")) return n;
      p_.expect(",", ("arguments of " + what).c_str());
    }
  }

  void primary() {
    const Token t = p_.peek();
    if (t.kind == Token::Kind::number) {
      p_.raw_next();
      out_.constant(t.number);
      return;
    }
    if (t.is_symbol("(")) {
      p_.raw_next();
      expression();
      p_.expect(")", "parenthesised expression in a function");
      return;
    }
    if (t.kind != Token::Kind::identifier) {
      p_.fail(t.where, t.kind == Token::Kind::end ? "unexpected end of file in a function"
                                                  : "expected a function expression, found '" + t.text + "'");
    }
    const std::string& w = t.text;
    // POV-Ray's fncode.cpp keeps x and u (and y and v) in one register, so `u` reads parameter x (the
    // parametric object's functions are written in u and v).
    const std::string alias = w == "u" ? "x" : w == "v" ? "y" : w == "x" ? "u" : w == "y" ? "v" : "";
    for (const std::string& name : {w, alias}) {
      for (std::size_t i = 0; i < parameters_.size() && !name.empty(); ++i) {
        if (parameters_[i] == name) {
          p_.raw_next();
          out_.parameter(static_cast<std::uint32_t>(i));
          return;
        }
      }
    }
    if (const Value* v = p_.lookup(w)) return declared(t, *v);
    const auto constant = [&](double value) {
      p_.raw_next();
      out_.constant(value);
    };
    // The scene's constants (pi, clock, image_width...) are constants inside a function too.
    if (const std::optional<double> c = p_.builtin_constant(w)) return constant(*c);
    if (w == "min" || w == "max") {
      p_.raw_next();
      const std::uint32_t n = arguments(w);
      if (n < 1) p_.fail(t.where, w + " needs at least one argument");
      for (std::uint32_t i = 1; i < n; ++i)
        out_.binary(w == "min" ? function::builtin_min : function::builtin_max);
      return;
    }
    if (w == "select") {
      p_.raw_next();
      const std::uint32_t n = arguments(w);
      if (n != 3 && n != 4) p_.fail(t.where, "select takes 3 or 4 arguments, found " + std::to_string(n));
      out_.call(n == 3 ? select3() : select4(), n);
      return;
    }
    for (const function::Builtin& b : function::builtins()) {
      if (w != b.name) continue;
      p_.raw_next();
      const std::uint32_t want = b.unary ? 1 : 2;
      const std::uint32_t n = arguments(w);
      if (n != want)
        p_.fail(t.where, w + " takes " + std::to_string(want) + " argument(s), found " + std::to_string(n));
      if (b.unary)
        out_.unary(b.unary);
      else
        out_.binary(b.binary);
      return;
    }
    p_.fail(t.where, "unknown identifier '" + w + "' in a function (functions.inc declares POV-Ray's f_*)");
  }

  void declared(const Token& t, const Value& v) {
    p_.raw_next();
    if (const auto* f = std::get_if<std::shared_ptr<const function::Function>>(&v.data)) {
      const std::uint32_t n = arguments(t.text);
      if (n != (*f)->arity())
        p_.fail(t.where, t.text + " takes " + std::to_string((*f)->arity()) + " argument(s), found " +
                             std::to_string(n));
      if ((*f)->components() > 1 && p_.peek().is_symbol(".")) return member(*f, n);
      out_.call(*f, n);
      return;
    }
    const auto* n = std::get_if<Numeric>(&v.data);
    if (!n) p_.fail(t.where, "'" + t.text + "' is a " + v.type_name() + ", which a function cannot use");
    if (n->size == 1) {
      out_.constant(n->x());
      return;
    }
    // A declared vector or colour may be used through one component (`V.x`).
    if (!p_.accept("."))
      p_.fail(t.where, "a function can only use a vector's components, as in " + t.text + ".x");
    const Token field = p_.raw_next();
    static const std::pair<const char*, int> fields[] = {
        {"x", 0},   {"y", 1},     {"z", 2},    {"t", 3},      {"u", 0},       {"v", 1},
        {"red", 0}, {"green", 1}, {"blue", 2}, {"filter", 3}, {"transmit", 4}};
    for (const auto& [name, index] : fields) {
      if (field.is_word(name) && index < (n->color ? 5 : n->size)) {
        out_.constant(n->v[static_cast<std::size_t>(index)]);
        return;
      }
    }
    p_.fail(field.where, "'." + field.text + "' is not a component of " + t.text);
  }

  /// `.red`, `.x`, `.gray`... after a call of a vector function (POV-Ray 3.7 reference, "Declaring
  /// User-Defined Color Functions"); gray weighs red, green and blue as POV-Ray's greyscale does.
  void member(const std::shared_ptr<const function::Function>& f, std::uint32_t argument_count) {
    p_.raw_next();  // '.'
    const Token field = p_.raw_next();
    if (field.is_word("gray") || field.is_word("grey")) {
      if (f->components() < 3) p_.fail(field.where, "'.gray' needs a colour");
      static const double weights[3] = {0.297, 0.589, 0.114};
      // One call of the callee, weighted: a one-component vector function around it.
      auto gray = function::Function::vector("gray", f->arity(), 1, [f](const double* a, double* out) {
        std::array<double, function::Function::kMaxComponents> c{};
        f->call_vector(a, c.data());
        out[0] = weights[0] * c[0] + weights[1] * c[1] + weights[2] * c[2];
      });
      out_.call(gray, argument_count);
      return;
    }
    static const std::pair<const char*, std::uint32_t> fields[] = {
        {"x", 0},   {"y", 1},     {"z", 2},    {"t", 3},      {"u", 0},       {"v", 1},
        {"red", 0}, {"green", 1}, {"blue", 2}, {"filter", 3}, {"transmit", 4}};
    for (const auto& [name, index] : fields) {
      if (field.is_word(name) && index < f->components()) {
        out_.call_component(f, argument_count, index);
        return;
      }
    }
    p_.fail(field.where, "'." + field.text + "' is not a component of this function's value");
  }

  Parser& p_;
  const std::vector<std::string>& parameters_;
  function::ProgramBuilder out_;
};

std::shared_ptr<const function::Function> Parser::parse_function_block() {
  std::vector<std::string> parameters;
  if (accept("(")) {
    for (;;) {
      const Token name = expect_identifier("a function's parameter list");
      for (const std::string& other : parameters)
        if (other == name.text) fail(name.where, "parameter '" + name.text + "' appears twice");
      parameters.push_back(name.text);
      if (accept(")")) break;
      expect(",", "a function's parameter list");
    }
  } else {
    parameters = {"x", "y", "z"};
  }
  expect("{", "function");
  const Token first = peek();
  if (first.is_word("internal")) {
    raw_next();
    expect("(", "internal()");
    const Token number = raw_next();
    if (number.kind != Token::Kind::number) fail(number.where, "internal() needs a function number");
    expect(")", "internal()");
    expect("}", "function");
    if (!(number.number >= 0 && number.number < 1000))
      fail(number.where, "no internal function with this number");
    try {
      return function::internal_function(static_cast<int>(number.number));
    } catch (const function::FunctionError& e) {
      fail(number.where, e.what());
    }
  }
  if (first.is_word("pattern") || first.is_word("pigment") || first.is_word("transform") ||
      first.is_word("spline")) {
    raw_next();
    auto f = parse_block_function(first);
    expect("}", "function");
    return f;
  }
  FunctionCompiler compiler(*this, parameters);
  compiler.expression();
  expect("}", "function");
  try {
    return function::Function::compiled(std::move(parameters), compiler.finish());
  } catch (const function::FunctionError& e) {
    fail(first.where, e.what());
  }
}

Numeric Parser::call_function(const Token& name, const function::Function& f) {
  expect("(", ("call of " + name.text).c_str());
  std::vector<double> args;
  if (!accept(")")) {
    for (;;) {
      args.push_back(parse_float());
      if (accept(")")) break;
      expect(",", ("arguments of " + name.text).c_str());
    }
  }
  if (args.size() != f.arity())
    fail(name.where, name.text + " takes " + std::to_string(f.arity()) + " argument(s), found " +
                         std::to_string(args.size()));
  try {
    if (f.components() > 1) {
      // A vector function's value is a vector, or a colour when it has five components.
      std::array<double, function::Function::kMaxComponents> out{};
      f.call_vector(args.data(), out.data());
      Numeric n;
      n.v = out;
      n.size = static_cast<int>(f.components());
      n.color = f.components() == 5;
      return n;
    }
    return Numeric::of(f(std::span<const double>(args)));
  } catch (const function::FunctionError& e) {
    fail(name.where, "calling " + name.text + ": " + e.what());
  }
}

}  // namespace snell::sdl
