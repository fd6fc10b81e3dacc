// Parsing `spline { ... }` and calling a spline identifier (POV-Ray 3.7 reference, "Splines").
#include <algorithm>

#include "snell/sdl/parser.hpp"

namespace snell::sdl {

namespace {

std::optional<Spline::Kind> spline_kind(const Token& t) {
  if (t.is_word("linear_spline")) return Spline::Kind::linear;
  if (t.is_word("quadratic_spline")) return Spline::Kind::quadratic;
  if (t.is_word("cubic_spline")) return Spline::Kind::cubic;
  if (t.is_word("natural_spline")) return Spline::Kind::natural;
  return std::nullopt;
}

}  // namespace

std::shared_ptr<const Spline> Parser::parse_spline_block() {
  expect("{", "spline");
  auto spline = std::make_shared<Spline>();
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      break;
    }
    if (const auto kind = spline_kind(t)) {
      raw_next();
      spline->kind = *kind;
      continue;
    }
    if (auto declared = take_declared<std::shared_ptr<const Spline>>()) {
      *spline = **declared;
      continue;
    }
    const double at = parse_float();
    accept(",");
    const scene::SourceLocation where = peek().where;
    const Numeric value = parse_argument_numeric();
    // A float value is promoted to the 2-vector <v, v>, as POV-Ray does: `Spline(t).x` reads it.
    const int size = value.color ? 5 : std::max(value.size, 2);
    if (!spline->points.empty() && size != spline->size && value.size != 1)
      fail(where, "spline values must all have " + std::to_string(spline->size) + " components");
    if (spline->points.empty()) spline->size = size;
    Numeric wide = value;  // Numeric::of fills every component, so a float reads as <v, v, ...>
    spline->add(at, wide.v);
    accept(",");
  }
  if (spline->points.empty()) fail(peek().where, "a spline needs at least one point");
  if (spline->kind == Spline::Kind::quadratic && spline->points.size() < 3)
    warn(peek().where, "a quadratic spline needs 3 points; evaluated as linear");
  return spline;
}

Numeric Parser::call_spline(const Token& name, const Spline& spline) {
  expect("(", ("call of spline " + name.text).c_str());
  const double t = parse_directive_float();
  Spline::Kind kind = spline.kind;
  if (accept(",")) {
    const Token k = next();
    const auto asked = spline_kind(k);
    if (!asked) fail(k.where, "expected linear_spline, quadratic_spline, cubic_spline or natural_spline");
    kind = *asked;
  }
  expect(")", ("call of spline " + name.text).c_str());
  Numeric r;
  r.v = spline.evaluate(t, kind);
  r.size = std::min(spline.size, 5);
  r.color = spline.size == 5;
  return r;
}

}  // namespace snell::sdl
