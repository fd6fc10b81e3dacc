// `height_field { [type] "file" | function W, H { ... }  smooth  water_level L  hierarchy }` (POV-Ray 3.7
// reference, "Height Field"). Heights follow POV-Ray's image_height_at (imageutil.cpp): a palette image's
// index / 256, a grey image's value, an 8-bit colour image's red + green / 256 (red the high byte).
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "snell/geometry/height_field.hpp"
#include "snell/io/image_file.hpp"
#include "snell/io/png_indices.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/sdl/shape_factory.hpp"

namespace snell::sdl {

namespace {

/// Image types POV-Ray names before the file; the file's own contents decide how it is read here.
bool is_image_type(const Token& t) {
  static const char* const types[] = {"gif", "tga",  "iff",  "ppm", "pgm", "png",
                                      "pot", "jpeg", "tiff", "sys", "exr", "hdr"};
  for (const char* type : types)
    if (t.is_word(type)) return true;
  return false;
}

/// Largest grid a `function W, H` height field may ask for (4096 x 4096 floats = 64 MB).
constexpr double kMaxFunctionSamples = 4096.0 * 4096.0;

geometry::HeightGrid grid_from_image(const std::filesystem::path& path) {
  geometry::HeightGrid grid;
  // Rows run top to bottom in the file; the grid's row 0 is the image's bottom row (heightfield.cpp).
  if (const auto indexed = io::read_png_indices(path)) {
    grid.width = indexed->width, grid.depth = indexed->height;
    grid.heights.resize(indexed->indices.size());
    for (int k = 0; k < grid.depth; ++k)
      for (int i = 0; i < grid.width; ++i)
        grid.heights[static_cast<std::size_t>(k * grid.width + i)] =
            indexed->indices[static_cast<std::size_t>((grid.depth - 1 - k) * grid.width + i)] / 256.0f;
    return grid;
  }
  const io::Image image = io::read_image(path);
  grid.width = image.width, grid.depth = image.height;
  grid.heights.resize(static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.depth));
  for (int k = 0; k < grid.depth; ++k)
    for (int i = 0; i < grid.width; ++i) {
      const math::Color c = image.at(i, grid.depth - 1 - k);
      const bool grey = c.r == c.g && c.g == c.b;
      const double value = grey ? c.r : (c.r * 256.0 + c.g) * 255.0 / 65536.0;
      grid.heights[static_cast<std::size_t>(k * grid.width + i)] =
          static_cast<float>(std::clamp(value, 0.0, 1.0));
    }
  return grid;
}

}  // namespace

ParsedObject Parser::parse_height_field(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "height_field");
  geometry::HeightGrid grid;
  const Token source = peek();
  if (source.is_word("function")) {
    raw_next();
    const double w = std::floor(parse_float());
    accept(",");
    const double d = std::floor(parse_float());
    if (!(w >= 2 && d >= 2) || w * d > kMaxFunctionSamples)
      fail(source.where, "height_field function needs a size from 2 x 2 to 4096 x 4096");
    const auto f = parse_function_block();
    if (f->arity() != 3) fail(source.where, "a height_field function takes x, y, z");
    grid.width = static_cast<int>(w), grid.depth = static_cast<int>(d);
    keep_memory(source.where, static_cast<uint64_t>(w * d) * sizeof(float), "height_field function grid");
    grid.heights.resize(static_cast<std::size_t>(w * d));
    try {
      // POV-Ray samples f(x, y, 0) with x, y in [0, 1] and y = 0 on the image's top row, which is the far
      // edge, z = 1 (parser_materials.cpp, Make_Pattern_Image); heights are clamped to [0, 1].
      for (int k = 0; k < grid.depth; ++k)
        for (int i = 0; i < grid.width; ++i) {
          const double args[3] = {i / (w - 1), 1 - k / (d - 1), 0};
          grid.heights[static_cast<std::size_t>(k * grid.width + i)] =
              static_cast<float>(std::clamp(f->call(args), 0.0, 1.0));
        }
    } catch (const function::FunctionError& e) {
      fail(source.where, e.what());
    }
  } else if (!parse_terrain_if_any(grid)) {  // diamond_square { }, fbm { }... (terrain_block.cpp)
    if (is_image_type(source)) raw_next();
    const Token name = peek();
    const std::string file = parse_string();
    std::vector<std::filesystem::path> candidates{frames_.back().folder / file};
    for (const auto& dir : options_.library_paths) candidates.push_back(dir / file);
    const auto found = std::find_if(candidates.begin(), candidates.end(), [](const std::filesystem::path& p) {
      std::error_code ec;
      return std::filesystem::is_regular_file(p, ec);
    });
    if (found == candidates.end()) fail(name.where, "cannot find height_field image \"" + file + "\"");
    if (options_.on_file_read) options_.on_file_read(*found);
    try {
      grid = grid_from_image(*found);
    } catch (const std::exception& e) {
      fail(name.where, e.what());
    }
    keep_memory(name.where, grid.heights.size() * sizeof(float), "height_field image \"" + file + "\"");
  }
  bool smooth = false;
  double water = 0;
  for (;;) {
    const Token t = peek();
    if (t.is_word("smooth")) {
      raw_next();
      smooth = parse_bool_optional(true);
    } else if (t.is_word("water_level")) {
      raw_next();
      water = parse_float();
    } else if (t.is_word("hierarchy") || t.is_word("premultiplied")) {
      raw_next();
      parse_bool_optional(true);
    } else if (t.is_word("gamma")) {
      raw_next();
      parse_float();
    } else {
      break;
    }
  }
  return finish_shape(std::move(o), keyword,
                      [&] { return shapes::height_field(std::move(grid), smooth, water); });
}

}  // namespace snell::sdl
