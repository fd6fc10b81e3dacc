// Shapes built from coefficient lists and point lists: poly, cubic, quartic, polygon, prism, lathe, sor
// and text (POV-Ray 3.7 reference, "Finite Solid Primitives", "Finite Patch Primitives", "Poly, Cubic
// and Quartic"). Called from parse_shape, which parses the opening brace before and the modifiers after.
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "snell/geometry/poly.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/sdl/shape_factory.hpp"

namespace snell::sdl {

namespace {

// POV-Ray's spline keywords of prism and lathe.
std::optional<geometry::SplineKind> spline_keyword(const Token& t) {
  if (t.is_word("linear_spline")) return geometry::SplineKind::linear;
  if (t.is_word("quadratic_spline")) return geometry::SplineKind::quadratic;
  if (t.is_word("cubic_spline")) return geometry::SplineKind::cubic;
  if (t.is_word("bezier_spline")) return geometry::SplineKind::bezier;
  return std::nullopt;
}

// Fewest points each spline needs, as POV-Ray's parser demands them for prisms and lathes.
int fewest_points(geometry::SplineKind kind, bool prism) {
  switch (kind) {
    case geometry::SplineKind::linear:
      return prism ? 3 : 2;
    case geometry::SplineKind::quadratic:
      return prism ? 5 : 3;
    case geometry::SplineKind::cubic:
      return prism ? 6 : 4;
    case geometry::SplineKind::bezier:
      return 4;
  }
  return 0;
}

// A count as written ("12", "1e+09"), not std::to_string's six decimals.
std::string shortest(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

constexpr int kMostPoints = 1 << 20;  // bounds memory for a hostile point count

}  // namespace

int Parser::parse_point_count(const char* what, int fewest) {
  const scene::SourceLocation where = peek().where;
  const double n = parse_float();
  if (!(n >= fewest) || n > kMostPoints)
    fail(where, std::string(what) + " needs between " + std::to_string(fewest) + " and " +
                    std::to_string(kMostPoints) + " points, not " + shortest(n));
  accept(",");
  return static_cast<int>(n);
}

std::vector<math::Vec2> Parser::parse_points_2d(int count) {
  std::vector<math::Vec2> points;
  for (int i = 0; i < count; ++i) {
    const math::Vec3 p = parse_vector();
    points.push_back({p.x, p.y});
    accept(",");  // POV-Ray allows a trailing comma
  }
  return points;
}

void Parser::skip_sturm() {
  if (peek().is_word("sturm")) {
    raw_next();
    parse_bool_optional(true);
  }
}

std::shared_ptr<const geometry::Shape> Parser::parse_outline_shape(const Token& keyword) {
  const std::string& w = keyword.text;
  if (w == "poly" || w == "cubic" || w == "quartic") {
    int order = w == "cubic" ? 3 : 4;
    if (w == "poly") {
      const scene::SourceLocation where = peek().where;
      const double n = parse_float();
      if (!(n >= 2 && n <= geometry::max_poly_order()))
        fail(where, "poly order must be between 2 and " + std::to_string(geometry::max_poly_order()));
      order = static_cast<int>(n);
      accept(",");
    }
    expect("<", w.c_str());
    std::vector<double> coefficients;
    while (!accept(">")) {
      if (static_cast<int>(coefficients.size()) > geometry::poly_coefficient_count(order))
        fail(peek().where, "too many coefficients in " + w);
      coefficients.push_back(parse_float());
      accept(",");
    }
    skip_sturm();
    return shapes::poly(order, coefficients);
  }
  if (w == "polygon") {
    const int n = parse_point_count("polygon", 3);
    std::vector<math::Vec3> points;
    for (int i = 0; i < n; ++i) {
      points.push_back(parse_vector());
      accept(",");
    }
    return shapes::polygon(points);
  }
  if (w == "prism") {
    auto kind = geometry::SplineKind::linear;
    auto sweep = geometry::Sweep::linear;
    for (;;) {
      if (auto k = spline_keyword(peek())) {
        kind = *k;
      } else if (peek().is_word("linear_sweep") || peek().is_word("conic_sweep")) {
        sweep = peek().is_word("conic_sweep") ? geometry::Sweep::conic : geometry::Sweep::linear;
      } else {
        break;
      }
      raw_next();
    }
    const double h1 = parse_float();
    accept(",");
    const double h2 = parse_float();
    accept(",");
    const scene::SourceLocation where = peek().where;
    const int n = parse_point_count("prism", fewest_points(kind, true));
    if (kind == geometry::SplineKind::bezier && n % 4 != 0)
      fail(where, "prism with bezier_spline needs four points per segment");
    std::vector<math::Vec2> points = parse_points_2d(n);
    bool open = false;
    if (peek().is_word("open")) {
      raw_next();
      open = true;
    }
    skip_sturm();
    math::Vec2 first_of_last;
    if (!geometry::outline_closed(kind, points, first_of_last)) {
      if (kind != geometry::SplineKind::linear) fail(keyword.where, "prism outline is not closed");
      warn(keyword.where, "linear prism not closed; closing it");
      points.push_back(first_of_last);
    }
    return shapes::prism(kind, points, h1, h2, sweep, open);
  }
  if (w == "lathe") {
    auto kind = geometry::SplineKind::linear;
    while (auto k = spline_keyword(peek())) {
      kind = *k;
      raw_next();
    }
    const scene::SourceLocation where = peek().where;
    const int n = parse_point_count("lathe", fewest_points(kind, false));
    if (kind == geometry::SplineKind::bezier && n % 4 != 0)
      fail(where, "lathe with bezier_spline needs four points per segment");
    const std::vector<math::Vec2> points = parse_points_2d(n);
    skip_sturm();
    return shapes::lathe(kind, points);
  }
  if (w == "sor") {
    const int n = parse_point_count("sor", 4);
    const std::vector<math::Vec2> points = parse_points_2d(n);
    bool open = false;
    for (;;) {
      if (peek().is_word("open")) {
        raw_next();
        open = true;
      } else if (peek().is_word("sturm")) {
        skip_sturm();
      } else {
        break;
      }
    }
    return shapes::sor(points, open);
  }
  if (w == "sphere_sweep") {
    // sphere_sweep { spline N, <centre>, radius ... [tolerance t] }
    const Token spline_word = peek();
    geometry::SweepSpline spline = geometry::SweepSpline::linear;
    if (spline_word.is_word("b_spline")) {
      spline = geometry::SweepSpline::b_spline;
    } else if (spline_word.is_word("cubic_spline")) {
      spline = geometry::SweepSpline::cubic;
    } else if (!spline_word.is_word("linear_spline")) {
      fail(spline_word.where, "expected linear_spline, b_spline or cubic_spline in sphere_sweep");
    }
    raw_next();
    const int n = parse_point_count("sphere_sweep", spline == geometry::SweepSpline::linear ? 2 : 4);
    std::vector<geometry::SweepSphere> spheres;
    for (int i = 0; i < n; ++i) {
      geometry::SweepSphere s;
      s.center = parse_vector();
      accept(",");
      s.radius = parse_float();
      accept(",");
      spheres.push_back(s);
    }
    if (peek().is_word("tolerance")) {
      raw_next();
      parse_float();  // the curved envelope is approximated by fixed steps instead
    }
    return shapes::sphere_sweep(spline, spheres);
  }
  // text { ttf "font.ttf" "string" thickness, offset }
  // or text { internal N "string" ... }: POV-Ray's built-in fonts are the four TrueType files that
  // povray-includes also ships (1 timrom, 2 cyrvetic, 3 crystal, any other number povlogo).
  const Token font_kind = peek();
  if (!font_kind.is_word("ttf") && !font_kind.is_word("internal"))
    fail(font_kind.where, "expected 'ttf' or 'internal' in text");
  raw_next();
  const scene::SourceLocation font_where = peek().where;
  std::string font;
  if (font_kind.is_word("internal")) {
    const int id = static_cast<int>(parse_float());
    font = id == 1 ? "timrom.ttf" : id == 2 ? "cyrvetic.ttf" : id == 3 ? "crystal.ttf" : "povlogo.ttf";
  } else {
    font = parse_string();
  }
  accept(",");
  const std::string text = parse_string();
  accept(",");
  const double thickness = parse_float();
  accept(",");
  const math::Vec3 offset = parse_vector();
  // POV-Ray adds ".ttf" to a name without it.
  std::vector<std::filesystem::path> candidates;
  for (const std::string& name : {font, font + ".ttf"}) {
    candidates.push_back(frames_.back().folder / name);
    for (const auto& dir : options_.library_paths) candidates.push_back(dir / name);
  }
  for (const auto& c : candidates) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(c, ec)) continue;
    if (options_.on_file_read) options_.on_file_read(c);
    return shapes::text(c, text, thickness, offset);
  }
  fail(font_where,
       "cannot find the font \"" + font + "\" (searched the scene's folder and the library paths)");
}

}  // namespace snell::sdl
