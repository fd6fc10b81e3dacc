// Expressions: floats, 2-5 component vectors and colours with POV-Ray's promotion rules, strings, and the
// built-in constants and functions (POV-Ray 3.7 reference, "Float Expressions", "Vector Expressions",
// "Color Expressions", "String Expressions").
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "snell/math/constants.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/sdl/string_functions.hpp"
#include "snell/texture/warp.hpp"

namespace snell::sdl {

namespace {

/// Widens `a` to `size` components: a float fills every component, a shorter vector is padded with 0.
Numeric widen(const Numeric& a, int size) {
  if (a.size >= size) return a;
  Numeric r = a;
  if (a.size == 1) {
    for (double& c : r.v) c = a.v[0];
  } else {
    for (int i = a.size; i < 5; ++i) r.v[static_cast<size_t>(i)] = 0;
  }
  r.size = size;
  return r;
}

template <typename Op>
Numeric combine(const Numeric& a, const Numeric& b, Op op) {
  const int size = std::max(a.size, b.size);
  const Numeric wa = widen(a, size), wb = widen(b, size);
  Numeric r;
  r.size = size;
  r.color = a.color || b.color;
  for (size_t i = 0; i < 5; ++i) r.v[i] = op(wa.v[i], wb.v[i]);
  return r;
}

using FunctionPtr = std::shared_ptr<const function::Function>;

}  // namespace

void Parser::expect(const char* symbol, const char* context) {
  const Token t = peek();
  if (!t.is_symbol(symbol)) {
    fail(t.where, std::string("expected '") + symbol + "' in " + context + ", found " +
                      (t.kind == Token::Kind::end ? std::string("end of file") : "'" + t.text + "'"));
  }
  raw_next();
}

bool Parser::accept(const char* symbol) {
  if (!peek().is_symbol(symbol)) return false;
  raw_next();
  return true;
}

Token Parser::expect_identifier(const char* context) {
  const Token t = next();
  if (t.kind != Token::Kind::identifier) fail(t.where, std::string("expected an identifier in ") + context);
  return t;
}

Numeric Parser::parse_argument_numeric() {
  return parse_additive();
}

double Parser::parse_directive_float() {
  const scene::SourceLocation where = peek().where;
  const Numeric n = parse_numeric();
  if (n.size != 1) fail(where, "expected a float, found a " + std::string(n.color ? "color" : "vector"));
  return n.x();
}

double Parser::parse_float() {
  const Token& start = peek();
  const scene::SourceLocation where = start.where;
  const Numeric n = parse_argument_numeric();
  if (n.size != 1) fail(where, "expected a float, found a " + std::string(n.color ? "color" : "vector"));
  return n.x();
}

int Parser::parse_int(const char* what, int lo, int hi) {
  const scene::SourceLocation where = peek().where;
  const double value = std::trunc(parse_float());
  if (!(value >= lo && value <= hi))
    fail(where, std::string(what) + " must be a whole number from " + std::to_string(lo) + " to " +
                    std::to_string(hi) + ", found " + fmt::format("{:g}", value));
  return static_cast<int>(value);
}

math::Vec3 Parser::parse_vector() {
  const scene::SourceLocation where = peek().where;
  const Numeric n = parse_argument_numeric();
  if (n.color) fail(where, "expected a vector, found a color");
  if (n.size == 2) return {n.v[0], n.v[1], 0};
  return n.vec3();
}

material::Rgbft Parser::parse_color() {
  Numeric n = widen(parse_argument_numeric(), 5);
  // POV-Ray's Parse_Colour keeps reading channel keywords after a bare colour (`pigment { White filter
  // 0.95 }`, interior/crystal.pov): they change that colour rather than start a new one.
  static const std::pair<const char*, size_t> channels[] = {
      {"red", 0}, {"green", 1}, {"blue", 2}, {"filter", 3}, {"transmit", 4}};
  for (bool more = true; more;) {
    more = false;
    for (const auto& [word, index] : channels)
      if (peek().is_word(word)) {
        raw_next();
        n.v[index] = parse_float();
        more = true;
      }
  }
  return {{n.v[0], n.v[1], n.v[2]}, n.v[3], n.v[4]};
}

bool Parser::starts_string() {
  const Token& t = peek();
  if (t.kind == Token::Kind::string) return true;
  if (t.kind != Token::Kind::identifier) return false;
  if (is_string_function(t.text)) return true;
  const Value* v = lookup(t.text);
  return v && std::holds_alternative<std::string>(v->data);
}

bool Parser::starts_numeric() {
  const Token& t = peek();
  if (t.kind == Token::Kind::number) return true;
  if (t.kind == Token::Kind::symbol)
    return t.text == "(" || t.text == "<" || t.text == "-" || t.text == "+" || t.text == "!";
  if (t.kind != Token::Kind::identifier) return false;
  if (const Value* v = lookup(t.text))
    return std::holds_alternative<Numeric>(v->data) ||
           std::holds_alternative<std::shared_ptr<const function::Function>>(v->data) ||
           std::holds_alternative<std::shared_ptr<const Spline>>(v->data);
  if (is_numeric_string_function(t.text)) return true;
  static const char* const words[] = {"x",
                                      "y",
                                      "z",
                                      "t",
                                      "u",
                                      "v",
                                      "pi",
                                      "tau",
                                      "true",
                                      "false",
                                      "on",
                                      "off",
                                      "yes",
                                      "no",
                                      "version",
                                      "clock",
                                      "image_width",
                                      "image_height",
                                      "frame_number",
                                      "clock_delta",
                                      "clock_on",
                                      "trace",
                                      "inside",
                                      "vturbulence",
                                      "min_extent",
                                      "max_extent",
                                      "dimension_size",
                                      "dimensions",
                                      "initial_frame",
                                      "final_frame",
                                      "rgb",
                                      "rgbf",
                                      "rgbt",
                                      "rgbft",
                                      "red",
                                      "green",
                                      "blue",
                                      "filter",
                                      "transmit",
                                      "color",
                                      "abs",
                                      "min",
                                      "max",
                                      "pow",
                                      "sqrt",
                                      "sqr",
                                      "exp",
                                      "log",
                                      "ln",
                                      "sin",
                                      "cos",
                                      "tan",
                                      "asin",
                                      "acos",
                                      "atan",
                                      "atan2",
                                      "floor",
                                      "ceil",
                                      "int",
                                      "mod",
                                      "div",
                                      "radians",
                                      "degrees",
                                      "vlength",
                                      "vnormalize",
                                      "vdot",
                                      "vcross",
                                      "select",
                                      "strlen",
                                      "defined",
                                      "val",
                                      "vrotate",
                                      "vaxis_rotate",
                                      "sinh",
                                      "cosh",
                                      "tanh",
                                      "asc",
                                      "gray",
                                      "grey",
                                      "initial_clock",
                                      "final_clock"};
  for (const char* w : words)
    if (t.text == w) return true;
  return false;
}

bool Parser::parse_bool_optional(bool if_absent) {
  if (!starts_numeric()) return if_absent;
  return parse_float() != 0;
}

Value Parser::parse_rvalue() {
  const Token& t = peek();
  if (starts_string()) return Value{parse_string()};
  if (t.kind == Token::Kind::identifier) {
    const Token word = t;
    if (const Value* v = lookup(word.text);
        v && (std::holds_alternative<FunctionPtr>(v->data) ||
              std::holds_alternative<std::shared_ptr<const Spline>>(v->data))) {
      // A function or spline name not followed by `(` is the function itself (a macro argument, `#declare G =
      // F`); with `(` it is a call inside a float expression.
      const Frame& f = frames_.back();
      if (f.pos + 1 >= f.tokens->size() || !(*f.tokens)[f.pos + 1].is_symbol("(")) {
        Value copy = *v;
        raw_next();
        return copy;
      }
    } else if (v && !std::holds_alternative<Numeric>(v->data)) {
      Value copy = *v;
      raw_next();
      return copy;
    }
    if (word.text == "function") {
      raw_next();
      return Value{parse_function_block()};
    }
    if (word.text == "pigment") {
      raw_next();
      return Value{parse_pigment_block(nullptr)};
    }
    if (word.text == "color_map" || word.text == "colour_map") {
      raw_next();
      return Value{parse_color_map()};
    }
    if (word.text == "pigment_map") {
      raw_next();
      return Value{parse_pigment_map()};
    }
    if (word.text == "normal") {
      raw_next();
      return Value{parse_normal_block()};
    }
    if (word.text == "finish") {
      raw_next();
      return Value{parse_finish_block(material::Finish{})};
    }
    if (word.text == "texture") {
      raw_next();
      return Value{parse_layered_textures()};
    }
    if (word.text == "spline") {
      raw_next();
      return Value{parse_spline_block()};
    }
    if (word.text == "array") {
      raw_next();
      return Value{parse_array()};
    }
    if (word.text == "material") {
      raw_next();
      return Value{parse_material_block()};
    }
    if (word.text == "interior") {
      raw_next();
      return Value{parse_interior_block()};
    }
    if (word.text == "transform") {
      raw_next();
      return Value{parse_transform_block()};
    }
    if (word.text == "media" || word.text == "density" || word.text == "fog" || word.text == "sky_sphere") {
      raw_next();
      return parse_atmospheric_value(word);
    }
    if (word.text == "camera") {
      raw_next();
      return Value{parse_camera(scene::CameraSpec{})};
    }
    if (auto object = parse_object_if_any()) return Value{std::move(*object)};
  }
  return Value{parse_numeric()};
}

Numeric Parser::parse_numeric() {
  return parse_ternary();
}

Numeric Parser::parse_ternary() {
  Numeric c = parse_or();
  if (!peek_after_value().is_symbol("?")) return c;
  raw_next();
  const bool saved = in_vector_;
  in_vector_ = false;
  const Numeric a = parse_ternary();
  expect(":", "the ?: operator");
  const Numeric b = parse_ternary();
  in_vector_ = saved;
  return c.x() != 0 ? a : b;
}

Numeric Parser::parse_or() {
  Numeric a = parse_and();
  while (peek_after_value().is_symbol("|")) {
    raw_next();
    const Numeric b = parse_and();
    a = Numeric::of((a.x() != 0 || b.x() != 0) ? 1 : 0);
  }
  return a;
}

Numeric Parser::parse_and() {
  Numeric a = parse_comparison();
  while (peek_after_value().is_symbol("&")) {
    raw_next();
    const Numeric b = parse_comparison();
    a = Numeric::of((a.x() != 0 && b.x() != 0) ? 1 : 0);
  }
  return a;
}

Numeric Parser::parse_comparison() {
  // Strings compare too (POV-Ray's Parse_Rel_String_Term): `#if (Name != "")`, by character codes.
  if (starts_string()) {
    const std::string left = parse_string();
    const Token op = raw_next();
    const std::string right = parse_string();
    const int c = left.compare(right);
    bool r = false;
    if (op.is_symbol("<"))
      r = c < 0;
    else if (op.is_symbol("<="))
      r = c <= 0;
    else if (op.is_symbol("="))
      r = c == 0;
    else if (op.is_symbol("!="))
      r = c != 0;
    else if (op.is_symbol(">"))
      r = c > 0;
    else if (op.is_symbol(">="))
      r = c >= 0;
    else
      fail(op.where, "expected a comparison after a string, found '" + op.text + "'");
    return Numeric::of(r ? 1 : 0);
  }
  Numeric a = parse_additive();
  for (;;) {
    const Token& t = peek_after_value();
    if (t.kind != Token::Kind::symbol) return a;
    const std::string op = t.text;
    // Inside `< ... >` a bare `>` closes the vector (POV-Ray needs parentheses for comparisons there).
    if (op == "<" || op == "<=" || op == "=" || op == "!=" || ((op == ">" || op == ">=") && !in_vector_)) {
      raw_next();
      const Numeric b = parse_additive();
      const double x = a.x(), y = b.x();
      bool r = false;
      if (op == "<")
        r = x < y;
      else if (op == "<=")
        r = x <= y;
      else if (op == "=")
        r = x == y;
      else if (op == "!=")
        r = x != y;
      else if (op == ">")
        r = x > y;
      else
        r = x >= y;
      a = Numeric::of(r ? 1 : 0);
    } else {
      return a;
    }
  }
}

Numeric Parser::parse_additive() {
  Numeric a = parse_multiplicative();
  for (;;) {
    const Token& t = peek_after_value();
    if (t.is_symbol("+")) {
      raw_next();
      a = combine(a, parse_multiplicative(), [](double p, double q) { return p + q; });
    } else if (t.is_symbol("-")) {
      raw_next();
      a = combine(a, parse_multiplicative(), [](double p, double q) { return p - q; });
    } else {
      return a;
    }
  }
}

Numeric Parser::parse_multiplicative() {
  Numeric a = parse_unary();
  for (;;) {
    const Token& t = peek_after_value();
    if (t.is_symbol("*")) {
      raw_next();
      a = combine(a, parse_unary(), [](double p, double q) { return p * q; });
    } else if (t.is_symbol("/")) {
      const scene::SourceLocation where = t.where;
      raw_next();
      const Numeric b = parse_unary();
      for (int i = 0; i < std::max(a.size, b.size); ++i)
        if (widen(b, std::max(a.size, b.size)).v[static_cast<size_t>(i)] == 0)
          fail(where, "division by zero");
      a = combine(a, b, [](double p, double q) { return p / q; });
    } else {
      return a;
    }
  }
}

Numeric Parser::parse_unary() {
  const Token& t = peek();
  const NestingGuard guard(*this, t.where);
  if (t.is_symbol("-")) {
    raw_next();
    Numeric a = parse_unary();
    for (double& c : a.v) c = -c;
    return a;
  }
  if (t.is_symbol("+")) {
    raw_next();
    return parse_unary();
  }
  if (t.is_symbol("!")) {
    raw_next();
    return Numeric::of(parse_unary().x() == 0 ? 1 : 0);
  }
  return parse_postfix();
}

Numeric Parser::parse_postfix() {
  Numeric a = parse_primary();
  while (peek_after_value().is_symbol(".")) {
    const Token dot = raw_next();
    const Token field = raw_next();
    static const std::pair<const char*, int> fields[] = {
        {"x", 0},     {"y", 1},    {"z", 2},      {"t", 3},        {"u", 0},     {"v", 1},    {"red", 0},
        {"green", 1}, {"blue", 2}, {"filter", 3}, {"transmit", 4}, {"gray", -1}, {"grey", -1}};
    int index = -2;
    for (const auto& [n, i] : fields)
      if (field.kind == Token::Kind::identifier && field.text == n) index = i;
    if (index == -2) fail(field.where, "unknown component '." + field.text + "'");
    if (a.size == 1) fail(dot.where, "'." + field.text + "' applied to a float");
    if (index == -1) {
      a = Numeric::of(math::Color(a.v[0], a.v[1], a.v[2]).grey());
      continue;
    }
    const int size = a.color ? 5 : a.size;
    if (index >= size) fail(field.where, "'." + field.text + "' needs more components than this value has");
    a = Numeric::of(a.v[static_cast<size_t>(index)]);
  }
  return a;
}

Numeric Parser::parse_primary() {
  const Token t = peek();
  if (t.kind == Token::Kind::number) {
    raw_next();
    return Numeric::of(t.number);
  }
  if (t.is_symbol("(")) {
    raw_next();
    const bool saved = in_vector_;
    in_vector_ = false;
    Numeric a = parse_numeric();
    in_vector_ = saved;
    expect(")", "parenthesised expression");
    return a;
  }
  if (t.is_symbol("<")) {
    raw_next();
    const bool saved = in_vector_;
    in_vector_ = true;
    Numeric r;
    r.size = 0;
    for (;;) {
      const scene::SourceLocation where = peek().where;
      const Numeric c = parse_numeric();
      if (c.size != 1) fail(where, "vector components must be floats");
      if (r.size == 5) fail(where, "a vector has at most 5 components");
      r.v[static_cast<size_t>(r.size++)] = c.x();
      if (accept(">")) break;
      // POV-Ray's Parse_Comma: `<A B C>` is a vector too, and a comma may end it (`<1, 2, 3,>`).
      if (accept(",") && accept(">")) break;
    }
    in_vector_ = saved;
    if (r.size < 2) fail(t.where, "a vector needs at least 2 components");
    return r;
  }
  if (t.kind == Token::Kind::string) fail(t.where, "expected a number, found a string");
  if (t.kind != Token::Kind::identifier) {
    fail(t.where, t.kind == Token::Kind::end ? "unexpected end of file in an expression"
                                             : "expected an expression, found '" + t.text + "'");
  }
  const std::string& w = t.text;
  if (const Value* v = lookup(w)) {
    if (const auto* n = std::get_if<Numeric>(&v->data)) {
      raw_next();
      return *n;
    }
    if (const auto* f = std::get_if<FunctionPtr>(&v->data)) {
      const FunctionPtr callee = *f;  // the call may run macros that change the symbol table
      raw_next();
      return call_function(t, *callee);
    }
    if (const auto* s = std::get_if<std::shared_ptr<const Spline>>(&v->data)) {
      const auto spline = *s;
      raw_next();
      return call_spline(t, *spline);
    }
    fail(t.where, "expected a float, vector or color, but '" + w + "' is a " + v->type_name());
  }
  const auto constant = [&](double value) {
    raw_next();
    return Numeric::of(value);
  };
  const auto axis = [&](double a, double b, double c) {
    raw_next();
    return Numeric{{a, b, c, 0, 0}, 3, false};
  };
  if (w == "x") return axis(1, 0, 0);
  if (w == "y") return axis(0, 1, 0);
  if (w == "z") return axis(0, 0, 1);
  if (w == "t") {
    raw_next();
    return Numeric{{0, 0, 0, 1, 0}, 4, false};
  }
  if (w == "u") {
    raw_next();
    return Numeric{{1, 0, 0, 0, 0}, 2, false};
  }
  if (w == "v") {
    raw_next();
    return Numeric{{0, 1, 0, 0, 0}, 2, false};
  }
  if (const std::optional<double> c = builtin_constant(w)) return constant(*c);
  if (w == "rgb" || w == "rgbf" || w == "rgbt" || w == "rgbft" || w == "red" || w == "green" || w == "blue" ||
      w == "filter" || w == "transmit" || w == "color")
    return parse_color_keywords();
  if (w == "defined") {
    raw_next();
    expect("(", "defined()");
    const Token name = raw_next();
    expect(")", "defined()");
    return Numeric::of(lookup(name.text) || user_files_.count(name.text) ? 1 : 0);
  }
  raw_next();
  return parse_function(t);
}

std::optional<double> Parser::builtin_constant(const std::string& w) const {
  if (w == "pi") return math::kPi;
  if (w == "tau") return 2 * math::kPi;
  if (w == "true" || w == "on" || w == "yes") return 1.0;
  if (w == "false" || w == "off" || w == "no") return 0.0;
  if (w == "version") return version_;
  if (w == "clock") return options_.clock;
  if (w == "clock_delta") return options_.clock_delta();
  if (w == "clock_on") return options_.clock_on ? 1.0 : 0.0;
  if (w == "initial_clock") return options_.initial_clock;
  if (w == "final_clock") return options_.final_clock;
  if (w == "initial_frame") return static_cast<double>(options_.initial_frame);
  if (w == "final_frame") return static_cast<double>(options_.final_frame);
  if (w == "frame_number") return static_cast<double>(options_.frame_number);
  if (w == "image_width") return static_cast<double>(options_.image_width);
  if (w == "image_height") return static_cast<double>(options_.image_height);
  return std::nullopt;
}

Numeric Parser::parse_color_keywords() {
  // POV-Ray's colour syntax: `color` is optional noise; rgb/rgbf/rgbt/rgbft take an expression and the
  // single-channel keywords a float, each changing only its channels (reference, "Specifying Colors").
  Numeric c{{0, 0, 0, 0, 0}, 5, true};
  bool any = false;
  for (;;) {
    // After a complete colour only closing directives may run, so `#declare C = rgb 1` stores first.
    const Token& t = any ? peek_after_value() : peek();
    const scene::SourceLocation where = t.where;
    const std::string w = t.kind == Token::Kind::identifier ? t.text : std::string();
    if (w == "color") {
      if (any)
        return c;  // a second `color` starts the next colour (old colour_map `[a b color c1 color c2]`)
      raw_next();
      continue;
    }
    int channels = 0;
    if (w == "rgb")
      channels = 3;
    else if (w == "rgbf" || w == "rgbt")
      channels = 4;
    else if (w == "rgbft")
      channels = 5;
    // An rgb* keyword once the colour has begun starts the next colour, as in POV-Ray's Parse_Colour:
    // `checker rgb 1 rgb 0.5` is two colours.
    if (channels > 0 && any) return c;
    if (channels > 0) {
      raw_next();
      const Numeric e = parse_numeric();
      if (e.size > 1 && !e.color && e.size < channels)
        fail(where,
             w + " needs " + std::to_string(channels) + " components, found " + std::to_string(e.size));
      const Numeric full = widen(e, 5);
      c.v[0] = full.v[0];
      c.v[1] = full.v[1];
      c.v[2] = full.v[2];
      if (w == "rgbf" || w == "rgbft") c.v[3] = full.v[3];
      if (w == "rgbt") c.v[4] = full.v[3];
      if (w == "rgbft") c.v[4] = full.v[4];
      any = true;
      continue;
    }
    int channel = -1;
    if (w == "red")
      channel = 0;
    else if (w == "green")
      channel = 1;
    else if (w == "blue")
      channel = 2;
    else if (w == "filter")
      channel = 3;
    else if (w == "transmit")
      channel = 4;
    if (channel >= 0) {
      raw_next();
      c.v[static_cast<size_t>(channel)] = parse_float();
      any = true;
      continue;
    }
    if (!any && starts_numeric()) {
      // `color Red * 0.5`, `color <1, 0, 0>`: an expression promoted to a colour.
      c = widen(parse_numeric(), 5);
      c.color = true;
      c.size = 5;
      any = true;
      continue;
    }
    if (!any) fail(where, "expected a color");
    return c;
  }
}

Numeric Parser::parse_function(const Token& name) {
  const std::string& f = name.text;
  static const char* const functions[] = {
      "abs",  "min",    "max",     "pow",          "sqrt",    "sqr",        "exp",
      "log",  "ln",     "sin",     "cos",          "tan",     "sinh",       "cosh",
      "tanh", "asin",   "acos",    "atan",         "atan2",   "floor",      "ceil",
      "int",  "mod",    "div",     "radians",      "degrees", "vlength",    "vnormalize",
      "vdot", "vcross", "vrotate", "vaxis_rotate", "select",  "vturbulence"};
  if (f == "dimensions" || f == "dimension_size") return parse_array_function(name);
  if (f == "seed" || f == "rand") return parse_random_function(name);
  if (is_numeric_string_function(f)) return parse_string_query(name);
  if (f == "trace" || f == "min_extent" || f == "max_extent" || f == "inside")
    return parse_object_query(name);
  bool known = false;
  for (const char* k : functions) known = known || f == k;
  if (!known) fail(name.where, "unknown identifier '" + f + "'");
  expect("(", ("function " + f).c_str());
  std::vector<Numeric> args;
  std::vector<scene::SourceLocation> where;
  if (!peek().is_symbol(")")) {
    for (;;) {
      where.push_back(peek().where);
      args.push_back(parse_numeric());
      if (accept(")")) break;
      expect(",", ("arguments of " + f).c_str());
    }
  } else {
    raw_next();
  }
  const auto need = [&](size_t n) {
    if (args.size() != n)
      fail(name.where,
           f + " takes " + std::to_string(n) + " argument(s), found " + std::to_string(args.size()));
  };
  const auto a = [&](size_t i) { return args[i].x(); };
  const auto vec = [&](size_t i) { return widen(args[i], 3).vec3(); };
  const auto of_vec = [](const math::Vec3& p) { return Numeric{{p.x, p.y, p.z, 0, 0}, 3, false}; };
  const auto domain = [&](bool ok, const char* what) {
    if (!ok) fail(name.where, f + ": " + what);
  };
  if (f == "abs") return need(1), Numeric::of(std::fabs(a(0)));
  if (f == "min" || f == "max") {
    if (args.empty()) fail(name.where, f + " needs at least one argument");
    double r = a(0);
    for (size_t i = 1; i < args.size(); ++i) r = f == "min" ? std::min(r, a(i)) : std::max(r, a(i));
    return Numeric::of(r);
  }
  if (f == "pow") {
    need(2);
    domain(!(a(0) == 0 && a(1) < 0), "zero to a negative power");
    return Numeric::of(std::pow(a(0), a(1)));
  }
  if (f == "sqrt") return need(1), domain(a(0) >= 0, "negative argument"), Numeric::of(std::sqrt(a(0)));
  if (f == "sqr") return need(1), Numeric::of(a(0) * a(0));
  if (f == "exp") return need(1), Numeric::of(std::exp(a(0)));
  if (f == "log")
    return need(1), domain(a(0) > 0, "argument must be positive"), Numeric::of(std::log10(a(0)));
  if (f == "ln") return need(1), domain(a(0) > 0, "argument must be positive"), Numeric::of(std::log(a(0)));
  if (f == "sin") return need(1), Numeric::of(std::sin(a(0)));
  if (f == "cos") return need(1), Numeric::of(std::cos(a(0)));
  if (f == "tan") return need(1), Numeric::of(std::tan(a(0)));
  if (f == "sinh") return need(1), Numeric::of(std::sinh(a(0)));
  if (f == "cosh") return need(1), Numeric::of(std::cosh(a(0)));
  if (f == "tanh") return need(1), Numeric::of(std::tanh(a(0)));
  if (f == "asin")
    return need(1), domain(std::fabs(a(0)) <= 1, "argument outside [-1, 1]"), Numeric::of(std::asin(a(0)));
  if (f == "acos")
    return need(1), domain(std::fabs(a(0)) <= 1, "argument outside [-1, 1]"), Numeric::of(std::acos(a(0)));
  if (f == "atan") return need(1), Numeric::of(std::atan(a(0)));
  if (f == "atan2") return need(2), Numeric::of(std::atan2(a(0), a(1)));
  if (f == "floor") return need(1), Numeric::of(std::floor(a(0)));
  if (f == "ceil") return need(1), Numeric::of(std::ceil(a(0)));
  if (f == "int") return need(1), Numeric::of(std::trunc(a(0)));
  if (f == "mod") return need(2), domain(a(1) != 0, "division by zero"), Numeric::of(std::fmod(a(0), a(1)));
  if (f == "div") return need(2), domain(a(1) != 0, "division by zero"), Numeric::of(std::trunc(a(0) / a(1)));
  if (f == "radians") return need(1), Numeric::of(a(0) * math::kPi / 180);
  if (f == "degrees") return need(1), Numeric::of(a(0) * 180 / math::kPi);
  if (f == "vlength") return need(1), Numeric::of(length(vec(0)));
  if (f == "vnormalize") {
    need(1);
    domain(length(vec(0)) > 0, "zero-length vector");
    return of_vec(normalize(vec(0)));
  }
  if (f == "vdot") return need(2), Numeric::of(dot(vec(0), vec(1)));
  if (f == "vcross") return need(2), of_vec(cross(vec(0), vec(1)));
  if (f == "vrotate") return need(2), of_vec(math::Transform::rotate_xyz_degrees(vec(1)).vector(vec(0)));
  if (f == "vaxis_rotate") {
    need(3);
    domain(length(vec(1)) > 0, "zero-length axis");
    return of_vec(math::Transform::rotate_axis_degrees(normalize(vec(1)), a(2)).vector(vec(0)));
  }
  if (f == "vturbulence") {
    // vturbulence(Lambda, Omega, Octaves, V): the displacement a turbulence warp would apply at V.
    need(4);
    return of_vec(texture::vector_turbulence(
        vec(3), static_cast<int>(std::clamp(a(2) == a(2) ? a(2) : 1.0, 1.0, 10.0)), a(1), a(0)));
  }
  if (f == "select") {
    if (args.size() == 3) return a(0) < 0 ? args[1] : args[2];
    need(4);
    return a(0) < 0 ? args[1] : (a(0) == 0 ? args[2] : args[3]);
  }
  fail(name.where, "unknown identifier '" + f + "'");
}

}  // namespace snell::sdl
