// Objects: shapes, union, CSG (intersection, difference, merge), clipped_by, blob, mesh, light_source and
// `object { Ident }`, with their modifiers (POV-Ray 3.7 reference, "Objects", "Object Modifiers", "Light
// Sources").
#include <stdexcept>

#include "snell/geometry/mesh.hpp"
#include "snell/sdl/degenerate_triangles.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/sdl/shape_factory.hpp"
#include "snell/texture/pattern_pigment.hpp"

namespace snell::sdl {

namespace {

bool is_shape_keyword(const std::string& w) {
  static const char* const shapes[] = {
      "sphere", "plane", "box", "cylinder", "cone", "disc", "torus", "triangle", "smooth_triangle", "quadric",
      // outline_shapes.cpp
      "poly", "cubic", "quartic", "polygon", "prism", "lathe", "sor", "text", "sphere_sweep"};
  for (const char* s : shapes)
    if (w == s) return true;
  return false;
}

/// Keeps `uv_indices` parallel to the faces once any triangle has uv_vectors (the others get (0, 0)).
void add_triangle_uvs(geometry::MeshData& data, const std::array<math::Vec2, 3>& uvs, bool has_uvs) {
  if (!has_uvs && data.uv_indices.empty()) return;
  while (data.uv_indices.size() + 1 < data.faces.size()) {
    const int z = static_cast<int>(data.uvs.size());
    data.uvs.push_back({0, 0});
    data.uv_indices.push_back({z, z, z});
  }
  const int first = static_cast<int>(data.uvs.size());
  for (const math::Vec2& uv : uvs) data.uvs.push_back(has_uvs ? uv : math::Vec2{0, 0});
  data.uv_indices.push_back({first, first + 1, first + 2});
}

}  // namespace

std::optional<ParsedObject> Parser::parse_object_if_any() {
  const Token t = peek();
  const NestingGuard guard(*this, t.where);
  if (t.kind != Token::Kind::identifier) return std::nullopt;
  const std::string& w = t.text;
  if (is_shape_keyword(w) || w == "union" || w == "merge" || w == "intersection" || w == "difference" ||
      w == "blob" || w == "mesh" || w == "mesh2" || w == "light_source" || w == "object" ||
      w == "isosurface" || w == "superellipsoid" || w == "height_field" || w == "bicubic_patch" ||
      w == "julia_fractal" || w == "lsystem" || w == "particle_system" || w == "boids" || w == "ovus" ||
      w == "lemon" || w == "parametric") {
    raw_next();
    return parse_object(t);
  }
  // A bare declared object, as POV-Ray accepts it where an object may stand.
  if (const Value* v = lookup(w)) {
    if (const auto* declared = std::get_if<ParsedObject>(&v->data)) {
      ParsedObject o = *declared;
      raw_next();
      return o;
    }
  }
  return std::nullopt;
}

ParsedObject Parser::parse_object(const Token& keyword) {
  const std::string& w = keyword.text;
  ParsedObject o;
  if (w == "union" || w == "merge" || w == "intersection" || w == "difference") {
    o = parse_union(keyword);
    if (w == "merge") o.combine = ParsedObject::Combine::merge;
    if (w == "intersection") o.combine = ParsedObject::Combine::intersection;
    if (w == "difference") o.combine = ParsedObject::Combine::difference;
  } else if (w == "blob") {
    o = parse_blob(keyword);
  } else if (w == "mesh") {
    o = parse_mesh(keyword);
  } else if (w == "mesh2") {
    o = parse_mesh2(keyword);
  } else if (w == "light_source") {
    o = parse_light(keyword);
  } else if (w == "isosurface") {
    o = parse_isosurface(keyword);
  } else if (w == "superellipsoid") {
    o = parse_superellipsoid(keyword);
  } else if (w == "ovus" || w == "lemon" || w == "parametric") {
    o = w == "ovus" ? parse_ovus(keyword) : w == "lemon" ? parse_lemon(keyword) : parse_parametric(keyword);
  } else if (w == "height_field") {
    o = parse_height_field(keyword);
  } else if (w == "bicubic_patch") {
    o = parse_bicubic_patch(keyword);
  } else if (w == "julia_fractal") {
    o = parse_julia_fractal(keyword);
  } else if (w == "lsystem") {
    o = parse_lsystem(keyword);
  } else if (w == "particle_system" || w == "boids") {
    o = w == "boids" ? parse_boids(keyword) : parse_particle_system(keyword);
  } else if (w == "object") {
    expect("{", "object");
    const Token& inner = peek();
    if (inner.kind == Token::Kind::identifier) {
      if (const Value* v = lookup(inner.text)) {
        const auto* declared = std::get_if<ParsedObject>(&v->data);
        if (!declared) fail(inner.where, "'" + inner.text + "' is a " + v->type_name() + ", not an object");
        o = *declared;
        raw_next();
      } else if (auto nested = parse_object_if_any()) {
        o = std::move(*nested);
      } else {
        fail(inner.where, "'" + inner.text + "' is not a declared object");
      }
    } else {
      fail(inner.where, "expected an object identifier in object { }");
    }
    o.where = keyword.where;
    parse_object_modifiers(o);
  } else {
    o = parse_shape(keyword);
  }
  return o;
}

ParsedObject Parser::parse_shape(const Token& keyword) {
  const std::string& w = keyword.text;
  ParsedObject o;
  o.where = keyword.where;
  expect("{", w.c_str());
  // POV-Ray's Parse_Comma takes a comma if there is one: `box { <0,0,0> <1,1,1> }` is valid.
  const auto comma = [&] { accept(","); };
  try {
    if (w == "sphere") {
      const math::Vec3 c = parse_vector();
      comma();
      const double r = parse_float();
      o.shape = shapes::sphere(c, r);
    } else if (w == "plane") {
      const scene::SourceLocation where = peek().where;
      const math::Vec3 n = parse_vector();
      if (length_squared(n) == 0) fail(where, "plane normal has zero length");
      comma();
      o.shape = shapes::plane(n, parse_float());
    } else if (w == "box") {
      const math::Vec3 a = parse_vector();
      comma();
      o.shape = shapes::box(a, parse_vector());
    } else if (w == "cylinder") {
      const scene::SourceLocation where = peek().where;
      const math::Vec3 a = parse_vector();
      comma();
      const math::Vec3 b = parse_vector();
      comma();
      const double r = parse_float();
      if (length_squared(b - a) == 0) fail(where, "cylinder base and cap are the same point");
      bool open = false;
      if (peek().is_word("open")) {
        raw_next();
        open = true;
      }
      o.shape = shapes::cylinder(a, b, r, open);
    } else if (w == "cone") {
      const scene::SourceLocation where = peek().where;
      const math::Vec3 a = parse_vector();
      comma();
      const double ra = parse_float();
      comma();
      const math::Vec3 b = parse_vector();
      comma();
      const double rb = parse_float();
      if (length_squared(b - a) == 0) fail(where, "cone base and cap are the same point");
      bool open = false;
      if (peek().is_word("open")) {
        raw_next();
        open = true;
      }
      o.shape = shapes::cone(a, ra, b, rb, open);
    } else if (w == "disc") {
      const math::Vec3 c = parse_vector();
      comma();
      const scene::SourceLocation where = peek().where;
      const math::Vec3 n = parse_vector();
      if (length_squared(n) == 0) fail(where, "disc normal has zero length");
      comma();
      const double r = parse_float();
      double hole = 0;
      if (accept(",")) hole = parse_float();
      o.shape = shapes::disc(c, n, r, hole);
    } else if (w == "torus") {
      const double major = parse_float();
      comma();
      const double minor = parse_float();
      if (peek().is_word("sturm")) raw_next();
      o.shape = shapes::torus(major, minor);
    } else if (w == "triangle") {
      const math::Vec3 a = parse_vector();
      comma();
      const math::Vec3 b = parse_vector();
      comma();
      const math::Vec3 c = parse_vector();
      if (is_degenerate_triangle(a, b, c))
        warn(keyword.where, "degenerate triangle (its corners are on one line); it is not rendered");
      o.shape = shapes::triangle(a, b, c);
    } else if (w == "smooth_triangle") {
      math::Vec3 p[6];
      for (int i = 0; i < 6; ++i) {
        p[i] = parse_vector();
        if (i < 5) comma();
      }
      if (is_degenerate_triangle(p[0], p[2], p[4]))
        warn(keyword.where, "degenerate triangle (its corners are on one line); it is not rendered");
      o.shape = shapes::smooth_triangle(p[0], p[1], p[2], p[3], p[4], p[5]);
    } else if (w == "quadric") {
      const math::Vec3 squares = parse_vector();
      comma();
      const math::Vec3 mixed = parse_vector();
      comma();
      const math::Vec3 linear = parse_vector();
      comma();
      o.shape = shapes::quadric(squares, mixed, linear, parse_float());
    } else {
      o.shape = parse_outline_shape(keyword);
    }
  } catch (const ParseError&) {
    throw;
  } catch (const std::exception& e) {
    fail(keyword.where, e.what());
  }
  parse_object_modifiers(o);
  return o;
}

ParsedObject Parser::parse_union(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", keyword.text.c_str());
  long long nodes = 1;
  for (;;) {
    if (auto child = parse_object_if_any()) {
      count_objects(nodes, *child, keyword.where);
      o.children.push_back(std::move(*child));
      continue;
    }
    if (peek().is_word("split_union")) {
      raw_next();
      parse_float();
      continue;
    }
    if (!parse_object_modifier(o)) break;
  }
  return o;
}

ParsedObject Parser::parse_blob(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "blob");
  double threshold = 1;  // POV-Ray's default blob threshold
  std::vector<geometry::BlobComponent> components;
  for (;;) {
    const Token t = peek();
    if (t.is_word("threshold")) {
      raw_next();
      threshold = parse_float();
    } else if (t.is_word("component")) {
      // Old syntax: component strength, radius, <center>.
      raw_next();
      geometry::BlobComponent c;
      c.strength = parse_float();
      expect(",", "blob component");
      c.radius = parse_float();
      expect(",", "blob component");
      c.center = parse_vector();
      components.push_back(c);
    } else if (t.is_word("sphere") || t.is_word("cylinder")) {
      raw_next();
      geometry::BlobComponent c;
      expect("{", t.text.c_str());
      c.center = parse_vector();
      expect(",", "blob component");
      if (t.text == "cylinder") {
        c.kind = geometry::BlobComponent::Kind::cylinder;
        c.end = parse_vector();
        expect(",", "blob component");
      }
      c.radius = parse_float();
      accept(",");
      if (peek().is_word("strength")) raw_next();
      c.strength = parse_float();
      for (;;) {
        const Token m = peek();
        if (m.is_symbol("}")) {
          raw_next();
          break;
        }
        if (auto step = parse_transform_item()) {
          c.transform = *step * c.transform;
          continue;
        }
        if (m.is_word("pigment") || m.is_word("texture") || m.is_word("finish") || m.is_word("normal")) {
          warn(m.where, "per-component blob textures are not supported yet; ignored");
          raw_next();
          skip_block(m.text);
          continue;
        }
        fail(m.where, "unexpected '" + m.text + "' in blob component");
      }
      if (c.radius <= 0) fail(t.where, "blob component radius must be positive");
      components.push_back(c);
    } else if (t.is_word("sturm")) {
      raw_next();
      parse_bool_optional(true);
    } else if (t.is_word("hierarchy")) {
      raw_next();
      parse_bool_optional(true);
    } else {
      break;
    }
  }
  if (components.empty()) fail(keyword.where, "blob has no components");
  return finish_shape(std::move(o), keyword, [&] { return shapes::blob(threshold, std::move(components)); });
}

ParsedObject Parser::parse_mesh(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "mesh");
  if (peek().kind == Token::Kind::string) return parse_mesh_file(keyword);
  // `mesh { Declared_Mesh modifiers }`: a copy of a declared mesh (POV-Ray's Parse_Object_Id).
  if (const Token& first = peek(); first.kind == Token::Kind::identifier) {
    if (const Value* v = lookup(first.text)) {
      const auto* declared = std::get_if<ParsedObject>(&v->data);
      if (!declared || !std::dynamic_pointer_cast<const geometry::Mesh>(declared->shape))
        fail(first.where, "'" + first.text + "' is not a declared mesh");
      o = *declared;
      o.where = keyword.where;
      raw_next();
      parse_object_modifiers(o);
      return o;
    }
  }
  geometry::MeshData data;
  for (;;) {
    const Token t = peek();
    if (t.is_word("triangle") || t.is_word("smooth_triangle")) {
      raw_next();
      expect("{", t.text.c_str());
      const bool smooth = t.text == "smooth_triangle";
      std::array<int, 3> face{}, normals{};
      std::array<math::Vec2, 3> uvs{};
      bool has_uvs = false;
      for (int i = 0; i < 3; ++i) {
        if (i > 0) accept(",");  // POV-Ray's Parse_Comma: the commas may be left out
        face[static_cast<size_t>(i)] = static_cast<int>(data.vertices.size());
        data.vertices.push_back(parse_vector());
        if (smooth) {
          accept(",");
          normals[static_cast<size_t>(i)] = static_cast<int>(data.normals.size());
          data.normals.push_back(parse_vector());
        }
      }
      for (;;) {
        const Token m = peek();
        if (m.is_symbol("}")) {
          raw_next();
          break;
        }
        if (m.is_word("uv_vectors")) {
          // Per-triangle uv coordinates (POV-Ray's Parse_Three_UVCoords; triangles without them get
          // (0, 0) at every corner).
          raw_next();
          for (int i = 0; i < 3; ++i) {
            if (i > 0) accept(",");
            const math::Vec3 uv = parse_vector();
            uvs[static_cast<size_t>(i)] = {uv.x, uv.y};
          }
          has_uvs = true;
          continue;
        }
        if (m.is_word("texture")) {
          warn(m.where, "per-triangle mesh textures are not supported yet; ignored");
          raw_next();
          skip_block("texture");
          continue;
        }
        fail(m.where, "unexpected '" + m.text + "' in mesh triangle");
      }
      data.faces.push_back(face);
      // --max-memory: charged by blocks of triangles (vertices, face and normal indices).
      constexpr size_t kBlock = 4096;
      if (data.faces.size() % kBlock == 1)
        keep_memory(t.where, kBlock * (3 * sizeof(math::Vec3) + 2 * sizeof(face)), "mesh triangles");
      add_triangle_uvs(data, uvs, has_uvs);
      if (smooth) {
        if (data.normal_indices.size() < data.faces.size() - 1) {
          // An earlier flat triangle: give it its own face normal slots pointing nowhere (zero).
          while (data.normal_indices.size() < data.faces.size() - 1) {
            const int z = static_cast<int>(data.normals.size());
            data.normals.push_back({});
            data.normal_indices.push_back({z, z, z});
          }
        }
        data.normal_indices.push_back(normals);
      } else if (!data.normal_indices.empty()) {
        const int z = static_cast<int>(data.normals.size());
        data.normals.push_back({});
        data.normal_indices.push_back({z, z, z});
      }
    } else if (t.is_word("inside_vector")) {
      raw_next();
      data.inside_vector = parse_vector();
    } else if (t.is_word("hierarchy")) {
      raw_next();
      parse_bool_optional(true);
    } else {
      break;
    }
  }
  if (data.faces.empty()) fail(keyword.where, "mesh has no triangles");
  if (const size_t n = count_degenerate_faces(data)) warn(keyword.where, degenerate_faces_message(n));
  return finish_shape(std::move(o), keyword, [&] { return shapes::mesh(std::move(data)); });
}

ParsedObject Parser::parse_light(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "light_source");
  scene::Light light;
  // `light_source { DeclaredLight modifiers }` (radiosity/cornell.pov) starts from a copy.
  if (auto declared = take_declared<ParsedObject>()) {
    if (!declared->light) fail(o.where, "'" + declared->name + "' is an object, not a light_source");
    light = *declared->light;
    o = std::move(*declared);
  } else {
    light.position = parse_vector();
    accept(",");
    light.color = parse_color().rgb;
  }
  bool radius_set = false, falloff_set = false;
  std::optional<ParsedObject> looks_like;
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      break;
    }
    if (auto step = parse_transform_item()) {
      o.apply(*step);
      continue;
    }
    if (t.kind != Token::Kind::identifier) fail(t.where, "unexpected '" + t.text + "' in light_source");
    const std::string& w = t.text;
    if (w == "color" || w == "rgb") {
      light.color = parse_color().rgb;
      continue;
    }
    raw_next();
    if (w == "spotlight" || w == "cylinder") {
      light.kind = w == "spotlight" ? scene::Light::Kind::spotlight : scene::Light::Kind::cylinder;
      // POV-Ray's cylinder light defaults are in units, not degrees (reference, "Cylindrical Lights").
      if (w == "cylinder") {
        if (!radius_set) light.radius = 0.75;
        if (!falloff_set) light.falloff = 1;
      }
    } else if (w == "parallel") {
      light.kind = scene::Light::Kind::parallel;
    } else if (w == "point_at") {
      light.point_at = parse_vector();
    } else if (w == "radius") {
      light.radius = parse_float();
      radius_set = true;
    } else if (w == "falloff") {
      light.falloff = parse_float();
      falloff_set = true;
    } else if (w == "tightness") {
      light.tightness = parse_float();
    } else if (w == "shadowless") {
      light.shadowless = true;
    } else if (w == "fade_distance") {
      light.fade_distance = parse_float();
    } else if (w == "fade_power") {
      light.fade_power = parse_float();
    } else if (w == "area_light") {
      light.area = true;
      // The commas are optional, as everywhere POV-Ray reads arguments (bsp/Tango.pov omits them).
      light.axis1 = parse_vector();
      accept(",");
      light.axis2 = parse_vector();
      accept(",");
      light.size1 = parse_int("area_light size");
      accept(",");
      light.size2 = parse_int("area_light size");
      if (light.size1 < 1 || light.size2 < 1) fail(t.where, "area_light sizes must be at least 1");
      if (light.size1 * static_cast<long>(light.size2) > 65536)
        fail(t.where, "area_light grid too large (at most 65536 points)");
    } else if (w == "adaptive") {
      light.adaptive = parse_int("adaptive");
    } else if (w == "jitter") {
      light.jitter = true;
    } else if (w == "circular") {
      light.circular = true;
    } else if (w == "orient") {
      light.orient = true;
    } else if (w == "area_illumination") {
      light.area_illumination = parse_bool_optional(true);
    } else if (w == "media_interaction") {
      light.media_interaction = parse_bool_optional(true);
    } else if (w == "media_attenuation") {
      light.media_attenuation = parse_bool_optional(true);
    } else if (w == "looks_like") {
      // POV-Ray 3.7 reference, "Looks_like": the object, placed at the light's centre, is drawn but casts
      // no shadow, so the light shines out through it; later light transforms move both.
      if (looks_like) fail(t.where, "only one looks_like is allowed per light_source");
      expect("{", "looks_like");
      const Token inner = peek();
      looks_like = take_declared<ParsedObject>();
      if (!looks_like) looks_like = parse_object_if_any();
      if (!looks_like) fail(inner.where, "expected an object in looks_like");
      looks_like->apply(math::Transform::translate(light.position));
      parse_object_modifiers(*looks_like);  // up to and including the closing '}'
      looks_like->flags.no_shadow = true;
    } else if (w == "projected_through") {
      // POV-Ray 3.7 reference, "Projected_Through": light passes only where the ray to it crosses the object.
      if (o.projected_through) fail(t.where, "only one projected_through is allowed per light_source");
      expect("{", "projected_through");
      const Token inner = peek();
      auto through = take_declared<ParsedObject>();
      if (!through) through = parse_object_if_any();
      if (!through) fail(inner.where, "expected an object in projected_through");
      parse_object_modifiers(*through);  // up to and including the closing '}'
      o.projected_through = std::make_shared<const ParsedObject>(std::move(*through));
    } else if (w == "photons") {
      parse_light_photons(light.photons);
    } else {
      fail(t.where, "unknown light_source keyword '" + w + "'");
    }
  }
  if (light.area && light.circular && (light.size1 <= 1 || light.size2 <= 1))
    fail(keyword.where, "a circular area_light needs more than one point along each axis");
  // The light is in its own space; earlier transforms were applied to `o` (and fold in at flattening).
  o.light = light;
  if (looks_like) o.children.push_back(std::move(*looks_like));
  return o;
}

void Parser::parse_object_modifiers(ParsedObject& object) {
  while (parse_object_modifier(object)) {
  }
}

void Parser::parse_clip_block(ParsedObject& o, const Token& keyword) {
  // clipped_by { objects } or bounded_by { objects }; `clipped_by { bounded_by }` and
  // `bounded_by { clipped_by }` reuse the other list (POV-Ray 3.7 reference, "Clipped_By", "Bounded_By").
  // bounded_by objects become a culling box for the accelerators (see parsed_object.cpp).
  const bool clip = keyword.text == "clipped_by";
  expect("{", keyword.text.c_str());
  const Token first = peek();
  if (clip && first.is_word("bounded_by")) {
    raw_next();
    expect("}", "clipped_by");
    o.clipped_by = o.bounded_by;
    return;
  }
  if (!clip && first.is_word("clipped_by")) {
    raw_next();
    expect("}", "bounded_by");
    return;
  }
  std::vector<ParsedObject> objects;
  // The clipping objects are written in the object's current space; keep them in its own space so that
  // later transforms of the object move them too.
  const math::Transform to_own = o.transform.inverse();
  long long nodes = count_nodes(o, options_.max_objects);
  while (auto child = parse_object_if_any()) {
    count_objects(nodes, *child, keyword.where);
    child->apply(to_own);
    objects.push_back(std::move(*child));
  }
  expect("}", keyword.text.c_str());
  if (objects.empty()) fail(keyword.where, keyword.text + " needs at least one object");
  auto& list = clip ? o.clipped_by : o.bounded_by;
  for (auto& obj : objects) list.push_back(std::move(obj));
}

void Parser::count_objects(long long& nodes, const ParsedObject& added, const scene::SourceLocation& where) {
  nodes += count_nodes(added, options_.max_objects);
  if (nodes > options_.max_objects)
    fail(where, "this object holds more than " + std::to_string(options_.max_objects) +
                    " objects (ParseOptions::max_objects)");
}

void Parser::attach_pigment(ParsedObject& o, std::shared_ptr<const material::Pigment> pigment) {
  auto texture = std::make_shared<material::Texture>(o.texture ? *o.texture : *default_texture_);
  texture->pigment = std::move(pigment);
  o.texture = std::move(texture);
}

bool Parser::parse_object_modifier(ParsedObject& o) {
  const Token t = peek();
  if (t.is_symbol("}")) {
    raw_next();
    return false;
  }
  if (t.kind != Token::Kind::identifier) {
    fail(t.where, t.kind == Token::Kind::end ? "unexpected end of file: missing '}'"
                                             : "unexpected '" + t.text + "' in object");
  }
  if (auto step = parse_transform_item()) {
    o.apply(*step);
    return true;
  }
  const std::string& w = t.text;
  raw_next();
  auto ensure_texture = [&] {
    auto texture = std::make_shared<material::Texture>(o.texture ? *o.texture : *default_texture_);
    if (!texture->pigment) texture->pigment = default_texture_->pigment;
    return texture;
  };
  // POV-Ray 3.7: `uv_mapping` as an object modifier makes the textures that follow uv-mapped.
  const auto uv =
      [&](std::shared_ptr<const material::Pigment> pigment) -> std::shared_ptr<const material::Pigment> {
    if (!o.uv_mapping || !pigment) return pigment;
    return std::make_shared<texture::UvMappedPigment>(std::move(pigment));
  };
  if (w == "uv_mapping") {
    if (o.texture) fail(t.where, "uv_mapping must be specified before texture");
    o.uv_mapping = true;
  } else if (w == "pigment") {
    const auto base = o.texture ? o.texture->pigment : nullptr;
    attach_pigment(o, uv(parse_pigment_block(base)));
  } else if (w == "finish") {
    auto texture = ensure_texture();
    texture->finish = parse_finish_block(texture->finish);
    o.texture = std::move(texture);
  } else if (w == "texture") {
    // The texture starts in the object's current space: later object transforms move it too. A texture
    // on an object that has one goes on top of it as a new layer, as in POV-Ray (Link_Textures).
    auto texture = parse_texture_block();
    if (o.uv_mapping && texture->pigment) {
      // Each layer of the new texture block gets its pigment uv-mapped (texture maps' entries keep theirs).
      auto copy = std::make_shared<material::Texture>(*texture);
      copy->pigment = uv(copy->pigment);
      texture = copy;
    }
    o.texture = material::Texture::layered(texture, o.texture);
  } else if (w == "material") {
    const auto m = parse_material_block();
    if (m->texture) o.texture = material::Texture::layered(m->texture, o.texture);
    if (m->interior) o.interior = m->interior;
  } else if (w == "interior") {
    o.interior = parse_interior_block();
  } else if (w == "normal") {
    auto texture = ensure_texture();
    texture->normal = parse_normal_block();
    o.texture = std::move(texture);
  } else if (w == "no_shadow") {
    o.flags.no_shadow = true;
  } else if (w == "no_image") {
    o.flags.no_image = true;
  } else if (w == "no_reflection") {
    o.flags.no_reflection = true;
  } else if (w == "double_illuminate") {
    o.flags.double_illuminate = true;
  } else if (w == "hollow") {
    o.flags.hollow = parse_bool_optional(true);
  } else if (w == "inverse") {
    o.flags.inverse = !o.flags.inverse;
  } else if (w == "clipped_by" || w == "bounded_by") {
    parse_clip_block(o, t);
  } else if (w == "motion") {
    parse_motion_block(o, t);
  } else if (w == "photons") {
    parse_object_photons(o.flags.photons);
  } else if (w == "radiosity" || w == "interior_texture") {
    warn(t.where, w + " is not supported yet; ignored");
    skip_block(w);
  } else if (w == "no_radiosity") {
  } else if (w == "sturm") {
    parse_bool_optional(true);  // `object { Quartic sturm }`: roots always come from the Sturm solver
  } else {
    fail(t.where, "unexpected '" + w + "' in object");
  }
  return true;
}

}  // namespace snell::sdl
