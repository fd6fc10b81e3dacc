// `normal {}` blocks, slope maps and normal maps (POV-Ray 3.7 reference, "Normal", "Slope Maps",
// "Normal Maps"). The pattern part is read exactly as in a pigment (pigment_builder.hpp); what follows a
// pattern's name, if a number, is its bump_size.
#include "snell/sdl/parser.hpp"
#include "snell/sdl/pigment_builder.hpp"
#include "snell/texture/average_normal.hpp"
#include "snell/texture/block_normals.hpp"
#include "snell/texture/bump_map.hpp"
#include "snell/texture/facets.hpp"
#include "snell/texture/object_pattern.hpp"
#include "snell/texture/pattern_normal.hpp"

namespace snell::sdl {

using texture::NormalPtr;

struct Parser::NormalBuilder {
  PigmentBuilder pattern;
  /// A declared normal that is not a pattern normal (moved by transforms after it).
  NormalPtr plain;
  double bump_size = 0.5;
  double accuracy = 0.02;
  std::optional<texture::SlopeMap> slope_map;
  std::vector<std::pair<double, NormalPtr>> normal_map;
  /// `facets` and its size, coords and metric (facets.hpp), a pattern for normals only.
  std::optional<texture::FacetsParams> facets;
  /// `checker normal {A} normal {B}`: one normal per block.
  std::vector<NormalPtr> block_entries;

  void start_from(const NormalPtr& normal) {
    *this = NormalBuilder{};
    const auto* declared = dynamic_cast<const texture::PatternNormal*>(normal.get());
    if (!declared) {
      plain = normal;
      return;
    }
    const texture::NormalSpec& s = declared->spec();
    pattern.start_pattern();
    pattern.spec.value_pattern = s.pattern;
    if (const auto* f = dynamic_cast<const texture::FacetsPattern*>(s.pattern.get())) facets = f->params();
    pattern.spec.wave = s.wave;
    pattern.spec.warps = s.warps;
    pattern.uv_mapping = s.uv_mapping;
    bump_size = s.bump_size;
    accuracy = s.accuracy;
    slope_map = s.slope_map;
    normal_map = s.normal_map;
  }

  /// Null when nothing was said. Throws std::invalid_argument as texture::PatternNormal does.
  NormalPtr build() const {
    if (!pattern.patterned) return plain;
    if (pattern.special == "average") return std::make_shared<texture::AverageNormal>(normal_map);
    texture::PatternSpec ps = pattern.build_spec();
    if (facets) ps.value_pattern = std::make_shared<texture::FacetsPattern>(*facets);
    if (ps.block_pattern && !block_entries.empty())
      return std::make_shared<texture::BlockNormal>(ps.block_pattern, ps.warps, block_entries);
    if (ps.block_pattern) ps.value_pattern = std::make_shared<texture::BlockValuePattern>(ps.block_pattern);
    texture::NormalSpec spec;
    spec.pattern = ps.value_pattern;
    spec.wave = ps.wave;
    spec.warps = ps.warps;
    spec.bump_size = bump_size;
    spec.accuracy = accuracy;
    spec.slope_map = slope_map;
    spec.normal_map = normal_map;
    spec.uv_mapping = pattern.uv_mapping;
    return std::make_shared<texture::PatternNormal>(std::move(spec));
  }
};

NormalPtr Parser::parse_normal_block() {
  const NestingGuard guard(*this, peek().where);
  const scene::SourceLocation where = peek().where;
  expect("{", "normal");
  NormalBuilder builder;
  parse_normal_body(builder, "}");
  try {
    return builder.build();
  } catch (const std::invalid_argument& e) {
    fail(where, std::string("normal: ") + e.what());
  }
}

void Parser::parse_normal_body(NormalBuilder& b, const char* closer) {
  for (;;) {
    const Token t = peek();
    if (t.is_symbol(closer)) {
      raw_next();
      return;
    }
    if (t.kind != Token::Kind::identifier) fail(t.where, "unexpected '" + t.text + "' in normal");
    const std::string& w = t.text;
    if (auto declared = take_declared<NormalPtr>()) {
      b.start_from(*declared);
      continue;
    }
    if (w == "normal" && std::string(closer) == "]") {
      raw_next();
      b.start_from(parse_normal_block());
      continue;
    }
    if (w == "checker" || w == "hexagon" || w == "brick" || w == "object") {
      // Normals may follow, one per block (inside the braces for `object { Obj normal {A} normal {B} }`);
      // brick's size and mortar come later as modifiers.
      raw_next();
      b.pattern.start_pattern();
      b.pattern.brick = w == "brick";
      std::shared_ptr<const texture::BlockPattern> blocks;
      if (w == "object") {
        expect("{", "object pattern");
        blocks = std::make_shared<texture::ObjectPattern>(parse_inside_test());
      } else if (w == "checker") {
        blocks = std::make_shared<texture::CheckerPattern>();
      } else if (w == "hexagon") {
        blocks = std::make_shared<texture::HexagonPattern>();
      } else {
        blocks = std::make_shared<texture::BrickPattern>();
      }
      b.pattern.spec.block_pattern = blocks;
      b.block_entries.clear();
      while (peek().is_word("normal")) {
        raw_next();
        b.block_entries.push_back(parse_normal_block());
        accept(",");
      }
      if (w == "object") expect("}", "object pattern");
      if (b.block_entries.empty() && starts_numeric()) b.bump_size = parse_float();
      continue;
    }
    if (w == "facets") {
      raw_next();
      b.pattern.start_pattern();
      b.pattern.spec.value_pattern = std::make_shared<texture::FacetsPattern>();
      b.facets = texture::FacetsParams{};
      if (starts_numeric()) b.bump_size = parse_float();
      continue;
    }
    if (b.facets && (w == "size" || w == "coords" || w == "metric")) {
      raw_next();
      const double v = parse_float();
      if (w == "size") b.facets->size = v;
      if (w == "coords") b.facets->coords = v;
      if (w == "metric") b.facets->metric = v;
      if (w == "metric" && !(v > 0)) fail(t.where, "facets metric must be positive");
      continue;
    }
    if (parse_pattern_type(b.pattern)) {
      b.facets.reset();
      accept(",");  // `gradient x, 0.5`
      if (starts_numeric()) b.bump_size = parse_float();
      continue;
    }
    if (!b.pattern.patterned) {
      if (auto step = parse_transform_item()) {
        if (b.plain) b.plain = std::make_shared<texture::TransformedNormal>(b.plain, *step);
        continue;
      }
    }
    if (w == "bump_size") {
      raw_next();
      b.bump_size = parse_float();
    } else if (w == "accuracy") {
      raw_next();
      b.accuracy = parse_float();
      if (!(b.accuracy > 0)) fail(t.where, "accuracy must be positive");
    } else if (w == "slope_map") {
      raw_next();
      parse_slope_map(b);
    } else if (w == "normal_map") {
      raw_next();
      parse_normal_map(b);
    } else if (w == "bump_map") {
      // An image's grey levels as heights, bent by pixel-to-pixel steps (bump_map.hpp).
      raw_next();
      auto image = std::dynamic_pointer_cast<const texture::ImageMapPigment>(parse_image_map(&b.bump_size));
      b.pattern.start_pattern();
      b.pattern.spec.value_pattern = std::make_shared<texture::BumpMapPattern>(image);
    } else if (w == "no_bump_scale") {
      raw_next();
    } else if (parse_pattern_modifier(b.pattern)) {
      continue;
    } else {
      fail(t.where, "unexpected '" + w + "' in normal");
    }
  }
}

void Parser::parse_slope_map(NormalBuilder& b) {
  const scene::SourceLocation where = peek().where;
  expect("{", "slope_map");
  std::vector<texture::SlopeMap::Entry> entries;
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      break;
    }
    if (!t.is_symbol("[")) fail(t.where, "expected '[' or '}' in slope_map, found '" + t.text + "'");
    raw_next();
    const double value = parse_float();
    accept(",");
    const Numeric hs = parse_numeric();
    entries.push_back({value, hs.v[0], hs.size == 1 ? 0.0 : hs.v[1]});
    expect("]", "slope_map entry");
  }
  if (entries.empty()) fail(where, "slope_map has no entries");
  b.slope_map.emplace(std::move(entries));
}

void Parser::parse_normal_map(NormalBuilder& b) {
  const scene::SourceLocation where = peek().where;
  expect("{", "normal_map");
  std::vector<std::pair<double, NormalPtr>> entries;
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      break;
    }
    if (!t.is_symbol("[")) fail(t.where, "expected '[' or '}' in normal_map, found '" + t.text + "'");
    raw_next();
    const double value = parse_map_entry_value(b.pattern.special == "average");
    accept(",");
    NormalBuilder entry;
    parse_normal_body(entry, "]");
    NormalPtr normal;
    try {
      normal = entry.build();
    } catch (const std::invalid_argument& e) {
      fail(t.where, std::string("normal_map entry: ") + e.what());
    }
    // An entry without a pattern leaves the normal as it is: a flat normal.
    if (!normal) normal = std::make_shared<texture::FlatNormal>();
    entries.emplace_back(value, std::move(normal));
  }
  if (entries.empty()) fail(where, "normal_map has no entries");
  b.normal_map = std::move(entries);
}

}  // namespace snell::sdl
