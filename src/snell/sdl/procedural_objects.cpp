// Procedural surfaces: isosurface and superellipsoid (POV-Ray 3.7 reference, "Isosurface Object",
// "Superquadric Ellipsoid").
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "snell/geometry/box.hpp"
#include "snell/geometry/isosurface.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/sdl/shape_factory.hpp"

namespace snell::sdl {

namespace {

/// POV-Ray's warning after rendering when rays met steeper slopes than max_gradient (isosurface.cpp).
std::string gradient_warning(const std::string& where, const geometry::Isosurface& iso) {
  const double found = iso.gradient_overshoot();
  if (found <= 0) return {};
  char text[256];
  std::snprintf(
      text, sizeof text,
      "%s: warning: the maximum gradient found was %.3f, but max_gradient of the isosurface was set to "
      "%.3f; the isosurface may contain holes (raise max_gradient)",
      where.c_str(), found, iso.settings().max_gradient);
  return text;
}

}  // namespace

ParsedObject Parser::parse_isosurface(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "isosurface");
  geometry::IsosurfaceSettings s;
  s.container =
      std::make_shared<geometry::Box>(math::Vec3(-1), math::Vec3(1));  // POV-Ray's default container
  std::optional<std::array<double, 3>> evaluate;
  for (;;) {
    const Token t = peek();
    if (t.is_word("function")) {
      raw_next();
      s.function = parse_function_block();
      if (s.function->arity() != 3) fail(t.where, "an isosurface function takes x, y, z");
    } else if (t.is_word("contained_by")) {
      raw_next();
      expect("{", "contained_by");
      const Token shape = raw_next();
      if (shape.is_word("box")) {
        expect("{", "box");
        const math::Vec3 a = parse_vector();
        accept(",");
        s.container = std::make_shared<geometry::Box>(a, parse_vector());
      } else if (shape.is_word("sphere")) {
        expect("{", "sphere");
        const math::Vec3 c = parse_vector();
        accept(",");
        const double r = parse_float();
        if (!(r > 0)) fail(shape.where, "contained_by sphere needs a positive radius");
        s.container = std::make_shared<geometry::Sphere>(c, r);
      } else {
        fail(shape.where, "contained_by takes a box or a sphere");
      }
      expect("}", shape.text.c_str());
      expect("}", "contained_by");
    } else if (t.is_word("threshold")) {
      raw_next();
      s.threshold = parse_float();
    } else if (t.is_word("accuracy")) {
      raw_next();
      s.accuracy = parse_float();
      if (!(s.accuracy > 0)) fail(t.where, "accuracy must be positive");
    } else if (t.is_word("max_gradient")) {
      raw_next();
      s.max_gradient = parse_float();
      if (!(s.max_gradient > 0)) fail(t.where, "max_gradient must be positive");
    } else if (t.is_word("evaluate")) {
      raw_next();
      std::array<double, 3> p{};
      for (int i = 0; i < 3; ++i) {
        if (i > 0) accept(",");
        p[static_cast<size_t>(i)] = parse_float();
      }
      evaluate = p;
    } else if (t.is_word("open")) {
      raw_next();
      s.open = true;
    } else if (t.is_word("max_trace")) {
      raw_next();
      const double n = parse_float();
      if (!(n >= 1)) fail(t.where, "max_trace must be at least 1");
      s.max_trace = static_cast<int>(std::min(n, 1e6));
    } else if (t.is_word("all_intersections")) {
      raw_next();
      s.max_trace = std::numeric_limits<int>::max();
    } else if (t.is_word("polarity")) {
      fail(t.where, "isosurface polarity is not supported");
    } else {
      break;
    }
  }
  if (!s.function) fail(keyword.where, "isosurface needs a function { }");
  if (evaluate) {
    // P0 is the smallest gradient to assume, P1 the over-estimate factor (P2, the attenuation of
    // POV-Ray's adaptive estimate, has no role in a measured one).
    s.max_gradient = geometry::estimate_max_gradient(*s.function, s.container->bounds(), (*evaluate)[0],
                                                     std::max(1.0, (*evaluate)[1]));
  }
  try {
    auto iso = shapes::isosurface(std::move(s));
    const std::string where = keyword.where.to_string();
    scene_.render_notes.push_back([where, iso] { return gradient_warning(where, *iso); });
    o.shape = std::move(iso);
  } catch (const std::exception& e) {
    fail(keyword.where, e.what());
  }
  parse_object_modifiers(o);
  return o;
}

ParsedObject Parser::parse_superellipsoid(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "superellipsoid");
  const math::Vec3 en = parse_vector();
  try {
    o.shape = shapes::superellipsoid(en.x, en.y);
  } catch (const std::exception& e) {
    fail(keyword.where, e.what());
  }
  parse_object_modifiers(o);
  return o;
}

}  // namespace snell::sdl
