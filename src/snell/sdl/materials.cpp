// pigment, finish, interior, texture and transform blocks (POV-Ray 3.7 reference, "Textures",
// "Interior", "Transformations"). Pigments and their patterns are parsed in pigments.cpp.
#include <cmath>
#include <string>

#include "snell/sdl/parser.hpp"
#include "snell/sdl/pigment_builder.hpp"

namespace snell::sdl {

namespace {

/// POV-Ray keeps the reciprocal of a reflection's `exponent` (and of `reflection_exponent`) and raises the
/// reflected colour to that (parstxtr.cpp: Reflect_Exp = 1 / value): `exponent 0.8` is colour^1.25.
double reflection_exponent_of(double value) {
  return 1.0 / value;
}

}  // namespace

std::optional<math::Transform> Parser::parse_transform_item() {
  const Token t = peek();
  if (t.kind != Token::Kind::identifier) return std::nullopt;
  const std::string& w = t.text;
  // An infinite or NaN amount (an overflow such as 1e200*1e200) would make every point it moves NaN.
  const auto finite_vector = [&] {
    const scene::SourceLocation where = peek().where;
    const math::Vec3 v = parse_vector();
    if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)))
      fail(where, w + " amount is not a finite number");
    return v;
  };
  if (w == "translate") {
    raw_next();
    return math::Transform::translate(finite_vector());
  }
  if (w == "rotate") {
    raw_next();
    return math::Transform::rotate_xyz_degrees(finite_vector());
  }
  if (w == "scale") {
    raw_next();
    const scene::SourceLocation where = peek().where;
    math::Vec3 s = finite_vector();
    // POV-Ray 3.7 warns about a zero scale component and uses 1 instead.
    for (int i = 0; i < 3; ++i) {
      if (s[i] == 0) {
        warn(where, "scale component is zero; using 1 instead");
        s[i] = 1;
      }
    }
    return math::Transform::scale(s);
  }
  if (w == "matrix") {
    raw_next();
    const scene::SourceLocation where = peek().where;
    expect("<", "matrix");
    const bool saved = in_vector_;
    in_vector_ = true;  // the closing '>' is not a comparison
    double values[12];
    for (int i = 0; i < 12; ++i) {
      values[i] = parse_float();
      if (i < 11) expect(",", "matrix (12 values)");
    }
    in_vector_ = saved;
    expect(">", "matrix");
    // POV-Ray 3.7 (Parse_Matrix) warns about a column of the 3x3 part that is all zero, a scale by 0,
    // and puts 1 on its diagonal; a matrix still singular after that is an error here.
    constexpr double kZero = 1e-10;
    for (int column = 0; column < 3; ++column) {
      if (std::fabs(values[column]) < kZero && std::fabs(values[3 + column]) < kZero &&
          std::fabs(values[6 + column]) < kZero) {
        warn(where, "matrix column " + std::to_string(column + 1) +
                        " is zero (a scale by 0); using 1 on its diagonal");
        values[4 * column] = 1;
      }
    }
    const auto m = math::Transform::pov_matrix(values);
    if (!m) fail(where, "singular matrix: it cannot be inverted");
    return *m;
  }
  if (w == "transform") {
    raw_next();
    return parse_transform_block();
  }
  return std::nullopt;
}

math::Transform Parser::parse_transform_block() {
  const Token& t = peek();
  if (t.kind == Token::Kind::identifier) {
    // `transform Ident` without braces.
    if (const Value* v = lookup(t.text); v && std::holds_alternative<math::Transform>(v->data)) {
      const math::Transform copy = std::get<math::Transform>(v->data);
      raw_next();
      return copy;
    }
  }
  expect("{", "transform");
  math::Transform result;
  for (;;) {
    const Token item = peek();
    if (item.is_symbol("}")) {
      raw_next();
      return result;
    }
    if (item.is_word("inverse")) {
      raw_next();
      result = result.inverse();
      continue;
    }
    if (item.kind == Token::Kind::identifier) {
      if (const Value* v = lookup(item.text); v && std::holds_alternative<math::Transform>(v->data)) {
        result = std::get<math::Transform>(v->data) * result;
        raw_next();
        continue;
      }
    }
    if (auto step = parse_transform_item()) {
      result = *step * result;
      continue;
    }
    fail(item.where, "unexpected '" + item.text + "' in transform");
  }
}

void Parser::parse_reflection(material::Finish& f) {
  if (!peek().is_symbol("{")) {
    // `reflection c`: min = max = c (the POV-Ray 3.5 form).
    const material::Rgbft c = parse_color();
    f.reflection_min = f.reflection_max = c.rgb;
    return;
  }
  raw_next();
  bool have_min = false;
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      // With fresnel, one colour is the most reflection and the least is zero (POV-Ray 3.7
      // parser_materials.cpp, end of Parse_Finish: equal min and max are cleared to min = 0).
      if (f.reflection_fresnel && f.reflection_min == f.reflection_max) f.reflection_min = math::Color(0);
      return;
    }
    if (t.is_symbol(",")) {
      raw_next();
      continue;
    }
    if (t.kind == Token::Kind::identifier) {
      const std::string& w = t.text;
      if (w == "fresnel") {
        raw_next();
        f.reflection_fresnel = parse_bool_optional(true);
        continue;
      }
      if (w == "falloff") {
        raw_next();
        f.reflection_falloff = parse_float();
        continue;
      }
      if (w == "exponent") {
        raw_next();
        f.reflection_exponent = reflection_exponent_of(parse_float());
        continue;
      }
      if (w == "metallic") {
        raw_next();
        f.reflection_metallic = starts_numeric() ? parse_float() : 1;
        continue;
      }
      if (parse_rough_item(w, f.reflection_blur, f.reflection_samples)) continue;
    }
    if (starts_numeric()) {
      // `{ max }` or `{ min, max }`: a single colour is both (POV-Ray 3.7 "reflection").
      const math::Color c = parse_color().rgb;
      if (!have_min) {
        f.reflection_min = f.reflection_max = c;
        have_min = true;
      } else {
        f.reflection_max = c;
      }
      continue;
    }
    fail(t.where, "unexpected '" + t.text + "' in reflection");
  }
}

material::Finish Parser::parse_finish_block(const material::Finish& base) {
  expect("{", "finish");
  material::Finish f = base;
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      return f;
    }
    if (t.kind != Token::Kind::identifier) fail(t.where, "unexpected '" + t.text + "' in finish");
    const std::string& w = t.text;
    if (auto declared = take_declared<material::Finish>()) {
      f = *declared;
      continue;
    }
    raw_next();
    if (w == "ambient") {
      f.ambient = parse_color().rgb;
      f.ambient_set = true;
    } else if (w == "emission") {
      f.emission = parse_color().rgb;
    } else if (w == "diffuse") {
      if (peek().is_word("albedo")) raw_next();
      f.diffuse = parse_float();
      if (accept(",")) parse_float();  // back-side diffuse: not modelled yet
    } else if (w == "brilliance") {
      f.brilliance = parse_float();
    } else if (w == "crand") {
      f.crand = parse_float();
    } else if (w == "phong") {
      if (peek().is_word("albedo")) raw_next();
      f.phong = parse_float();
    } else if (w == "phong_size") {
      f.phong_size = parse_float();
    } else if (w == "specular") {
      if (peek().is_word("albedo")) raw_next();
      f.specular = parse_float();
    } else if (w == "roughness") {
      f.roughness = parse_float();
    } else if (w == "metallic") {
      f.metallic = starts_numeric() ? parse_float() : 1;
    } else if (w == "reflection") {
      parse_reflection(f);
    } else if (w == "transmission") {
      parse_transmission(f);
    } else if (w == "reflection_exponent") {
      f.reflection_exponent = reflection_exponent_of(parse_float());
    } else if (w == "conserve_energy") {
      f.conserve_energy = parse_bool_optional(true);
    } else if (w == "subsurface") {
      parse_finish_subsurface(f);
    } else if (w == "irid") {
      warn(t.where, w + " is not supported yet; ignored");
      skip_block(w);
    } else {
      fail(t.where, "unknown finish keyword '" + w + "'");
    }
  }
}

std::shared_ptr<const material::Interior> Parser::parse_interior_block() {
  expect("{", "interior");
  auto interior = std::make_shared<material::Interior>();
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      return interior;
    }
    if (t.kind != Token::Kind::identifier) fail(t.where, "unexpected '" + t.text + "' in interior");
    const std::string& w = t.text;
    if (auto declared = take_declared<std::shared_ptr<const material::Interior>>()) {
      *interior = **declared;
      continue;
    }
    raw_next();
    if (w == "ior")
      interior->ior = parse_float();
    else if (w == "dispersion")
      interior->dispersion = parse_float();
    else if (w == "dispersion_samples")
      parse_float();
    else if (w == "caustics")
      interior->caustics = parse_float();
    else if (w == "fade_distance")
      interior->fade_distance = parse_float();
    else if (w == "fade_power")
      interior->fade_power = parse_float();
    else if (w == "fade_color")
      interior->fade_color = parse_color().rgb;
    else if (w == "media") {
      // An unsupported media is dropped (parse_media_block warned).
      if (auto media = parse_media_block()) interior->media.push_back(std::move(*media));
    } else {
      fail(t.where, "unknown interior keyword '" + w + "'");
    }
  }
}

std::shared_ptr<const material::Texture> Parser::parse_texture_block() {
  const NestingGuard guard(*this, peek().where);
  expect("{", "texture");
  return parse_texture_body("}");
}

std::shared_ptr<const material::Texture> Parser::parse_texture_body(const char* closer) {
  const scene::SourceLocation where = peek().where;
  auto texture = std::make_shared<material::Texture>(*default_texture_);
  texture->pigment = nullptr;
  TexturePatternBuilder patterned;
  bool uv_mapping = false;
  for (;;) {
    const Token t = peek();
    if (t.is_symbol(closer)) {
      raw_next();
      break;
    }
    if (t.kind != Token::Kind::identifier) fail(t.where, "unexpected '" + t.text + "' in texture");
    const std::string& w = t.text;
    if (auto declared = take_declared<std::shared_ptr<const material::Texture>>()) {
      *texture = **declared;
      continue;
    }
    if (auto step = parse_transform_item()) {
      // A declared layered or averaged texture moves as a whole.
      texture->move(*step);
      continue;
    }
    if (parse_texture_pattern(patterned)) continue;
    raw_next();
    if (w == "uv_mapping") {
      uv_mapping = true;  // applies to the texture's pigment (below)
    } else if (w == "texture" && std::string(closer) == "]") {
      *texture = *parse_texture_block();  // `[v texture {..}]` in a texture_map
    } else if (w == "pigment") {
      texture->pigment = parse_pigment_block(texture->pigment);
    } else if (w == "finish") {
      texture->finish = parse_finish_block(texture->finish);
    } else if (w == "normal") {
      texture->normal = parse_normal_block();
    } else {
      fail(t.where, "unexpected '" + w + "' in texture");
    }
  }
  if (patterned.active) finish_texture_pattern(patterned, *texture, where);
  if (!texture->pigment) texture->pigment = default_texture_->pigment;
  if (uv_mapping) texture->pigment = std::make_shared<texture::UvMappedPigment>(texture->pigment);
  return texture;
}

std::shared_ptr<const material::Texture> Parser::parse_layered_textures() {
  auto texture = parse_texture_block();
  // `texture {A} texture {B}`: B lies on top of A (POV-Ray 3.7 reference, "Layered Textures").
  while (peek_after_value().is_word("texture")) {
    raw_next();
    texture = material::Texture::layered(parse_texture_block(), texture);
  }
  return texture;
}

std::shared_ptr<const material::Material> Parser::parse_material_block() {
  expect("{", "material");
  auto material = std::make_shared<material::Material>();
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      return material;
    }
    if (t.kind != Token::Kind::identifier) fail(t.where, "unexpected '" + t.text + "' in material");
    const std::string& w = t.text;
    if (auto declared = take_declared<std::shared_ptr<const material::Material>>()) {
      *material = **declared;
      continue;
    }
    if (auto step = parse_transform_item()) {
      // Material transforms move its texture (an interior has no pattern to move).
      if (material->texture) material->texture = material->texture->transformed(*step);
      continue;
    }
    raw_next();
    if (w == "texture") {
      material->texture = material::Texture::layered(parse_texture_block(), material->texture);
    } else if (w == "interior") {
      material->interior = parse_interior_block();
    } else if (w == "interior_texture") {
      warn(t.where, "interior_texture is not supported yet; ignored");
      skip_block(w);
    } else {
      fail(t.where, "unexpected '" + w + "' in material");
    }
  }
}

}  // namespace snell::sdl
