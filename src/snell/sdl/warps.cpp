// `warp { ... }` inside a pigment, normal or texture pattern (POV-Ray 3.7 reference, "Warps"): each warp
// takes its place in the pattern's warp list, in the order written.
#include "snell/sdl/parser.hpp"
#include "snell/sdl/pigment_builder.hpp"
#include "snell/texture/mapping_warps.hpp"

namespace snell::sdl {

namespace {

math::Vec3 as_vector(const Numeric& n) {
  return n.size == 1 ? math::Vec3{n.x(), n.x(), n.x()} : n.vec3();
}

}  // namespace

void Parser::parse_warp(PigmentBuilder& b) {
  expect("{", "warp");
  const Token kind = raw_next();
  // Modifiers of the warp until the closing brace; `read` handles one and says whether it knew it.
  const auto modifiers = [&](const auto& read) {
    for (;;) {
      const Token m = peek();
      if (m.is_symbol("}")) {
        raw_next();
        return;
      }
      raw_next();
      if (!read(m)) fail(m.where, "unexpected '" + m.text + "' in warp " + kind.text);
    }
  };
  const auto unit = [&](const Token& where) {
    const math::Vec3 v = parse_vector();
    if (!(math::length(v) > 0)) fail(where.where, "orientation must not be the zero vector");
    return math::normalize(v);
  };
  std::shared_ptr<const texture::Warp> warp;
  if (kind.is_word("turbulence")) {
    texture::TurbulenceParams params;
    params.amount = as_vector(parse_numeric());
    modifiers([&](const Token& m) {
      if (m.is_word("octaves"))
        params.octaves = std::clamp(parse_int("octaves"), 1, 10);
      else if (m.is_word("omega"))
        params.omega = parse_float();
      else if (m.is_word("lambda"))
        params.lambda = parse_float();
      else
        return false;
      return true;
    });
    warp = std::make_shared<texture::TurbulenceWarp>(params);
  } else if (kind.is_word("black_hole")) {
    texture::BlackHoleParams params;
    params.center = parse_vector();
    accept(",");
    params.radius = parse_float();
    if (!(params.radius > 0)) fail(kind.where, "a black_hole's radius must be positive");
    modifiers([&](const Token& m) {
      if (m.is_word("strength"))
        params.strength = parse_float();
      else if (m.is_word("falloff"))
        params.falloff = parse_float();
      else if (m.is_word("inverse"))
        params.inverse = true;
      else if (m.is_word("type"))
        parse_float();  // POV-Ray knows only type 0
      else if (m.is_word("repeat"))
        params.repeat = parse_vector();
      else if (m.is_word("turbulence"))
        params.jitter = parse_vector();
      else
        return false;
      return true;
    });
    if (params.repeat.x < 0 || params.repeat.y < 0 || params.repeat.z < 0)
      fail(kind.where, "a black_hole's repeat must not be negative");
    warp = std::make_shared<texture::BlackHoleWarp>(params);
  } else if (kind.is_word("repeat")) {
    const math::Vec3 v = parse_vector();
    const int axes = (v.x != 0) + (v.y != 0) + (v.z != 0);
    if (axes != 1) fail(kind.where, "repeat needs exactly one non-zero axis, as in repeat x*2");
    const int axis = v.x != 0 ? 0 : v.y != 0 ? 1 : 2;
    const double width = axis == 0 ? v.x : axis == 1 ? v.y : v.z;
    math::Vec3 offset{0, 0, 0}, flip{1, 1, 1};
    modifiers([&](const Token& m) {
      if (m.is_word("offset")) {
        offset = parse_vector();
      } else if (m.is_word("flip")) {
        const math::Vec3 f = parse_vector();
        flip = {f.x != 0 ? -1.0 : 1.0, f.y != 0 ? -1.0 : 1.0, f.z != 0 ? -1.0 : 1.0};
      } else {
        return false;
      }
      return true;
    });
    warp = std::make_shared<texture::RepeatWarp>(axis, width, offset, flip);
  } else if (kind.is_word("cylindrical") || kind.is_word("spherical") || kind.is_word("toroidal")) {
    texture::MappingWarp::Params params;
    params.kind = kind.is_word("cylindrical") ? texture::MappingWarp::Kind::cylindrical
                  : kind.is_word("spherical") ? texture::MappingWarp::Kind::spherical
                                              : texture::MappingWarp::Kind::toroidal;
    modifiers([&](const Token& m) {
      if (m.is_word("orientation"))
        params.orientation = unit(m);
      else if (m.is_word("dist_exp"))
        params.dist_exp = parse_float();
      else if (m.is_word("major_radius") && params.kind == texture::MappingWarp::Kind::toroidal)
        params.major_radius = parse_float();
      else
        return false;
      return true;
    });
    warp = std::make_shared<texture::MappingWarp>(params);
  } else if (kind.is_word("planar")) {
    texture::MappingWarp::Params params;
    params.kind = texture::MappingWarp::Kind::planar;
    if (starts_numeric()) {
      params.orientation = unit(kind);
      accept(",");
      params.offset = parse_float();
    }
    expect("}", "warp planar");
    warp = std::make_shared<texture::MappingWarp>(params);
  } else {
    fail(kind.where, "warp '" + kind.text +
                         "' is not supported (turbulence, black_hole, repeat, cylindrical, spherical, "
                         "toroidal or planar)");
  }
  if (b.patterned) b.spec.warps.push(warp);  // a plain colour is the same everywhere
}

}  // namespace snell::sdl
