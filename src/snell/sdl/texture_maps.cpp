// Patterned textures (POV-Ray 3.7 reference, "Texture Maps", "Patterned Textures"):
//   texture { gradient x texture_map { [0 T_A] [1 pigment {..} finish {..}] } turbulence 0.2 }
//   texture { checker texture { T_A } texture { T_B } }
// The pattern is read as in a pigment (pigment_builder.hpp); transforms in the block move the whole
// texture, entries included (they are applied to the texture itself in materials.cpp).
#include <utility>

#include "snell/sdl/parser.hpp"
#include "snell/sdl/pigment_builder.hpp"
#include "snell/texture/average_texture.hpp"
#include "snell/texture/object_pattern.hpp"
#include "snell/texture/polygon_block_patterns.hpp"
#include "snell/texture/texture_map.hpp"

namespace snell::sdl {

bool Parser::parse_texture_pattern(TexturePatternBuilder& b) {
  const Token t = peek();
  const std::string& w = t.text;
  if (w == "checker" || w == "hexagon" || w == "brick" || w == "object" ||
      texture::make_polygon_block_pattern(w)) {
    raw_next();
    b = TexturePatternBuilder{};
    b.active = true;
    b.pattern.start_pattern();
    b.pattern.brick = w == "brick";
    // `object { Obj texture {outside} texture {inside} }` (object_pattern.hpp).
    if (w == "object") expect("{", "object pattern");
    if (w == "object")
      b.pattern.spec.block_pattern = std::make_shared<texture::ObjectPattern>(parse_inside_test());
    if (w == "checker") b.pattern.spec.block_pattern = std::make_shared<texture::CheckerPattern>();
    if (w == "hexagon") b.pattern.spec.block_pattern = std::make_shared<texture::HexagonPattern>();
    if (w == "brick") b.pattern.spec.block_pattern = std::make_shared<texture::BrickPattern>();
    if (auto polygon = texture::make_polygon_block_pattern(w)) b.pattern.spec.block_pattern = polygon;
    const int count = b.pattern.spec.block_pattern->block_count();
    for (int i = 0; i < count; ++i) {
      if (i > 0) accept(",");
      if (!peek().is_word("texture")) break;
      raw_next();
      b.blocks.push_back(parse_texture_block());
    }
    if (static_cast<int>(b.blocks.size()) != count)
      fail(t.where, "'" + w + "' in a texture needs " + std::to_string(count) + " texture {} entries");
    if (w == "object") expect("}", "object pattern");
    return true;
  }
  if (w == "tiles") {
    // The old form of a checker of textures: `tiles { texture {A}.. tile2 texture {B}.. }`.
    raw_next();
    b = TexturePatternBuilder{};
    b.active = true;
    b.pattern.start_pattern();
    b.pattern.spec.block_pattern = std::make_shared<texture::CheckerPattern>();
    expect("{", "tiles");
    for (int tile = 0; tile < 2; ++tile) {
      const Token at = peek();
      if (tile == 1) {
        if (!at.is_word("tile2")) fail(at.where, "expected 'tile2' in tiles, found '" + at.text + "'");
        raw_next();
      }
      std::shared_ptr<const material::Texture> layers;
      while (peek().is_word("texture")) {
        raw_next();
        layers = material::Texture::layered(parse_texture_block(), layers);
      }
      if (!layers) fail(at.where, "tiles needs a texture {} for each tile");
      b.blocks.push_back(layers);
    }
    // POV-Ray's Parse_Tiles puts the first texture on the odd checker cells and tile2 on the even
    // ones ("first tile is 1, 2nd tile is 0 to keep compatible with old tiles").
    std::swap(b.blocks[0], b.blocks[1]);
    expect("}", "tiles");
    return true;
  }
  if (w == "material_map") {
    raw_next();
    b = TexturePatternBuilder{};
    b.active = true;
    b.material_map = parse_material_map();
    return true;
  }
  if (w == "texture_map") {
    raw_next();
    if (!b.active || !b.pattern.spec.value_pattern)
      fail(t.where, "texture_map needs a value pattern (gradient, bozo, ...) before it");
    const scene::SourceLocation where = peek().where;
    expect("{", "texture_map");
    b.map.clear();
    for (;;) {
      const Token e = peek();
      if (e.is_symbol("}")) {
        raw_next();
        break;
      }
      if (!e.is_symbol("[")) fail(e.where, "expected '[' or '}' in texture_map, found '" + e.text + "'");
      raw_next();
      const double value = parse_map_entry_value(b.pattern.special == "average");
      accept(",");
      const NestingGuard guard(*this, e.where);
      b.map.emplace_back(value, parse_texture_body("]"));
    }
    if (b.map.empty()) fail(where, "texture_map has no entries");
    return true;
  }
  if (t.kind != Token::Kind::identifier) return false;
  if (w == "pigment" || w == "normal" || w == "finish" || w == "texture") return false;
  const bool was_active = b.active;
  if (parse_pattern_type(b.pattern)) {
    b.map.clear();
    b.blocks.clear();
    b.active = true;
    return true;
  }
  return was_active && parse_pattern_modifier(b.pattern);
}

void Parser::finish_texture_pattern(const TexturePatternBuilder& b, material::Texture& texture,
                                    const scene::SourceLocation& where) {
  if (b.material_map) {
    texture.selector = b.material_map;
    return;
  }
  if (b.pattern.special == "average") {
    if (b.map.empty()) fail(where, "an average texture needs a texture_map");
    try {
      texture::average_textures(b.map, texture);
    } catch (const std::invalid_argument& e) {
      fail(where, std::string("average texture: ") + e.what());
    }
    return;
  }
  texture::PatternSpec spec = b.pattern.build_spec();
  if (spec.value_pattern && b.map.empty()) fail(where, "a patterned texture needs a texture_map");
  try {
    texture.selector = std::make_shared<texture::PatternTextureSelector>(std::move(spec), b.map, b.blocks);
  } catch (const std::invalid_argument& e) {
    fail(where, std::string("texture: ") + e.what());
  }
}

}  // namespace snell::sdl
