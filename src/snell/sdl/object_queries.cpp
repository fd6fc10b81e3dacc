// Functions that ask an object about its geometry while parsing (POV-Ray 3.7 reference, "Vector
// Functions"): `trace(Object, Start, Direction [, Normal])`, `min_extent(Object)`/`max_extent(Object)` and
// `inside(Object, Point)`; and the inside test behind the `object` pattern.
// The object is flattened into scene objects exactly as it would be placed in the scene, so the answers
// are those of the renderer's own intersection code.
#include <algorithm>
#include <limits>

#include "snell/sdl/parser.hpp"

namespace snell::sdl {

namespace {

/// POV-Ray's bound for "infinite" extents (BOUND_HUGE in its source): unbounded objects report it.
constexpr double kBoundHuge = 2.0e10;

Numeric vector_of(const math::Vec3& p) {
  return Numeric{{p.x, p.y, p.z, 0, 0}, 3, false};
}

double clamp_huge(double v) {
  return std::clamp(v, -kBoundHuge, kBoundHuge);
}

}  // namespace

ParsedObject Parser::parse_object_argument(const char* function_name) {
  const Token at = peek();
  auto object = parse_object_if_any();
  if (!object) fail(at.where, std::string(function_name) + " needs an object, found '" + at.text + "'");
  return std::move(*object);
}

Numeric Parser::parse_object_query(const Token& name) {
  const std::string& f = name.text;
  expect("(", f.c_str());
  const ParsedObject object = parse_object_argument(f.c_str());
  std::vector<std::shared_ptr<const scene::Object>> parts;
  std::vector<scene::Light> lights;
  flatten(object, parts, lights);
  if (f == "inside") {
    expect(",", "inside");
    const math::Vec3 point = parse_vector();
    expect(")", "inside");
    const bool in =
        std::any_of(parts.begin(), parts.end(), [&](const auto& part) { return part->inside(point); });
    return Numeric::of(in ? 1 : 0);
  }
  if (f == "min_extent" || f == "max_extent") {
    expect(")", f.c_str());
    math::Bounds3 box;
    for (const auto& part : parts) box.unite(part->world_bounds());
    if (parts.empty()) return vector_of({0, 0, 0});
    const math::Vec3 p = f == "min_extent" ? box.lo : box.hi;
    return vector_of({clamp_huge(p.x), clamp_huge(p.y), clamp_huge(p.z)});
  }
  // trace(Object, Start, Direction [, Normal]): the first hit from Start along Direction, <0,0,0> when
  // there is none; Normal (an identifier) receives the surface normal there, or <0,0,0>.
  expect(",", "trace");
  const math::Vec3 start = parse_vector();
  expect(",", "trace");
  const scene::SourceLocation direction_at = peek().where;
  const math::Vec3 direction = parse_vector();
  if (length(direction) == 0) fail(direction_at, "trace direction is a zero vector");
  std::optional<Token> normal_name;
  if (accept(",")) {
    normal_name = raw_next();
    if (normal_name->kind != Token::Kind::identifier)
      fail(normal_name->where, "expected an identifier to receive trace's normal");
  }
  expect(")", "trace");
  const math::Ray ray{start, normalize(direction), 0};
  scene::SurfaceHit nearest;
  bool found = false;
  double t_max = std::numeric_limits<double>::infinity();
  for (const auto& part : parts) {
    scene::SurfaceHit hit;
    if (part->intersect(ray, 0, t_max, hit)) {
      nearest = hit;
      t_max = hit.t;
      found = true;
    }
  }
  if (normal_name) {
    const math::Vec3 normal = found ? normalize(nearest.normal) : math::Vec3(0, 0, 0);
    assign(normal_name->text, Value{vector_of(normal)});
  }
  return vector_of(found ? nearest.point : math::Vec3(0, 0, 0));
}

std::function<bool(const math::Vec3&)> Parser::parse_inside_test() {
  const ParsedObject object = parse_object_argument("the object pattern");
  auto parts = std::make_shared<std::vector<std::shared_ptr<const scene::Object>>>();
  std::vector<scene::Light> lights;
  flatten(object, *parts, lights);
  return [parts](const math::Vec3& p) {
    return std::any_of(parts->begin(), parts->end(), [&](const auto& part) { return part->inside(p); });
  };
}

void Parser::assign(const std::string& name, Value value) {
  for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it)
    if (const auto found = it->find(name); found != it->end()) {
      found->second = std::move(value);
      return;
    }
  declare(name, std::move(value), false);
}

}  // namespace snell::sdl
