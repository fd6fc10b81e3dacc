// snell's Assimp plugin: the only code that includes Assimp (see snell/io/assimp_plugin_abi.hpp).
// Assimp triangulates polygons and bakes the node hierarchy into the vertices
// (aiProcess_PreTransformVertices), which also merges meshes that share a material, so each remaining
// aiMesh becomes one ImportedPart with one material.
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cmath>
#include <cstring>
#include <string>

#include "snell/io/assimp_plugin_abi.hpp"

// Debian's Assimp 5.2 is built with its internal assertions on, and a failed one prints a line and calls
// abort(): the mesh fuzz target found damaged OBJ files that end so inside the triangulation step
// (fuzz/corpus/mesh/regressions/). That version has no way to install an assertion handler, so snell
// supplies the library's own hook, which the dynamic linker binds in place of Assimp's copy: a failed check
// becomes an exception that unwinds out of Importer::ReadFile into import_mesh's error path. (Exported from
// the plugin, whose other symbols are hidden, so that the binding happens.)
namespace Assimp {
__attribute__((visibility("default"))) void aiAssertViolation(const char* failed_expression, const char* file,
                                                              int line) {
  throw snell::io::MeshImportError(std::string("the importer's consistency check '") + failed_expression +
                                   "' failed (" + file + ":" + std::to_string(line) + "): a damaged file");
}
}  // namespace Assimp

namespace snell::io {
namespace {

ImportedMaterial read_material(const aiMaterial& m, const std::filesystem::path& folder) {
  ImportedMaterial out;
  aiString name;
  if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
  aiColor3D c;
  if (m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) out.diffuse = math::Color(c.r, c.g, c.b);
  if (m.Get(AI_MATKEY_COLOR_SPECULAR, c) == AI_SUCCESS) out.specular = (c.r + c.g + c.b) / 3.0;
  float value = 0;
  if (m.Get(AI_MATKEY_SHININESS, value) == AI_SUCCESS) out.shininess = value;
  if (m.Get(AI_MATKEY_OPACITY, value) == AI_SUCCESS) out.opacity = std::clamp(double(value), 0.0, 1.0);
  aiString texture;
  if (m.GetTextureCount(aiTextureType_DIFFUSE) > 0 &&
      m.GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS && texture.length > 0 &&
      texture.C_Str()[0] != '*')  // '*n' names a texture embedded in the file: not supported, colour only
    out.diffuse_texture = folder / texture.C_Str();
  return out;
}

ImportedPart read_part(const aiMesh& m, const aiScene& scene, const std::filesystem::path& folder) {
  ImportedPart part;
  geometry::MeshData& d = part.mesh;
  d.vertices.reserve(m.mNumVertices);
  for (unsigned i = 0; i < m.mNumVertices; ++i) {
    const aiVector3D& v = m.mVertices[i];
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw MeshImportError("vertex " + std::to_string(i) + " is not a finite number (NaN or infinity)");
    d.vertices.push_back({v.x, v.y, v.z});
  }
  if (m.HasNormals()) {
    d.normals.reserve(m.mNumVertices);
    for (unsigned i = 0; i < m.mNumVertices; ++i) {
      const aiVector3D& n = m.mNormals[i];
      const bool usable = std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z);
      d.normals.push_back(usable ? math::Vec3{n.x, n.y, n.z} : math::Vec3{});
    }
  }
  const bool has_uv = m.HasTextureCoords(0);
  if (has_uv) {
    d.uvs.reserve(m.mNumVertices);
    for (unsigned i = 0; i < m.mNumVertices; ++i)
      d.uvs.push_back({m.mTextureCoords[0][i].x, m.mTextureCoords[0][i].y});
  }
  d.faces.reserve(m.mNumFaces);
  for (unsigned f = 0; f < m.mNumFaces; ++f) {
    const aiFace& face = m.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines left over after triangulation
    const std::array<int, 3> tri{static_cast<int>(face.mIndices[0]), static_cast<int>(face.mIndices[1]),
                                 static_cast<int>(face.mIndices[2])};
    d.faces.push_back(tri);
  }
  // Normals and uvs share the vertex numbering in Assimp.
  if (!d.normals.empty()) d.normal_indices = d.faces;
  if (has_uv) d.uv_indices = d.faces;
  if (m.mMaterialIndex < scene.mNumMaterials)
    part.material = read_material(*scene.mMaterials[m.mMaterialIndex], folder);
  return part;
}

ImportedMesh read_model(const std::filesystem::path& path) {
  Assimp::Importer importer;
  // Points and lines are no surfaces: drop them rather than fail on a model that also has edges.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      path.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
                         aiProcess_PreTransformVertices | aiProcess_ValidateDataStructure);
  if (!scene) throw MeshImportError(importer.GetErrorString());

  ImportedMesh out;
  const std::filesystem::path folder = path.parent_path();
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    ImportedPart part = read_part(*scene->mMeshes[i], *scene, folder);
    if (part.mesh.faces.empty()) continue;
    out.triangles += static_cast<std::int64_t>(part.mesh.faces.size());
    out.parts.push_back(std::move(part));
  }
  return out;
}

}  // namespace
}  // namespace snell::io

extern "C" __attribute__((visibility("default"))) int snell_assimp_import(const char* path,
                                                                          snell::io::ImportedMesh* out,
                                                                          char* error, size_t error_size) {
  try {
    *out = snell::io::read_model(path);
    return 0;
  } catch (const std::exception& e) {
    if (error_size > 0) {
      const size_t n = std::min(std::strlen(e.what()), error_size - 1);
      std::memcpy(error, e.what(), n);
      error[n] = '\0';
    }
    return 1;
  }
}
