// Pattern pigments, colour maps and pigment maps (POV-Ray 3.7 reference, "Pigment", "Patterns",
// "Color Maps", "Pigment Maps", "Pattern Modifiers"). The parser fills a PigmentBuilder and turns it into
// a texture::PatternPigment (or keeps a plain pigment when no pattern was named).
#include <algorithm>
#include <stdexcept>

#include "snell/sdl/parser.hpp"
#include "snell/sdl/pigment_builder.hpp"
#include "snell/texture/aoi_pattern.hpp"
#include "snell/texture/cellular_patterns.hpp"
#include "snell/texture/function_pattern.hpp"
#include "snell/texture/image_pattern.hpp"
#include "snell/texture/noise_patterns.hpp"
#include "snell/texture/object_pattern.hpp"
#include "snell/texture/pigment_pattern.hpp"
#include "snell/texture/polygon_block_patterns.hpp"
#include "snell/texture/ripple_patterns.hpp"
#include "snell/texture/slope_pattern.hpp"
#include "snell/texture/spiral_patterns.hpp"
#include "snell/texture/tiling_patterns.hpp"
#include "snell/texture/value_patterns.hpp"

namespace snell::sdl {

using texture::PigmentPtr;

namespace {

material::Rgbft rgb(double r, double g, double b) {
  return material::Rgbft{math::Color(r, g, b), 0, 0};
}

PigmentPtr solid(const material::Rgbft& c) {
  return std::make_shared<material::SolidPigment>(c);
}

/// Patterns POV-Ray has that snell does not evaluate yet: named in the error rather than "unexpected".
bool is_unsupported_pattern(const std::string& w) {
  static const char* const patterns[] = {"pavement"};
  for (const char* p : patterns)
    if (w == p) return true;
  return false;
}

}  // namespace

std::shared_ptr<const material::Pigment> Parser::parse_pigment_block(
    const std::shared_ptr<const material::Pigment>& base) {
  const scene::SourceLocation where = peek().where;
  const NestingGuard guard(*this, where);
  expect("{", "pigment");
  PigmentBuilder builder;
  builder.start_from(base);
  parse_pigment_body(builder, "}");
  PigmentPtr pigment;
  try {
    pigment = builder.build();
  } catch (const std::invalid_argument& e) {
    fail(where, e.what());  // an inconsistent pattern: no map for `average`, a wrong entry count...
  }
  return pigment ? pigment : solid(material::Rgbft{});
}

std::shared_ptr<const texture::ValuePattern> Parser::parse_function_pattern(const Token& keyword) {
  const std::shared_ptr<const function::Function> f = parse_function_block();
  if (f->arity() != 3) fail(keyword.where, "a function pattern takes the three arguments x, y, z");
  // Evaluate once here so that a function snell cannot evaluate is a parse error, not a render failure.
  try {
    const double origin[3] = {0, 0, 0};
    f->call(origin);
  } catch (const std::exception& e) {
    fail(keyword.where, e.what());
  }
  return std::make_shared<texture::FunctionPattern>(f);
}

void Parser::parse_pigment_body(PigmentBuilder& b, const char* closer) {
  for (;;) {
    const Token t = peek();
    if (t.is_symbol(closer)) {
      raw_next();
      return;
    }
    if (t.kind == Token::Kind::identifier) {
      if (const Value* v = lookup(t.text)) {
        if (const auto* p = std::get_if<std::shared_ptr<const material::Pigment>>(&v->data)) {
          const PigmentPtr copy = *p;
          raw_next();
          b.start_from(copy);
          continue;
        }
        if (const auto* d = std::get_if<std::shared_ptr<const material::Density>>(&v->data)) {
          // `density { DeclaredDensity ... }`; a density declared from an unsupported pattern is empty.
          if (!*d) fail(t.where, "density '" + t.text + "' uses a pattern that is not supported yet");
          const PigmentPtr copy = (*d)->pigment;
          raw_next();
          b.start_from(copy);
          continue;
        }
      }
      if (t.text == "image_map") {
        raw_next();
        b.start_from(parse_image_map());
        continue;
      }
      if (parse_pattern_type(b)) continue;
      if (is_unsupported_pattern(t.text)) fail(t.where, "pattern '" + t.text + "' is not supported yet");
      if (t.text == "facets") fail(t.where, "the facets pattern can only be used in a normal");
      if (parse_pattern_modifier(b)) continue;
      if (t.text == "pigment" && std::string(closer) == "]") {
        // `[v pigment { ... }]` in a pigment_map: accepted like the bare body.
        raw_next();
        b.start_from(parse_pigment_block(nullptr));
        continue;
      }
    }
    if (starts_numeric()) {
      b.start_from(solid(parse_color()));
      continue;
    }
    fail(t.where, "unexpected '" + t.text + "' in pigment");
  }
}

bool Parser::parse_pattern_type(PigmentBuilder& b) {
  const Token t = peek();
  const std::string& w = t.text;
  std::shared_ptr<const texture::ValuePattern> value;
  std::string special;
  if (w == "gradient") {
    raw_next();
    const math::Vec3 direction = parse_vector();
    value = std::make_shared<texture::GradientPattern>(direction);
  } else if (w == "onion") {
    value = std::make_shared<texture::OnionPattern>();
  } else if (w == "spherical") {
    value = std::make_shared<texture::SphericalPattern>();
  } else if (w == "cylindrical") {
    value = std::make_shared<texture::CylindricalPattern>();
  } else if (w == "planar") {
    value = std::make_shared<texture::PlanarPattern>();
  } else if (w == "boxed") {
    value = std::make_shared<texture::BoxedPattern>();
  } else if (w == "radial") {
    value = std::make_shared<texture::RadialPattern>();
  } else if (w == "leopard") {
    value = std::make_shared<texture::LeopardPattern>();
  } else if (w == "slope") {
    raw_next();
    value = parse_slope();
  } else if (w == "image_pattern") {
    raw_next();
    auto image = std::dynamic_pointer_cast<const texture::ImageMapPigment>(parse_image_map());
    value = std::make_shared<texture::ImagePattern>(image);
  } else if (w == "cells") {
    value = std::make_shared<texture::CellsPattern>();
  } else if (w == "aoi") {
    value = std::make_shared<texture::AoiPattern>();
  } else if (w == "tiling") {
    raw_next();
    const Token number = peek();
    const int n = static_cast<int>(parse_float());
    if (!texture::TilingPattern::supported(n))
      fail(number.where, "tiling " + std::to_string(n) + " is not supported yet (snell has tilings 1 to 5)");
    value = std::make_shared<texture::TilingPattern>(n);
  } else if (w == "function") {
    raw_next();
    value = parse_function_pattern(t);
  } else if (w == "potential") {
    raw_next();
    value = parse_potential_pattern();
  } else if (w == "pigment_pattern") {
    raw_next();
    value = std::make_shared<texture::PigmentPattern>(parse_pigment_block(nullptr));
  } else if (w == "marble" || w == "wood" || w == "agate" || w == "crackle" || w == "quilted" ||
             w == "ripples" || w == "waves" || w == "spiral1" || w == "spiral2" || w == "mandel" ||
             w == "julia" || w == "average" || w == "bozo" || w == "spotted" || w == "granite" ||
             w == "wrinkles" || w == "bumps" || w == "dents" || w == "density_file" || w == "magnet") {
    value = std::make_shared<texture::GranitePattern>();  // replaced in build_spec(), with its parameters
    special = w == "spotted" ? "bozo" : w;
  }
  if (value) {
    if (w != "gradient" && w != "image_pattern" && w != "slope" && w != "function" &&
        w != "pigment_pattern" && w != "potential" && w != "tiling")
      raw_next();
    b.start_pattern();
    b.spec.value_pattern = std::move(value);
    b.special = special;
    b.noise = texture::NoiseChoice(global_noise_generator_);
    if (w == "spiral1" || w == "spiral2") b.arms = parse_float();
    if (w == "density_file") {
      const Token type = peek();
      if (!type.is_word("df3")) fail(type.where, "expected 'df3' after density_file");
      raw_next();
      const Token file_token = peek();
      const std::string file = parse_string();
      const std::filesystem::path path = find_image_file(file_token, file);
      try {
        b.density_grid = std::make_shared<const texture::DensityGrid>(texture::read_df3(path));
      } catch (const std::runtime_error& e) {
        fail(file_token.where, "cannot read density file \"" + file + "\": " + e.what());
      }
    }
    if (w == "magnet") parse_magnet_head(b);
    if (w == "julia") {
      const Numeric c = parse_numeric();
      b.julia_real = c.v[0];
      b.julia_imaginary = c.size == 1 ? c.v[0] : c.v[1];
      accept(",");
    }
    if (w == "mandel" || w == "julia" || w == "magnet") {
      const double n = parse_float();
      if (!(n >= 1 && n <= 1e6)) fail(t.where, "the iteration count must be between 1 and 1000000");
      b.fractal.max_iterations = static_cast<int>(n);
    }
    // POV-Ray's per-pattern defaults (pattern.cpp default maps and waves).
    using E = texture::ColorMap::Entry;
    if (w == "marble" || w == "wood" || w == "spiral1" || w == "spiral2")
      b.spec.wave.wave = texture::Wave::triangle;
    if (w == "marble")
      b.spec.color_map =
          texture::ColorMap({E{0.0, rgb(0.9, 0.8, 0.8)}, E{0.9, rgb(0.9, 0.08, 0.08)}, E{0.9, rgb(0, 0, 0)}});
    if (w == "wood")
      b.spec.color_map = texture::ColorMap({E{0.6, rgb(0.666, 0.312, 0.2)}, E{0.6, rgb(0.4, 0.1333, 0.066)}});
    if (w == "agate")
      b.spec.color_map = texture::ColorMap({E{0.0, rgb(1, 1, 1)}, E{0.5, rgb(0.95, 0.75, 0.5)},
                                            E{0.5, rgb(0.9, 0.7, 0.5)}, E{0.6, rgb(0.9, 0.7, 0.4)},
                                            E{0.6, rgb(1.0, 0.7, 0.4)}, E{1.0, rgb(0.6, 0.3, 0.0)}});
    if (w == "bozo" || w == "spotted")
      b.spec.color_map =
          texture::ColorMap({E{0.4, rgb(1, 1, 1)}, E{0.4, rgb(0, 1, 0)}, E{0.6, rgb(0, 1, 0)},
                             E{0.6, rgb(0, 0, 1)}, E{0.8, rgb(0, 0, 1)}, E{0.8, rgb(1, 0, 0)}});
    if (w == "radial")
      b.spec.color_map = texture::ColorMap(
          {E{0.0, rgb(0, 1, 1)}, E{0.333, rgb(1, 1, 0)}, E{0.666, rgb(1, 0, 1)}, E{1.0, rgb(0, 1, 1)}});
    return true;
  }

  // Block patterns: up to block_count entries (colours or pigment bodies) follow, commas optional;
  // entries left out take POV-Ray's defaults (pattern.cpp default maps).
  std::vector<material::Rgbft> defaults;
  std::shared_ptr<const texture::BlockPattern> block;
  if (w == "checker") {
    block = std::make_shared<texture::CheckerPattern>();
    defaults = {rgb(0, 0, 1), rgb(0, 1, 0)};
  } else if (w == "hexagon") {
    block = std::make_shared<texture::HexagonPattern>();
    defaults = {rgb(0, 0, 1), rgb(0, 1, 0), rgb(1, 0, 0)};
  } else if (w == "brick") {
    block = std::make_shared<texture::BrickPattern>();
    defaults = {rgb(0.5, 0.5, 0.5), rgb(0.6, 0.15, 0.15)};
  } else if (auto polygon = texture::make_polygon_block_pattern(w)) {
    block = polygon;
    defaults = {rgb(1, 0, 0), rgb(0, 1, 0), rgb(0, 0, 1), rgb(1, 1, 0), rgb(0, 1, 1), rgb(1, 0, 1)};
    defaults.resize(static_cast<size_t>(block->block_count()));
  } else if (w == "object") {
    // `object { Obj [A [, B]] }`: A outside the object, B inside.
    raw_next();
    expect("{", "object pattern");
    block = std::make_shared<texture::ObjectPattern>(parse_inside_test());
    defaults = {rgb(0, 0, 0), rgb(1, 1, 1)};
  } else {
    return false;
  }
  if (w != "object") raw_next();
  b.start_pattern();
  b.brick = w == "brick";
  b.spec.block_pattern = block;
  for (size_t i = 0; i < defaults.size(); ++i) {
    if (i > 0 && peek().is_symbol(",")) raw_next();
    const Token& e = peek();
    if (e.is_word("pigment")) {
      raw_next();
      b.spec.block_entries.push_back(parse_pigment_block(nullptr));
      continue;
    }
    if (e.kind == Token::Kind::identifier) {
      if (const Value* v = lookup(e.text)) {
        if (const auto* p = std::get_if<std::shared_ptr<const material::Pigment>>(&v->data)) {
          const PigmentPtr copy = *p;
          raw_next();
          b.spec.block_entries.push_back(copy);
          continue;
        }
      }
    }
    if (!starts_numeric()) break;
    b.spec.block_entries.push_back(solid(parse_color()));
  }
  for (size_t i = b.spec.block_entries.size(); i < defaults.size(); ++i)
    b.spec.block_entries.push_back(solid(defaults[i]));
  if (w == "object") expect("}", "object pattern");
  return true;
}

bool Parser::parse_pattern_modifier(PigmentBuilder& b) {
  const Token t = peek();
  if (t.kind != Token::Kind::identifier) return false;
  if (auto step = parse_transform_item()) {
    b.transform(*step);
    return true;
  }
  const std::string& w = t.text;
  auto need_value_pattern = [&] {
    if (!b.patterned || !b.spec.value_pattern)
      fail(t.where, "'" + w + "' needs a value pattern (gradient, onion, spherical, ...) before it");
  };
  auto set_wave = [&](texture::Wave wave) {
    raw_next();
    b.spec.wave.wave = wave;
  };
  if (w == "color_map" || w == "colour_map") {
    raw_next();
    need_value_pattern();
    b.spec.color_map = *parse_color_map();
    b.pigment_entries.clear();
  } else if (w == "pigment_map" || w == "density_map") {
    // A density_map's entries are colours or densities: read as a pigment map of either.
    raw_next();
    need_value_pattern();
    b.pigment_entries = parse_pigment_map(b.special == "average")->entries();
    b.spec.color_map.reset();
  } else if (w == "ramp_wave") {
    set_wave(texture::Wave::ramp);
  } else if (w == "triangle_wave") {
    set_wave(texture::Wave::triangle);
  } else if (w == "sine_wave") {
    set_wave(texture::Wave::sine);
  } else if (w == "scallop_wave") {
    set_wave(texture::Wave::scallop);
  } else if (w == "cubic_wave") {
    set_wave(texture::Wave::cubic);
  } else if (w == "poly_wave") {
    set_wave(texture::Wave::poly);
    if (starts_numeric()) b.spec.wave.exponent = parse_float();
  } else if (w == "frequency") {
    raw_next();
    b.spec.wave.frequency = parse_float();
  } else if (w == "phase") {
    raw_next();
    b.spec.wave.phase = parse_float();
  } else if (w == "turbulence") {
    raw_next();
    const Numeric n = parse_numeric();
    b.turbulence_params().amount = n.size == 1 ? math::Vec3{n.x(), n.x(), n.x()} : n.vec3();
  } else if (w == "octaves") {
    raw_next();
    // POV-Ray clips octaves to 1..10.
    b.turbulence_params().octaves = std::clamp(parse_int("octaves"), 1, 10);
  } else if (w == "omega") {
    raw_next();
    b.turbulence_params().omega = parse_float();
  } else if (w == "lambda") {
    raw_next();
    b.turbulence_params().lambda = parse_float();
  } else if (w == "brick_size") {
    raw_next();
    const Numeric n = parse_numeric();
    const math::Vec3 size = n.size == 1 ? math::Vec3{n.x(), n.x(), n.x()} : n.vec3();
    if (!b.brick) fail(t.where, "brick_size is only for the brick pattern");
    if (!(size.x > 0 && size.y > 0 && size.z > 0)) fail(t.where, "brick_size must be positive");
    b.brick_size = size;
  } else if (w == "mortar") {
    raw_next();
    const double mortar = parse_float();
    if (!b.brick) fail(t.where, "mortar is only for the brick pattern");
    if (mortar < 0) fail(t.where, "mortar must not be negative");
    b.mortar = mortar;
  } else if (w == "warp") {
    raw_next();
    parse_warp(b);
  } else if (w == "form" || w == "metric" || w == "offset" || w == "solid") {
    raw_next();
    if (b.special != "crackle") fail(t.where, "'" + w + "' is only for the crackle pattern");
    if (w == "form") b.crackle.form = parse_vector();
    if (w == "metric") b.crackle.metric = parse_float();
    if (w == "offset") b.crackle.offset = parse_float();
    if (w == "solid") b.crackle.solid = true;
    if (!(b.crackle.metric > 0)) fail(t.where, "crackle metric must be positive");
  } else if (w == "interior" || w == "exterior" || w == "exponent") {
    raw_next();
    if (w == "exponent" ? b.special != "mandel" && b.special != "julia"
                        : b.special != "mandel" && b.special != "julia" && b.special != "magnet")
      fail(t.where, "'" + w + "' is only for mandel and julia" + (w == "exponent" ? "" : " and magnet"));
    const double type = parse_float();
    if (w == "exponent") {
      // POV-Ray falls back to 2 with a warning outside 2..33 (parser_materials.cpp, kFractalMaxExponent).
      const int exponent = static_cast<int>(type);
      b.fractal.exponent = exponent >= 2 && exponent <= 33 ? exponent : 2;
      if (exponent < 2 || exponent > 33) warn(t.where, "fractal exponents are 2 to 33: using 2");
      return true;
    }
    accept(",");
    const double factor = parse_float();
    if (type < 0 || type > (w == "interior" ? 6 : 8))
      fail(t.where, w + " types are 0 to " + (w == "interior" ? "6" : "8"));
    (w == "interior" ? b.fractal.interior_type : b.fractal.exterior_type) = static_cast<int>(type);
    (w == "interior" ? b.fractal.interior_factor : b.fractal.exterior_factor) = factor;
  } else if (w == "control0" || w == "control1") {
    raw_next();
    if (b.special != "quilted") fail(t.where, "'" + w + "' is only for the quilted pattern");
    (w == "control0" ? b.control0 : b.control1) = parse_float();
  } else if (w == "interpolate" && b.special == "density_file") {
    raw_next();
    b.density_interpolation = static_cast<int>(parse_float());
  } else if (w == "agate_turb") {
    raw_next();
    b.agate_turb = parse_float();
  } else if (w == "uv_mapping") {
    raw_next();
    b.uv_mapping = true;
  } else if (w == "quick_color" || w == "quick_colour") {
    raw_next();
    parse_color();
  } else if (w == "noise_generator") {
    raw_next();
    b.noise = texture::NoiseChoice(std::make_shared<const texture::NoiseGenerator>(parse_noise_generator()));
  } else {
    return false;
  }
  return true;
}

void Parser::parse_magnet_head(PigmentBuilder& b) {
  // `magnet 1|2 mandel n` or `magnet 1|2 julia <c>, n` (the iteration count is read by the caller).
  const Token type = peek();
  const double n = parse_float();
  if (n != 1 && n != 2) fail(type.where, "magnet type must be 1 or 2");
  b.magnet.type = static_cast<int>(n);
  const Token form = peek();
  if (!form.is_word("mandel") && !form.is_word("julia"))
    fail(form.where, "expected 'mandel' or 'julia' after the magnet type");
  raw_next();
  b.magnet.julia = form.is_word("julia");
  if (b.magnet.julia) {
    const Numeric c = parse_numeric();
    b.magnet.c_real = c.v[0];
    b.magnet.c_imaginary = c.size == 1 ? c.v[0] : c.v[1];
    accept(",");
  }
}

texture::NoiseGenerator Parser::parse_noise_generator() {
  const scene::SourceLocation where = peek().where;
  const double n = parse_float();
  if (n != 1 && n != 2 && n != 3) fail(where, "noise_generator must be 1, 2 or 3");
  return static_cast<texture::NoiseGenerator>(static_cast<int>(n));
}

std::shared_ptr<const texture::ValuePattern> Parser::parse_slope() {
  texture::SlopeParams params;
  // The 3.5 form `slope <d>` or the 3.7 block `slope { <d> [, lo, hi] [altitude <a> [, lo, hi]] }`.
  if (!accept("{")) {
    params.direction = parse_vector();
    return std::make_shared<texture::SlopePattern>(params);
  }
  params.direction = parse_vector();
  if (accept(",")) {
    params.low = parse_float();
    expect(",", "slope");
    params.high = parse_float();
  }
  if (peek().is_word("altitude")) {
    raw_next();
    params.altitude = parse_vector();
    if (accept(",")) {
      params.altitude_low = parse_float();
      expect(",", "slope altitude");
      params.altitude_high = parse_float();
    }
  }
  expect("}", "slope");
  return std::make_shared<texture::SlopePattern>(params);
}

std::shared_ptr<const texture::ColorMap> Parser::parse_color_map() {
  // `color_map Ident` (old form) or `color_map { [Ident] entries }`.
  if (auto declared = take_declared<std::shared_ptr<const texture::ColorMap>>()) return *declared;
  const scene::SourceLocation where = peek().where;
  expect("{", "color_map");
  std::vector<texture::ColorMap::Entry> entries;
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      break;
    }
    if (auto declared = take_declared<std::shared_ptr<const texture::ColorMap>>()) {
      entries = (*declared)->entries();
      continue;
    }
    if (!t.is_symbol("[")) fail(t.where, "expected '[' or '}' in color_map, found '" + t.text + "'");
    raw_next();
    const double v1 = parse_float();
    accept(",");
    if (peek().is_symbol("]")) fail(peek().where, "color_map entry needs a colour after its value");
    const Numeric second = parse_numeric();
    if (second.size == 1 && !second.color && !peek().is_symbol("]")) {
      // The old form `[v1, v2 color c1 color c2]`: a band from c1 at v1 to c2 at v2.
      accept(",");
      const material::Rgbft c1 = parse_color();
      accept(",");
      const material::Rgbft c2 = parse_color();
      entries.emplace_back(v1, c1);
      entries.emplace_back(second.x(), c2);
    } else {
      // Promoted as parse_color does: a float fills every component, a short vector is padded with 0.
      Numeric c = second;
      if (c.size == 1) c.v.fill(c.v[0]);
      for (int i = c.size == 1 ? 5 : c.size; i < 5; ++i) c.v[static_cast<size_t>(i)] = 0;
      entries.emplace_back(v1, material::Rgbft{{c.v[0], c.v[1], c.v[2]}, c.v[3], c.v[4]});
    }
    expect("]", "color_map entry");
  }
  if (entries.empty()) fail(where, "color_map has no entries");
  return std::make_shared<texture::ColorMap>(std::move(entries));
}

double Parser::parse_map_entry_value(bool average) {
  if (!average) return parse_float();
  // A colour keyword begins the entry's pigment, not a weight.
  const Token& t = peek();
  const bool colour = t.is_word("rgb") || t.is_word("rgbf") || t.is_word("rgbt") || t.is_word("rgbft") ||
                      t.is_word("color") || t.is_word("colour");
  return colour || !starts_numeric() ? 1.0 : parse_float();
}

std::shared_ptr<const texture::PigmentMap> Parser::parse_pigment_map(bool average) {
  if (auto declared = take_declared<std::shared_ptr<const texture::PigmentMap>>()) return *declared;
  const scene::SourceLocation where = peek().where;
  expect("{", "pigment_map");
  std::vector<texture::PigmentMap::Entry> entries;
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      break;
    }
    if (auto declared = take_declared<std::shared_ptr<const texture::PigmentMap>>()) {
      entries = (*declared)->entries();
      continue;
    }
    if (!t.is_symbol("[")) fail(t.where, "expected '[' or '}' in pigment_map, found '" + t.text + "'");
    raw_next();
    const double value = parse_map_entry_value(average);
    accept(",");
    PigmentBuilder entry;
    parse_pigment_body(entry, "]");
    PigmentPtr pigment = entry.build();
    if (!pigment) pigment = solid(material::Rgbft{});
    entries.emplace_back(value, std::move(pigment));
  }
  if (entries.empty()) fail(where, "pigment_map has no entries");
  return std::make_shared<texture::PigmentMap>(std::move(entries));
}

}  // namespace snell::sdl
