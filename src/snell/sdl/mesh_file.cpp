// `mesh { "model.obj" [object modifiers] }`: a snell extension (POV-Ray's mesh holds only triangle lists).
// The file is found like an image_map file (the scene's folder, then the library paths), read through
// io/mesh_import, and each of its materials becomes one mesh with a texture made from the material, unless
// the scene gives the mesh a texture of its own.
#include <filesystem>

#include "snell/io/image_file.hpp"
#include "snell/io/mesh_import.hpp"
#include "snell/sdl/image_gamma.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/sdl/shape_factory.hpp"
#include "snell/texture/image_map.hpp"
#include "snell/texture/pattern_pigment.hpp"

namespace snell::sdl {

namespace {

/// Material -> texture, as in docs/language.md ("Imported meshes"): diffuse colour -> pigment, 1 - opacity
/// -> transmit, specular colour -> phong with the shininess as phong_size, diffuse image -> uv-mapped
/// image_map (its file gamma taken as sRGB's 2.2 like an 8-bit image_map).
std::shared_ptr<const material::Texture> material_texture(const io::ImportedMaterial& m,
                                                          const material::Texture& base, double assumed_gamma,
                                                          std::string& image_problem) {
  auto texture = std::make_shared<material::Texture>(base);
  texture->pigment = std::make_shared<material::SolidPigment>(material::Rgbft{m.diffuse, 0, 1 - m.opacity});
  if (!m.diffuse_texture.empty()) {
    try {
      texture::ImageMapSpec spec;
      auto image = std::make_shared<io::Image>(io::read_image(m.diffuse_texture));
      decode_gamma(*image, 2.2, assumed_gamma);
      spec.image = image;
      spec.transmit_all = 1 - m.opacity;
      texture->pigment =
          std::make_shared<texture::UvMappedPigment>(std::make_shared<texture::ImageMapPigment>(spec));
    } catch (const std::exception& e) {
      image_problem = "cannot read the texture image \"" + m.diffuse_texture.string() + "\" of material '" +
                      m.name + "' (" + e.what() + "); its colour is used";
    }
  }
  if (m.specular > 0 && m.shininess > 0) {
    texture->finish.phong = m.specular;
    texture->finish.phong_size = m.shininess;
  }
  return texture;
}

}  // namespace

ParsedObject Parser::parse_mesh_file(const Token& keyword) {
  const Token file_token = peek();
  const std::string file = parse_string();
  std::vector<std::filesystem::path> candidates{frames_.back().folder / file};
  for (const auto& dir : options_.library_paths) candidates.push_back(dir / file);
  std::filesystem::path found;
  for (const auto& c : candidates) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(c, ec)) {
      found = c;
      break;
    }
  }
  if (found.empty())
    fail(file_token.where,
         "cannot find mesh file \"" + file + "\" (searched the scene's folder and the library paths)");
  io::ImportedMesh imported;
  try {
    imported = io::import_mesh(found);
  } catch (const std::exception& e) {
    fail(file_token.where, "cannot import mesh file \"" + file + "\": " + e.what());
  }

  ParsedObject o;
  o.where = keyword.where;
  const double assumed_gamma = scene_.effective_assumed_gamma();
  for (io::ImportedPart& part : imported.parts) {
    ParsedObject child;
    child.where = keyword.where;
    std::string image_problem;
    child.texture = material_texture(part.material, *default_texture_, assumed_gamma, image_problem);
    if (!image_problem.empty()) warn(file_token.where, image_problem);
    try {
      child.shape = shapes::mesh(std::move(part.mesh));
    } catch (const std::exception& e) {
      fail(file_token.where, "cannot build mesh from \"" + file + "\": " + e.what());
    }
    o.children.push_back(std::move(child));
  }
  if (o.children.size() == 1) {  // one material: a plain shape rather than a union of one
    ParsedObject only = std::move(o.children.front());
    o = std::move(only);
  }
  const auto material_textures = o.children.empty() ? o.texture : nullptr;
  if (o.children.empty()) o.texture = nullptr;
  parse_object_modifiers(o);
  if (o.children.empty() && !o.texture) {
    o.texture = material_textures->transformed(o.transform);  // the texture moves with the object
  } else if (!o.children.empty() && o.texture) {
    for (ParsedObject& child : o.children) child.texture = nullptr;  // the scene's own texture wins
  }
  return o;
}

}  // namespace snell::sdl
