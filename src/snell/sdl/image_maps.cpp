// `image_map { [type] "file" [gamma g] map_type n interpolate n once filter all f transmit all t }`
// (POV-Ray 3.7 reference, "Image Maps"). The file is looked for next to the scene, then in the library
// paths, and read through OpenImageIO (io::read_image), whatever its type keyword says.
#include <cmath>

#include "snell/io/image_file.hpp"
#include "snell/sdl/image_gamma.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/texture/image_map.hpp"

namespace snell::sdl {

namespace {

bool is_bitmap_type(const std::string& w) {
  static const char* const types[] = {"gif",  "tga",  "iff", "ppm", "pgm", "png",
                                      "jpeg", "tiff", "sys", "exr", "hdr"};
  for (const char* t : types)
    if (w == t) return true;
  return false;
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
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      break;
    }
    raw_next();
    const std::string& w = t.text;
    if (w == "map_type") {
      const double type = parse_float();
      if (type != 0 && type != 1 && type != 2) fail(t.where, "map_type must be 0, 1 or 2 here");
      spec.type = static_cast<texture::ImageMapType>(static_cast<int>(type));
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
    } else {
      fail(t.where, "unexpected '" + w + "' in image_map");
    }
  }
  std::vector<std::filesystem::path> candidates{frames_.back().folder / file};
  for (const auto& dir : options_.library_paths) candidates.push_back(dir / file);
  for (const auto& c : candidates) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(c, ec)) continue;
    if (options_.on_file_read) options_.on_file_read(c);
    auto image = std::make_shared<io::Image>();
    try {
      *image = io::read_image(c);
    } catch (const std::exception& e) {
      fail(file_token.where, "cannot read image \"" + file + "\": " + e.what());
    }
    keep_memory(file_token.where, (image->rgb.size() + image->alpha.size()) * sizeof(float),
                "image_map \"" + file + "\"");
    decode_gamma(*image, file_gamma, scene_.effective_assumed_gamma());
    spec.image = image;
    return std::make_shared<texture::ImageMapPigment>(spec);
  }
  fail(file_token.where,
       "cannot find image file \"" + file + "\" (searched the scene's folder and the library paths)");
}

}  // namespace snell::sdl
