// ovus, lemon and parametric (POV-Ray 3.7 reference, "Ovus", "Parametric"; POV-Ray 3.8 reference,
// "Lemon"), and the `contained_by { box | sphere }` block they share with isosurface.
#include <cmath>

#include "snell/geometry/box.hpp"
#include "snell/geometry/lemon.hpp"
#include "snell/geometry/ovus.hpp"
#include "snell/geometry/parametric.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/sdl/shape_factory.hpp"

namespace snell::sdl {

std::shared_ptr<const geometry::Shape> Parser::parse_contained_by() {
  expect("{", "contained_by");
  const Token shape = raw_next();
  std::shared_ptr<const geometry::Shape> container;
  if (shape.is_word("box")) {
    expect("{", "box");
    const math::Vec3 a = parse_vector();
    accept(",");
    container = std::make_shared<geometry::Box>(a, parse_vector());
  } else if (shape.is_word("sphere")) {
    expect("{", "sphere");
    const math::Vec3 c = parse_vector();
    accept(",");
    const double r = parse_float();
    if (!(r > 0)) fail(shape.where, "contained_by sphere needs a positive radius");
    container = std::make_shared<geometry::Sphere>(c, r);
  } else {
    fail(shape.where, "contained_by takes a box or a sphere");
  }
  expect("}", shape.text.c_str());
  expect("}", "contained_by");
  return container;
}

ParsedObject Parser::parse_ovus(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "ovus");
  const double bottom = parse_float();
  accept(",");
  const double top = parse_float();
  double connecting = 0, distance = 0;  // 0: POV-Ray's defaults
  for (;;) {
    const Token t = peek();
    if (t.is_word("radius") || t.is_word("distance") || t.is_word("precision")) {
      raw_next();
      const double value = parse_float();
      if (!(value > 0)) fail(t.where, t.text + " must be positive");
      if (t.text == "radius") connecting = value;
      if (t.text == "distance") distance = value;  // `precision` tunes POV-Ray's root finder only
    } else if (t.is_word("sturm")) {
      skip_sturm();
    } else {
      break;
    }
  }
  return finish_shape(std::move(o), keyword, [&] {
    auto ovus = std::make_shared<geometry::Ovus>(bottom, top, connecting, distance);
    if (ovus->is_sphere()) warn(keyword.where, "the ovus is reduced to a sphere; consider a sphere instead");
    return ovus;
  });
}

ParsedObject Parser::parse_lemon(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "lemon");
  const math::Vec3 base = parse_vector();
  accept(",");
  const double base_radius = parse_float();
  accept(",");
  const math::Vec3 cap = parse_vector();
  accept(",");
  const double cap_radius = parse_float();
  accept(",");
  const double inner_radius = parse_float();
  bool open = false;
  if (peek().is_word("open")) {
    raw_next();
    open = true;
  }
  skip_sturm();
  return finish_shape(std::move(o), keyword, [&] {
    auto lemon = std::make_shared<geometry::Lemon>(base, base_radius, cap, cap_radius, inner_radius, open);
    if (lemon->inner_radius() > inner_radius * (1 + 1e-9))
      warn(keyword.where, "the lemon's inner radius is too small; it was raised to the smallest allowed, " +
                              std::to_string(lemon->inner_radius()));
    return lemon;
  });
}

ParsedObject Parser::parse_parametric(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "parametric");
  geometry::ParametricSettings s;
  s.container = std::make_shared<geometry::Box>(math::Vec3(-1), math::Vec3(1));  // POV-Ray's default
  for (auto& f : s.functions) {
    const Token t = peek();
    if (!t.is_word("function")) fail(t.where, "parametric needs three functions: function { x(u,v) } ...");
    raw_next();
    f = parse_function_block();
    if (f->arity() != 3) fail(t.where, "a parametric function takes u, v");
  }
  const math::Vec3 lo = parse_vector();
  accept(",");
  const math::Vec3 hi = parse_vector();
  s.uv_min = {lo.x, lo.y};
  s.uv_max = {hi.x, hi.y};
  for (;;) {
    const Token t = peek();
    if (t.is_word("contained_by")) {
      raw_next();
      s.container = parse_contained_by();
    } else if (t.is_word("accuracy")) {
      raw_next();
      s.accuracy = parse_float();
      if (!(s.accuracy > 0)) fail(t.where, "accuracy must be positive");
    } else if (t.is_word("max_gradient")) {
      raw_next();
      if (!(parse_float() > 0)) fail(t.where, "max_gradient must be positive");
    } else if (t.is_word("precompute")) {
      // `precompute depth, [x], [y], [z]`: POV-Ray caches interval bounds; the lattice makes it moot.
      raw_next();
      const double depth = parse_float();
      if (!(depth >= 0 && depth <= 20)) fail(t.where, "precompute depth must be between 0 and 20");
      for (const char* axis : {"x", "y", "z"}) {
        accept(",");
        if (peek().is_word(axis)) raw_next();
      }
    } else {
      break;
    }
  }
  return finish_shape(std::move(o), keyword,
                      [&] { return std::make_shared<geometry::Parametric>(std::move(s)); });
}

}  // namespace snell::sdl
