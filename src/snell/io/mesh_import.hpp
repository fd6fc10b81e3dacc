#pragma once
// Triangle meshes from model files (.obj .ply .stl .3ds .gltf/.glb .fbx ...) through Assimp, for the snell
// extension `mesh { "file" }`. Assimp's headers stay inside mesh_import.cpp.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "snell/geometry/mesh.hpp"
#include "snell/math/color.hpp"

namespace snell::io {

/// The parts of a file's material that map onto a POV-Ray texture (docs/language.md, "Imported meshes").
struct ImportedMaterial {
  std::string name;
  math::Color diffuse{0.8};
  double specular = 0;                    // specular colour's mean intensity -> phong
  double shininess = 0;                   // specular exponent -> phong_size
  double opacity = 1;                     // 1 - opacity -> transmit
  std::filesystem::path diffuse_texture;  // empty without an image; resolved next to the model file
};

/// One material's triangles (Assimp splits a model by material); vertices in the file's own coordinates.
struct ImportedPart {
  geometry::MeshData mesh;
  ImportedMaterial material;
};

struct ImportedMesh {
  std::vector<ImportedPart> parts;
  std::int64_t triangles = 0;
};

/// A file that cannot be imported: the message says why (unreadable, no faces, NaN vertices, counts that
/// the file's size cannot hold).
struct MeshImportError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Reads `path`. Before Assimp sees the file, element counts in PLY headers and binary STL are checked
/// against the file's size, so a header claiming a billion faces fails at once instead of allocating.
ImportedMesh import_mesh(const std::filesystem::path& path);

/// The header check alone (exposed for tests): throws MeshImportError when the counts a PLY or binary STL
/// header claims need more bytes than `file_size`.
void check_claimed_counts(const std::filesystem::path& path, std::uintmax_t file_size);

}  // namespace snell::io
