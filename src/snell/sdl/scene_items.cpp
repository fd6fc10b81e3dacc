// The top level of a scene: camera, background, global_settings and objects (POV-Ray 3.7 reference,
// "Scene Settings", "Camera").
#include <cmath>

#include "snell/math/constants.hpp"
#include "snell/sdl/parser.hpp"

namespace snell::sdl {

Parser::Parser(const ParseOptions& options) : options_(options) {
  scopes_.emplace_back();
  for (const auto& [name, value] : options_.declares) scopes_.front()[name] = Value{Numeric::of(value)};
}

scene::Scene Parser::parse_file(const std::filesystem::path& path) {
  push_file(path, Frame::Kind::file,
            scene::SourceLocation{std::make_shared<const std::string>(path.string()), 0, 0});
  locate_memory_errors([this] { parse_scene_items(); });
  return finish_scene();
}

scene::Scene Parser::parse_text(const std::string& text, const std::string& file_name) {
  Frame f;
  f.tokens = tokens_of(file_name, text);
  f.folder = std::filesystem::path(file_name).parent_path();
  frames_.push_back(std::move(f));
  locate_memory_errors([this] { parse_scene_items(); });
  return finish_scene();
}

void Parser::parse_scene_items() {
  for (;;) {
    const Token t = peek();
    if (t.kind == Token::Kind::end) return;
    if (t.is_symbol(";")) {  // stray semicolons after declarations are harmless in POV-Ray
      raw_next();
      continue;
    }
    if (t.kind != Token::Kind::identifier)
      fail(t.where, "unexpected '" + t.text + "' at the top level of the scene");
    if (t.text == "camera") {
      raw_next();
      scene_.camera = parse_camera(scene_.camera);
      continue;
    }
    if (t.text == "background") {
      raw_next();
      parse_background();
      continue;
    }
    if (t.text == "default") {  // the pre-3.0 spelling of #default, which POV-Ray 3.7 still reads
      directive_default(raw_next());
      continue;
    }
    if (t.text == "global_settings") {
      raw_next();
      parse_global_settings();
      continue;
    }
    if (t.text == "sky_sphere") {
      raw_next();
      scene_.sky_sphere = parse_sky_sphere_block();
      continue;
    }
    if (t.text == "fog") {
      raw_next();
      scene_.fogs.push_back(parse_fog_block());
      continue;
    }
    if (t.text == "media") {
      raw_next();
      if (auto media = parse_media_block()) scene_.atmosphere.push_back(std::move(*media));
      continue;
    }
    if (t.text == "rainbow") {
      raw_next();
      warn(t.where, "rainbow is not supported yet; ignored");
      skip_block(t.text);
      continue;
    }
    if (auto object = parse_object_if_any()) {
      if (!object->texture) object->texture = default_texture_;  // `#default {}` in force now
      flatten(*object, scene_.objects, scene_.lights);
      continue;
    }
    if (lookup(t.text))
      fail(t.where, "'" + t.text + "' cannot stand alone here; use object { " + t.text + " }");
    fail(t.where, "unknown keyword '" + t.text + "'");
  }
}

void Parser::parse_background() {
  expect("{", "background");
  scene_.background = parse_color();
  expect("}", "background");
}

void Parser::parse_global_settings() {
  expect("{", "global_settings");
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      return;
    }
    if (t.kind != Token::Kind::identifier) fail(t.where, "unexpected '" + t.text + "' in global_settings");
    const std::string& w = t.text;
    raw_next();
    if (w == "assumed_gamma") {
      const double g = parse_float();
      // POV-Ray 3.7 honours only the first assumed_gamma of a scene.
      if (!assumed_gamma_seen_)
        scene_.settings.assumed_gamma = g;
      else
        warn(t.where, "assumed_gamma given again; the first one stays in effect");
      assumed_gamma_seen_ = true;
    } else if (w == "max_trace_level") {
      scene_.settings.max_trace_level = parse_int("max_trace_level");
    } else if (w == "adc_bailout") {
      scene_.settings.adc_bailout = parse_float();
    } else if (w == "ambient_light") {
      scene_.settings.ambient_light = parse_color().rgb;
    } else if (w == "charset") {
      raw_next();
    } else if (w == "noise_generator") {
      *global_noise_generator_ = parse_noise_generator();
    } else if (w == "number_of_waves" || w == "max_intersections" || w == "irid_wavelength" ||
               w == "hf_gray_16") {
      if (w == "irid_wavelength")
        parse_color();
      else if (w != "hf_gray_16" || starts_numeric())
        parse_float();
    } else if (w == "mm_per_unit") {
      scene_.settings.mm_per_unit = parse_float();
    } else if (w == "subsurface") {
      parse_global_subsurface();
    } else if (w == "radiosity") {
      scene_.settings.radiosity = parse_radiosity_block();
    } else if (w == "photons") {
      scene_.settings.photons = parse_global_photons();
    } else {
      fail(t.where, "unknown global_settings keyword '" + w + "'");
    }
  }
}

scene::CameraSpec Parser::parse_camera(const scene::CameraSpec& base) {
  // POV-Ray 3.5+ applies camera modifiers in a fixed order whatever order they are written in:
  // right, direction, angle, up, sky, location, look_at, then transforms (source: parser.cpp,
  // Parse_Camera; reference "Camera"). A declared camera given by name takes only transforms.
  expect("{", "camera");
  scene::CameraSpec cam = base;
  math::Transform transform;
  {
    const Token& t = peek();
    if (t.kind == Token::Kind::identifier) {
      if (const Value* v = lookup(t.text); v && std::holds_alternative<scene::CameraSpec>(v->data)) {
        cam = std::get<scene::CameraSpec>(v->data);
        raw_next();
        for (;;) {
          if (auto step = parse_transform_item()) {
            transform = *step * transform;
            continue;
          }
          expect("}", "camera");
          break;
        }
        cam.location = transform.point(cam.location);
        cam.direction = transform.vector(cam.direction);
        cam.up = transform.vector(cam.up);
        cam.right = transform.vector(cam.right);
        return cam;
      }
    }
  }
  std::optional<math::Vec3> look_at, up, right, sky;
  std::optional<double> angle, v_angle;
  std::optional<math::Vec3> focal_point;
  math::Vec3 sky_v{0, 1, 0};
  // POV-Ray's default focal distance is the direction length as last set by angle or look_at.
  double direction_length = 1;
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      break;
    }
    if (auto step = parse_transform_item()) {
      transform = *step * transform;
      continue;
    }
    if (t.kind != Token::Kind::identifier) fail(t.where, "unexpected '" + t.text + "' in camera");
    const std::string& w = t.text;
    raw_next();
    using Kind = scene::CameraSpec::Kind;
    if (w == "perspective")
      cam.kind = Kind::perspective;
    else if (w == "orthographic")
      cam.kind = Kind::orthographic;
    else if (w == "fisheye")
      cam.kind = Kind::fisheye;
    else if (w == "ultra_wide_angle")
      cam.kind = Kind::ultra_wide_angle;
    else if (w == "omnimax")
      cam.kind = Kind::omnimax;
    else if (w == "panoramic")
      cam.kind = Kind::panoramic;
    else if (w == "spherical")
      cam.kind = Kind::spherical;
    else if (w == "cylinder") {
      const double n = parse_float();
      static constexpr Kind kCylinders[] = {Kind::cylinder1, Kind::cylinder2, Kind::cylinder3,
                                            Kind::cylinder4};
      if (n != std::floor(n) || n < 1 || n > 4) fail(t.where, "cylinder camera type must be 1, 2, 3 or 4");
      cam.kind = kCylinders[static_cast<int>(n) - 1];
    } else if (w == "location")
      cam.location = parse_vector();
    else if (w == "direction")
      cam.direction = parse_vector();
    else if (w == "up")
      up = parse_vector();
    else if (w == "right")
      right = parse_vector();
    else if (w == "sky")
      sky = parse_vector();
    else if (w == "look_at")
      look_at = parse_vector();
    else if (w == "angle") {
      // The spherical camera takes `angle H [, V]`, V defaulting to H/2 (reference "Spherical projection").
      const double a = parse_float();
      if (a < 0) fail(t.where, "negative camera angle");
      angle = a;
      // POV-Ray reads the optional second value with or without the comma.
      if ((accept(",") || cam.kind == Kind::spherical) && starts_numeric()) {
        const double v = parse_float();
        if (v < 0) fail(t.where, "negative vertical camera angle");
        v_angle = v;
      }
    } else if (w == "aperture")
      cam.aperture = parse_float();
    else if (w == "blur_samples") {
      // `blur_samples N` or `blur_samples MIN, MAX` (POV-Ray 3.7 reference "Focal Blur").
      const int first = parse_int("blur_samples");
      if (first <= 0) fail(t.where, "the number of focal blur samples must be positive");
      accept(",");
      const int second = starts_numeric() ? parse_int("blur_samples") : 0;
      if (second == 0) {
        cam.blur_samples = first;
        cam.blur_samples_min = 0;
      } else {
        if (first > second) fail(t.where, "focal blur samples minimum must not be larger than maximum");
        cam.blur_samples_min = first;
        cam.blur_samples = second;
      }
      if (cam.blur_samples > 4096) fail(t.where, "too many focal blur samples (at most 4096)");
    } else if (w == "shutter")
      parse_shutter_block(cam, t);
    else if (w == "focal_point")
      focal_point = parse_vector();
    else if (w == "confidence") {
      const double c = parse_float();
      if (c > 0 && c < 1)
        cam.confidence = c;
      else
        warn(t.where, "confidence must be between 0 and 1; keeping the default");
    } else if (w == "variance") {
      const double v = parse_float();
      if (v >= 0 && v <= 1)
        cam.variance = v;
      else
        warn(t.where, "variance must be between 0 and 1; keeping the default");
    } else if (w == "mesh_camera")
      parse_mesh_camera(cam, t);
    else if (w == "user_defined")
      fail(t.where, "the " + w + " camera is not supported yet");
    else if (w == "normal") {
      warn(t.where, "camera normal is not supported yet; ignored");
      skip_block("normal");
    } else
      fail(t.where, "unknown camera keyword '" + w + "'");
  }
  if (up) cam.up = *up;
  if (right) cam.right = *right;
  if (sky) sky_v = *sky;
  const bool planar =
      cam.kind == scene::CameraSpec::Kind::perspective || cam.kind == scene::CameraSpec::Kind::orthographic;
  if (angle && planar) {
    if (*angle >= 180) fail(peek().where, "camera angle must be below 180 degrees");
    if (*angle > 0 && length_squared(cam.direction) > 0) {
      direction_length = length(cam.right) / std::tan(*angle * math::kPi / 360) / 2;
      cam.direction = normalize(cam.direction) * direction_length;
    }
  } else if (angle && cam.kind == scene::CameraSpec::Kind::spherical) {
    cam.h_angle = *angle;
    cam.v_angle = v_angle ? *v_angle : *angle * 0.5;
  } else if (angle) {
    cam.angle = *angle;
  }
  if (look_at) {
    direction_length = length(cam.direction);
    const double up_length = length(cam.up);
    const double right_length = length(cam.right);
    // Keep the handedness the written vectors had (right-handed cameras use `right -x`).
    const double handedness = dot(cross(cam.up, cam.direction), cam.right);
    math::Vec3 d = *look_at - cam.location;
    if (length_squared(d) < 1e-10) fail(peek().where, "camera location and look_at are the same point");
    d = normalize(d);
    math::Vec3 r = cross(sky_v, d);
    if (length_squared(r) < 1e-20) {
      warn(peek().where, "camera sky is parallel to the viewing direction; keeping the given right vector");
      r = cam.right;
    }
    r = normalize(r);
    cam.up = normalize(cross(d, r)) * up_length;
    cam.direction = d * direction_length;
    cam.right = r * (handedness > 0 ? right_length : -right_length);
  }
  if (cam.kind == scene::CameraSpec::Kind::orthographic && ((!up && !right) || angle)) {
    // POV-Ray sizes an orthographic view like the perspective one at the look_at distance.
    const double k1 = length((look_at ? *look_at : math::Vec3{0, 0, 1}) - cam.location);
    const double k2 = length(cam.direction);
    if (k1 > 1e-10 && k2 > 1e-10) {
      cam.right = cam.right * (k1 / k2);
      cam.up = cam.up * (k1 / k2);
    }
  }
  if (focal_point) {
    cam.focal_point = *focal_point;
    cam.focal_distance = length(*focal_point - cam.location);
  } else if (cam.focal_distance < 0) {
    cam.focal_distance = direction_length;
  }
  if (cam.focal_distance == 0) cam.focal_distance = 1;
  cam.location = transform.point(cam.location);
  cam.direction = transform.vector(cam.direction);
  cam.up = transform.vector(cam.up);
  cam.right = transform.vector(cam.right);
  cam.focal_point = transform.point(cam.focal_point);
  return cam;
}

scene::Scene Parser::finish_scene() {
  if (!conds_.empty())
    fail(conds_.back().where, "this block has no matching #end before the end of the file");
  scene_.settings.language_version = version_;
  return std::move(scene_);
}

}  // namespace snell::sdl
