// `image_map { [type] "file" [gamma g] map_type n interpolate n once filter all f transmit all t }`
// (POV-Ray 3.7 reference, "Image Maps") and `material_map { [type] "file" [map_type n] [once] texture {..}
// ... }` ("Material Maps"). The file is looked for next to the scene, then in the library paths, and read
// through OpenImageIO (io::read_image), whatever its type keyword says; a palette PNG's indices through
// libpng (io::read_png_indices).
#include <algorithm>
#include <cmath>
#include <optional>

#include "snell/io/image_file.hpp"
#include "snell/io/png_indices.hpp"
#include "snell/sdl/image_gamma.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/texture/image_map.hpp"
#include "snell/texture/material_map.hpp"

namespace snell::sdl {

namespace {

bool is_bitmap_type(const std::string& w) {
  static const char* const types[] = {"gif",  "tga",  "iff", "ppm", "pgm", "png",
                                      "jpeg", "tiff", "sys", "exr", "hdr"};
  for (const char* t : types)
    if (w == t) return true;
  return false;
}

/// `map_type n`: planar 0, spherical 1 or cylindrical 2; nullopt for the types snell lacks.
std::optional<texture::ImageMapType> image_map_type(double n) {
  if (n != 0 && n != 1 && n != 2) return std::nullopt;
  return static_cast<texture::ImageMapType>(static_cast<int>(n));
}

}  // namespace

void decode_gamma(io::Image& image, double file_gamma, double assumed_gamma) {
  const double exponent = file_gamma / assumed_gamma;
  if (std::fabs(exponent - 1) < 1e-12) return;
  for (float& c : image.rgb) c = static_cast<float>(std::pow(std::max(0.0f, c), exponent));
}

std::shared_ptr<const material::Pigment> Parser::parse_image_map(double* bump_size) {
  expect("{", "image_map");
  if (is_bitmap_type(peek().text)) raw_next();
  const Token file_token = peek();
  const std::string file = parse_string();
  texture::ImageMapSpec spec;
  double file_gamma = 2.2;
  bool use_color = false;
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      break;
    }
    raw_next();
    const std::string& w = t.text;
    if (w == "map_type") {
      const auto type = image_map_type(parse_float());
      if (!type) fail(t.where, "map_type must be 0, 1 or 2 here");
      spec.type = *type;
    } else if (w == "interpolate") {
      spec.interpolate = static_cast<int>(parse_float());
    } else if (w == "once") {
      spec.once = true;
    } else if (w == "gamma") {
      file_gamma = parse_float();
      if (!(file_gamma > 0)) fail(t.where, "gamma must be positive");
    } else if (w == "filter" || w == "transmit") {
      // `filter all f`, or `filter index f` for palette images (not distinguished here: ignored).
      const bool all = peek().is_word("all");
      if (all) raw_next();
      const double amount = all ? parse_float() : (parse_float(), accept(","), parse_float());
      if (all) (w == "filter" ? spec.filter_all : spec.transmit_all) = amount;
    } else if (w == "bump_size" && bump_size) {
      *bump_size = parse_float();
    } else if (w == "use_color" || w == "use_colour" || w == "use_index" || w == "use_alpha") {
      use_color = w != "use_index";
    } else {
      fail(t.where, "unexpected '" + w + "' in image_map");
    }
  }
  const std::filesystem::path path = find_image_file(file_token, file);
  auto image = std::make_shared<io::Image>();
  try {
    *image = io::read_image(path);
  } catch (const std::exception& e) {
    fail(file_token.where, "cannot read image \"" + file + "\": " + e.what());
  }
  keep_memory(file_token.where, (image->rgb.size() + image->alpha.size()) * sizeof(float),
              "image_map \"" + file + "\"");
  decode_gamma(*image, file_gamma, scene_.effective_assumed_gamma());
  // A bump_map of a palette image takes each pixel's palette index itself as its height unless told
  // `use_color` (POV-Ray imageutil.cpp, bump_map: Amount * index).
  if (bump_size && !use_color) {
    if (const auto indexed = io::read_png_indices(path)) {
      for (size_t i = 0; i < indexed->indices.size(); ++i)
        for (size_t c = 0; c < 3; ++c) image->rgb[3 * i + c] = static_cast<float>(indexed->indices[i]);
    }
  }
  spec.image = image;
  return std::make_shared<texture::ImageMapPigment>(spec);
}

std::filesystem::path Parser::find_image_file(const Token& file_token, const std::string& file) {
  std::vector<std::filesystem::path> candidates{frames_.back().folder / file};
  for (const auto& dir : options_.library_paths) candidates.push_back(dir / file);
  for (const auto& c : candidates) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(c, ec)) continue;
    if (options_.on_file_read) options_.on_file_read(c);
    return c;
  }
  fail(file_token.where,
       "cannot find file \"" + file + "\" (searched the scene's folder and the library paths)");
}

std::shared_ptr<const material::TextureSelector> Parser::parse_material_map() {
  const scene::SourceLocation where = peek().where;
  expect("{", "material_map");
  if (is_bitmap_type(peek().text)) raw_next();
  const Token file_token = peek();
  const std::string file = parse_string();
  texture::MaterialMapImage image;
  std::vector<std::shared_ptr<const material::Texture>> textures;
  while (!accept("}")) {
    const Token item = peek();
    raw_next();
    if (item.is_word("texture")) {
      textures.push_back(parse_texture_block());
    } else if (item.is_word("once")) {
      image.once = true;
    } else if (item.is_word("interpolate")) {
      parse_float();  // POV-Ray picks a material by the nearest pixel whatever this says
    } else if (!item.is_word("map_type")) {
      fail(item.where, "unexpected '" + item.text + "' in material_map");
    } else if (const auto type = image_map_type(parse_float())) {
      image.type = *type;
    } else {
      fail(item.where, "map_type must be 0, 1 or 2 here");
    }
  }
  if (textures.empty()) fail(where, "material_map needs at least one texture {}");
  const std::filesystem::path path = find_image_file(file_token, file);
  try {
    if (const auto indexed = io::read_png_indices(path)) {
      image.width = indexed->width, image.height = indexed->height;
      image.numbers.assign(indexed->indices.begin(), indexed->indices.end());
    } else {
      // Not a palette image: the red channel's stored value times 255 (POV-Ray imageutil.cpp).
      const io::Image pixels = io::read_image(path);
      image.width = pixels.width, image.height = pixels.height;
      for (size_t i = 0; i < pixels.rgb.size(); i += 3)
        image.numbers.push_back(static_cast<int>(std::clamp(pixels.rgb[i], 0.0f, 1.0f) * 255.0f));
    }
    return std::make_shared<texture::MaterialMapSelector>(std::move(image), std::move(textures));
  } catch (const std::exception& e) {
    fail(file_token.where, "cannot read image \"" + file + "\": " + e.what());
  }
}

}  // namespace snell::sdl
