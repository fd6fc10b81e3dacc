// Generated height fields: `height_field { diamond_square { size 513 roughness 0.6 seed 7 } ... }` and
// `fbm { }`, `ridged { }`, `midpoint { }` in its place (procedural/terrain.hpp). Heights are normalised to
// [0, 1] like an image's; `export "file.png"` (16-bit grey) or `"file.exr"` writes them out as a height map
// that `height_field { png "file.png" }` reads back. See docs/procedural.md.
#include "snell/geometry/height_field.hpp"
#include "snell/io/image_file.hpp"
#include "snell/procedural/terrain.hpp"
#include "snell/sdl/parser.hpp"

namespace snell::sdl {

namespace {

/// The rows of a midpoint profile, twice: a ridge that runs along z.
procedural::HeightMap extruded_profile(const std::vector<double>& profile) {
  procedural::HeightMap map{static_cast<int>(profile.size()), 2, profile};
  map.values.insert(map.values.end(), profile.begin(), profile.end());
  return map;
}

void export_height_map(const procedural::HeightMap& map, const std::filesystem::path& path) {
  io::Image image(map.width, map.depth);
  // Image rows run top to bottom and the height field reads the bottom row as z = 0.
  for (int k = 0; k < map.depth; ++k)
    for (int i = 0; i < map.width; ++i) {
      const auto v = static_cast<float>(map.at(i, k));
      const std::size_t at = image.index(i, map.depth - 1 - k);
      image.rgb[at] = image.rgb[at + 1] = image.rgb[at + 2] = v;
    }
  io::WriteOptions options;
  options.encoding.passthrough = true;  // heights, not colours: no transfer curve
  options.bits = 16;
  io::write_image(path, image, options);
}

}  // namespace

bool Parser::parse_terrain_if_any(geometry::HeightGrid& grid) {
  const Token kind = peek();
  if (!kind.is_word("diamond_square") && !kind.is_word("fbm") && !kind.is_word("ridged") &&
      !kind.is_word("midpoint"))
    return false;
  raw_next();
  expect("{", kind.text.c_str());
  const bool noise = kind.is_word("fbm") || kind.is_word("ridged");
  procedural::NoiseTerrain s;
  s.size = noise ? 257 : 513;
  s.roughness = noise ? 0.8 : 0.5;
  std::string export_file;
  scene::SourceLocation export_where;
  for (;;) {
    const Token t = raw_next();
    if (t.is_symbol("}")) break;
    const auto number = [&] { return parse_float(); };
    if (t.is_word("size")) {
      s.size = parse_int("size", 2, procedural::kMaxTerrainSize);
    } else if (t.is_word("roughness")) {
      s.roughness = number();
    } else if (t.is_word("seed")) {
      s.seed = static_cast<std::uint64_t>(parse_int("seed", 0));
    } else if (t.is_word("export")) {
      export_where = peek().where;
      export_file = parse_string();
    } else if (noise && t.is_word("octaves")) {
      s.octaves = parse_int("octaves", 1, 30);
    } else if (noise && t.is_word("lacunarity")) {
      s.lacunarity = number();
    } else if (noise && t.is_word("frequency")) {
      s.frequency = number();
    } else if (kind.is_word("ridged") && t.is_word("offset")) {
      s.offset = number();
    } else if (kind.is_word("ridged") && t.is_word("gain")) {
      s.gain = number();
    } else {
      fail(t.where, "unexpected '" + t.text + "' in " + kind.text);
    }
  }
  procedural::HeightMap map;
  try {
    if (kind.is_word("diamond_square")) map = procedural::diamond_square(s.size, s.roughness, s.seed);
    if (kind.is_word("midpoint"))
      map = extruded_profile(procedural::midpoint_profile(s.size, s.roughness, s.seed));
    if (kind.is_word("fbm")) map = procedural::fbm_terrain(s);
    if (kind.is_word("ridged")) map = procedural::ridged_terrain(s);
  } catch (const procedural::TerrainError& e) {
    fail(kind.where, kind.text + ": " + e.what());
  }
  procedural::normalize(map);
  if (!export_file.empty()) {
    try {
      export_height_map(map, frames_.back().folder / export_file);
    } catch (const std::exception& e) {
      fail(export_where, e.what());
    }
  }
  grid.width = map.width, grid.depth = map.depth;
  grid.heights.assign(map.values.begin(), map.values.end());
  return true;
}

}  // namespace snell::sdl
