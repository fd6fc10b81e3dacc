// Procedural surfaces: isosurface, superellipsoid and bicubic_patch (POV-Ray 3.7 reference, "Isosurface
// Object", "Superquadric Ellipsoid", "Bicubic Patch").
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>

#include "snell/geometry/bicubic_patch.hpp"
#include "snell/geometry/box.hpp"
#include "snell/geometry/isosurface.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/sdl/shape_factory.hpp"

namespace snell::sdl {

namespace {

/// POV-Ray's warnings after rendering when the slopes met along rays disagree with max_gradient: steeper
/// (holes likely) or much gentler (slower than needed), with the thresholds of POV-Ray's isosurface.cpp.
std::string gradient_warning(const std::string& where, const geometry::Isosurface& iso) {
  const double found = iso.steepest_slope(), set = iso.settings().max_gradient;
  if (!(found > 1e-10)) return {};
  const double diff = set - found, ratio = set / found;
  const char* advice = nullptr;
  if ((ratio <= 0.9 && diff <= -0.5) || ((ratio <= 0.95 || diff <= -0.1) && set < 10))
    advice = "the isosurface may contain holes; raise max_gradient";
  else if (diff >= 10 || (ratio >= 1.1 && diff >= 0.5))
    advice = "lower max_gradient for a faster render";
  if (!advice) return {};
  char text[256];
  std::snprintf(text, sizeof text,
                "%s: warning: the maximum gradient found was %.3f, but max_gradient was set to %.3f; %s",
                where.c_str(), found, set, advice);
  return text;
}

}  // namespace

ParsedObject Parser::finish_shape(ParsedObject o, const Token& keyword,
                                  const std::function<std::shared_ptr<const geometry::Shape>()>& make) {
  try {
    o.shape = make();  // geometry only: the tokens were read before
  } catch (const std::exception& e) {
    fail(keyword.where, e.what());
  }
  parse_object_modifiers(o);
  return o;
}

ParsedObject Parser::parse_isosurface(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "isosurface");
  geometry::IsosurfaceSettings s;
  s.count_work = std::getenv("SNELL_ISOSURFACE_STATS") != nullptr;  // reported after rendering, below
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
      s.container = parse_contained_by();
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
  return finish_shape(std::move(o), keyword, [&] {
    auto iso = shapes::isosurface(std::move(s));
    const std::string where = keyword.where.to_string();
    // With `evaluate` the gradient was measured, so there is nothing to advise (as in POV-Ray).
    if (!evaluate) scene_.render_notes.push_back([where, iso] { return gradient_warning(where, *iso); });
    // SNELL_ISOSURFACE_STATS=1 reports how often each isosurface evaluated its function
    // (docs/performance.md).
    if (iso->settings().count_work)
      scene_.render_notes.push_back([where, iso] {
        return where + ": note: " + std::to_string(iso->evaluations()) + " function evaluations on " +
               std::to_string(iso->rays()) + " rays, " + std::to_string(iso->hits()) + " surface points";
      });
    return iso;
  });
}

ParsedObject Parser::parse_superellipsoid(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "superellipsoid");
  const math::Vec3 en = parse_vector();
  return finish_shape(std::move(o), keyword, [&] { return shapes::superellipsoid(en.x, en.y); });
}

ParsedObject Parser::parse_bicubic_patch(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "bicubic_patch");
  // POV-Ray's defaults when u_steps / v_steps are not given (parser, Parse_Bicubic_Patch).
  int u_steps = 3, v_steps = 3;
  for (;;) {
    const Token t = peek();
    if (t.is_word("type") || t.is_word("flatness")) {
      raw_next();
      parse_float();  // snell always tessellates uniformly, as type 1 does
    } else if (t.is_word("u_steps") || t.is_word("v_steps")) {
      raw_next();
      const double steps = parse_float();
      if (!(steps >= 0 && steps <= 8)) fail(t.where, t.text + " must be between 0 and 8");
      (t.text == "u_steps" ? u_steps : v_steps) = static_cast<int>(steps);
    } else if (t.is_word("accuracy")) {
      raw_next();
      parse_float();
    } else {
      break;
    }
  }
  accept(",");
  geometry::BezierPoints points;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) accept(",");
    points[i] = parse_vector();
  }
  if (peek().is_word("uv_vectors")) {
    raw_next();
    for (int i = 0; i < 4; ++i) parse_vector();  // corner uv; the unit square is assumed
  }
  return finish_shape(std::move(o), keyword, [&] {
    return shapes::mesh(geometry::tessellate_bicubic_patch(points, u_steps, v_steps));
  });
}

ParsedObject Parser::parse_julia_fractal(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "julia_fractal");
  const auto vector4 = [&] {
    const Numeric n = parse_numeric();
    return geometry::Vec4{n.v[0], n.v[1], n.v[2], n.v[3]};
  };
  geometry::JuliaFractal::Settings s;
  s.c = vector4();
  for (;;) {
    const Token t = peek();
    if (t.is_word("quaternion") || t.is_word("hypercomplex")) {
      raw_next();
      s.algebra = t.text == "quaternion" ? geometry::JuliaFractal::Algebra::quaternion
                                         : geometry::JuliaFractal::Algebra::hypercomplex;
    } else if (t.is_word("sqr") || t.is_word("cube")) {
      raw_next();
      s.power = t.text == "sqr" ? 2 : 3;
    } else if (t.is_word("exp") || t.is_word("reciprocal") || t.is_word("sin") || t.is_word("asin") ||
               t.is_word("sinh") || t.is_word("asinh") || t.is_word("cos") || t.is_word("acos") ||
               t.is_word("cosh") || t.is_word("acosh") || t.is_word("tan") || t.is_word("atan") ||
               t.is_word("tanh") || t.is_word("atanh") || t.is_word("ln") || t.is_word("pwr")) {
      fail(t.where, "julia_fractal function '" + t.text + "' is not supported (sqr and cube are)");
    } else if (t.is_word("max_iteration")) {
      raw_next();
      const double n = parse_float();
      if (!(n >= 1 && n <= 10000)) fail(t.where, "max_iteration must be between 1 and 10000");
      s.max_iteration = static_cast<int>(n);
    } else if (t.is_word("precision")) {
      raw_next();
      s.precision = parse_float();
      if (!(s.precision > 0)) fail(t.where, "precision must be positive");
    } else if (t.is_word("slice")) {
      raw_next();
      s.slice_normal = vector4();
      accept(",");
      s.slice_distance = parse_float();
    } else {
      break;
    }
  }
  return finish_shape(std::move(o), keyword, [&] { return shapes::julia_fractal(s); });
}

}  // namespace snell::sdl
