// fog, media, density and sky_sphere blocks (POV-Ray 3.7 reference, "Atmospheric Effects", "Media",
// "Density"), and their identifiers.
#include <cmath>
#include <optional>

#include "snell/sdl/parser.hpp"
#include "snell/texture/color_map.hpp"
#include "snell/texture/pattern_pigment.hpp"

namespace snell::sdl {

Value Parser::parse_atmospheric_value(const Token& word) {
  // A media or density that uses something unsupported is declared empty; using it drops the media.
  if (word.text == "media") {
    auto media = parse_media_block();
    return Value{media ? std::make_shared<const material::Media>(std::move(*media))
                       : std::shared_ptr<const material::Media>{}};
  }
  if (word.text == "density") {
    auto density = parse_density_block();
    return Value{density ? std::make_shared<const material::Density>(std::move(*density))
                         : std::shared_ptr<const material::Density>{}};
  }
  if (word.text == "fog") return Value{std::make_shared<const scene::Fog>(parse_fog_block())};
  return Value{std::make_shared<const scene::SkySphere>(parse_sky_sphere_block())};
}

scene::Fog Parser::parse_fog_block() {
  expect("{", "fog");
  scene::Fog fog;
  if (auto declared = take_declared<std::shared_ptr<const scene::Fog>>()) fog = **declared;
  auto turbulence = [&]() -> scene::FogTurbulence& {
    if (!fog.turbulence) fog.turbulence = scene::FogTurbulence{};
    return *fog.turbulence;
  };
  for (;;) {
    if (accept("}")) break;
    const Token t = peek();
    if (t.is_word("translate")) {  // POV-Ray: a fog's up vector is a direction; moving it does nothing
      warn(t.where, "a fog cannot be translated; ignored");
      raw_next();
      parse_vector();
      continue;
    }
    if (auto step = parse_transform_item()) {
      fog.up = step->vector(fog.up);
      continue;
    }
    if (t.is_word("color") || t.is_word("colour") || t.is_word("rgb") || t.is_word("rgbf") ||
        t.is_word("rgbt") || t.is_word("rgbft") || t.is_word("red") || t.is_word("green") ||
        t.is_word("blue") || t.is_word("filter") || t.is_word("transmit")) {
      fog.color = parse_color();
      continue;
    }
    if (t.kind != Token::Kind::identifier) {
      // A bare number is the old spelling of `distance`; a colour identifier is the colour.
      if (starts_numeric()) {
        fog.distance = parse_float();
        continue;
      }
      fail(t.where, "unexpected '" + t.text + "' in fog");
    }
    const std::string& w = t.text;
    if (const Value* v = lookup(w)) {
      const auto* n = std::get_if<Numeric>(&v->data);
      if (n && n->color) {
        fog.color = parse_color();
      } else if (n) {
        fog.distance = parse_float();
      } else {
        fail(t.where, "'" + w + "' is a " + v->type_name() + ", not a colour or distance in fog");
      }
      continue;
    }
    raw_next();
    if (w == "distance") {
      fog.distance = parse_float();
    } else if (w == "fog_type") {
      const double type = parse_float();
      if (type == 2)
        fog.type = scene::Fog::Type::ground;
      else if (type == 1)
        fog.type = scene::Fog::Type::constant;
      else
        warn(t.where, "unknown fog type; using constant fog");
    } else if (w == "fog_alt") {
      fog.altitude = parse_float();
    } else if (w == "fog_offset") {
      fog.offset = parse_float();
    } else if (w == "turb_depth") {
      fog.turb_depth = parse_float();
    } else if (w == "up") {
      fog.up = parse_vector();
    } else if (w == "turbulence") {
      turbulence().amount = parse_vector();
    } else if (w == "octaves") {
      turbulence().octaves = std::clamp(static_cast<int>(parse_float()), 1, 10);
    } else if (w == "omega") {
      turbulence().omega = parse_float();
    } else if (w == "lambda") {
      turbulence().lambda = parse_float();
    } else {
      fail(t.where, "unknown fog keyword '" + w + "'");
    }
  }
  if (length_squared(fog.up) == 0) fail(peek().where, "fog up vector has zero length");
  fog.up = normalize(fog.up);
  return fog;
}

std::optional<material::Media> Parser::parse_media_block() {
  expect("{", "media");
  bool supported = true;
  material::Media media;
  // Before 3.5 the default was method 1 with 10 intervals of one sample (POV-Ray parser, Parse_Media).
  if (version_ < 3.5) {
    media.method = 1;
    media.intervals = 10;
    media.min_samples = media.max_samples = 1;
  }
  if (auto declared = take_declared<std::shared_ptr<const material::Media>>()) {
    if (*declared)
      media = **declared;
    else
      supported = false;  // declared from a media this parser could not build
  }
  for (;;) {
    if (accept("}")) break;
    const Token t = peek();
    if (auto step = parse_transform_item()) {
      media = media.transformed(*step);
      continue;
    }
    if (t.kind != Token::Kind::identifier) fail(t.where, "unexpected '" + t.text + "' in media");
    const std::string& w = t.text;
    raw_next();
    if (w == "intervals") {
      media.intervals = static_cast<int>(parse_float());
      if (media.intervals < 1) fail(t.where, "media needs at least one interval");
      if (media.intervals > 10000) fail(t.where, "too many media intervals (at most 10000)");
    } else if (w == "samples") {
      media.min_samples = static_cast<int>(parse_float());
      accept(",");
      media.max_samples = starts_numeric() ? static_cast<int>(parse_float()) : media.min_samples;
      if (media.min_samples < 1) fail(t.where, "media needs at least one sample per interval");
      if (media.max_samples < media.min_samples)
        fail(t.where, "media's maximum samples are fewer than its minimum");
      if (media.max_samples > 10000) fail(t.where, "too many media samples (at most 10000)");
    } else if (w == "method") {
      const double method = parse_float();
      if (method != 1 && method != 2 && method != 3) fail(t.where, "media method must be 1, 2 or 3");
      media.method = static_cast<int>(method);
    } else if (w == "jitter") {
      media.jitter = parse_float();
    } else if (w == "aa_threshold") {
      media.aa_threshold = parse_float();
      if (media.aa_threshold <= 0) fail(t.where, "media aa_threshold must be greater than zero");
    } else if (w == "aa_level") {
      media.aa_level = static_cast<int>(parse_float());
      if (media.aa_level < 1) fail(t.where, "media aa_level must be at least 1");
      if (media.aa_level > 16) fail(t.where, "media aa_level too large (at most 16)");
    } else if (w == "absorption") {
      media.absorption = parse_color().rgb;
    } else if (w == "emission") {
      media.emission = parse_color().rgb;
    } else if (w == "scattering") {
      expect("{", "scattering");
      const double type = parse_float();
      if (type >= 1 && type <= 5 && type == std::floor(type))
        media.phase = static_cast<material::Media::Phase>(static_cast<int>(type));
      else
        warn(t.where, "unknown scattering type; using isotropic scattering");
      accept(",");
      media.scattering = parse_color().rgb;
      for (;;) {
        if (accept("}")) break;
        const Token s = peek();
        if (s.is_word("eccentricity")) {
          raw_next();
          if (media.phase != material::Media::Phase::henyey_greenstein)
            fail(s.where, "eccentricity needs scattering type 5 (Henyey-Greenstein)");
          media.eccentricity = parse_float();
        } else if (s.is_word("extinction")) {
          raw_next();
          media.scattering_extinction = parse_float();
        } else {
          fail(s.where, "unexpected '" + s.text + "' in scattering");
        }
      }
    } else if (w == "confidence") {
      media.confidence = parse_float();
      if (media.confidence < 0 || media.confidence >= 1) fail(t.where, "media confidence must be in [0, 1)");
    } else if (w == "variance") {
      media.variance = parse_float();
    } else if (w == "ratio") {
      media.ratio = parse_float();
    } else if (w == "density") {
      if (auto density = parse_density_block())
        media.densities.push_back(std::move(*density));
      else
        supported = false;
    } else if (w == "collect") {
      parse_bool_optional(true);
    } else {
      fail(t.where, "unknown media keyword '" + w + "'");
    }
  }
  if (!supported) return std::nullopt;
  return media;
}

std::optional<material::Density> Parser::parse_density_block() {
  // A density is a pigment whose colour scales the medium (a declared density may start it, and
  // `density_map` is its colour map); a pattern without a map runs from black at 0 to white at 1 instead of
  // the pigment's default map.
  material::Density density;
  const scene::SourceLocation where = peek().where;
  const size_t frame_count = frames_.size(), cond_count = conds_.size(), start = frames_.back().pos;
  try {
    density.pigment = parse_pigment_block(nullptr);
  } catch (const ParseError& e) {
    // A pattern snell lacks (density_file, crackle, ...) drops the medium with a warning, as unsupported
    // media blocks were before, instead of failing the scene. Other errors stay errors.
    const std::string message = e.what();
    if (message.find("is not supported yet") == std::string::npos || frames_.size() != frame_count ||
        conds_.size() != cond_count)
      throw;
    frames_.back().pos = start;
    frames_.back().injected.reset();
    // The first line of the diagnostic, after its "file:line:col: error: " prefix.
    const size_t at = message.find("error: ");
    const size_t from = at == std::string::npos ? 0 : at + 7;
    warn(where,
         "density: " + message.substr(from, message.find('\n', from) - from) + "; the media is ignored");
    skip_block("density");
    return std::nullopt;
  }
  if (const auto* pattern = dynamic_cast<const texture::PatternPigment*>(density.pigment.get())) {
    texture::PatternSpec spec = pattern->spec();
    if (spec.value_pattern && !spec.color_map && !spec.pigment_map) {
      using E = texture::ColorMap::Entry;
      spec.color_map = texture::ColorMap(
          {E{0.0, material::Rgbft{math::Color(0)}}, E{1.0, material::Rgbft{math::Color(1)}}});
      density.pigment = std::make_shared<texture::PatternPigment>(std::move(spec));
    }
  }
  return density;
}

scene::SkySphere Parser::parse_sky_sphere_block() {
  expect("{", "sky_sphere");
  scene::SkySphere sky;
  if (auto declared = take_declared<std::shared_ptr<const scene::SkySphere>>()) sky = **declared;
  for (;;) {
    if (accept("}")) break;
    const Token t = peek();
    if (t.is_word("pigment")) {
      raw_next();
      sky.pigments.push_back(parse_pigment_block(nullptr));
      continue;
    }
    if (auto step = parse_transform_item()) {
      sky.transform = *step * sky.transform;
      continue;
    }
    if (t.is_word("emission")) {
      raw_next();
      warn(t.where, "sky_sphere emission is not supported yet; ignored");
      parse_color();
      continue;
    }
    fail(t.where, "unexpected '" + t.text + "' in sky_sphere");
  }
  return sky;
}

}  // namespace snell::sdl
