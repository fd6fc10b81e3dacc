// Model files through Assimp (Debian libassimp-dev). Assimp triangulates polygons and bakes the node
// hierarchy into the vertices (aiProcess_PreTransformVertices), which also merges meshes that share a
// material, so each remaining aiMesh becomes one ImportedPart with one material.
#include "snell/io/mesh_import.hpp"

#include "snell/io/ply_binary.hpp"

#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

// Debian's Assimp 5.2 is built with its internal assertions on, and a failed one prints a line and calls
// abort(): the mesh fuzz target found damaged OBJ files that end so inside the triangulation step
// (fuzz/corpus/mesh/regressions/). That version has no way to install an assertion handler, so snell
// supplies the library's own hook, which the dynamic linker binds in place of Assimp's copy: a failed check
// becomes an exception that unwinds out of Importer::ReadFile into import_mesh's error path.
namespace Assimp {
void aiAssertViolation(const char* failed_expression, const char* file, int line) {
  throw snell::io::MeshImportError(std::string("the importer's consistency check '") + failed_expression +
                                   "' failed (" + file + ":" + std::to_string(line) + "): a damaged file");
}
}  // namespace Assimp

namespace snell::io {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

int ply_type_size(const std::string& type) {
  const int size = ply_scalar_size(type);
  if (size == 0) throw MeshImportError("PLY header names an unknown property type '" + type + "'");
  return size;
}

/// The least number of bytes the PLY body must have for the header's element counts: a list property costs
/// at least its count field (binary) and every property at least two characters (ASCII, "0 ").
void check_ply_header(std::istream& in, std::uintmax_t file_size) {
  const std::optional<PlyHeader> header = read_ply_header(in);
  if (!header) throw MeshImportError("the file does not start with 'ply'");
  double needed = 0;
  for (const PlyHeader::Element& element : header->elements) {
    if (element.count > std::numeric_limits<int>::max())
      throw MeshImportError("PLY header claims " + std::to_string(element.count) + " " + element.name +
                            " elements, more than 32-bit indices can address");
    double element_bytes = 0;
    for (const PlyHeader::Property& property : element.properties)
      element_bytes += header->format == "ascii"
                           ? 2
                           : ply_type_size(property.count_type.empty() ? property.type : property.count_type);
    needed += static_cast<double>(element.count) * element_bytes;
  }
  if (needed > static_cast<double>(file_size))
    throw MeshImportError("PLY header claims elements needing at least " +
                          std::to_string(static_cast<long long>(needed)) + " bytes, but the file has " +
                          std::to_string(file_size));
}

/// Binary STL: 80-byte header, a 32-bit triangle count, then 50 bytes per triangle.
void check_stl_header(std::istream& in, std::uintmax_t file_size) {
  std::array<char, 84> head{};
  in.read(head.data(), head.size());
  if (in.gcount() < 84 || std::strncmp(head.data(), "solid", 5) == 0) return;  // ASCII STL or tiny
  std::uint32_t count = 0;
  std::memcpy(&count, head.data() + 80, 4);
  if (84.0 + 50.0 * count > static_cast<double>(file_size))
    throw MeshImportError("binary STL claims " + std::to_string(count) +
                          " triangles, but the file has only " + std::to_string(file_size) + " bytes");
}

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

}  // namespace

void check_claimed_counts(const std::filesystem::path& path, std::uintmax_t file_size) {
  const std::string ext = lower_extension(path);
  if (ext != ".ply" && ext != ".stl") return;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshImportError("cannot open the file");
  if (ext == ".ply")
    check_ply_header(in, file_size);
  else
    check_stl_header(in, file_size);
}

ImportedMesh import_mesh(const std::filesystem::path& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw MeshImportError("cannot read the file: " + ec.message());
  if (size == 0) throw MeshImportError("the file is empty");
  check_claimed_counts(path, size);
  if (lower_extension(path) == ".ply") {
    if (auto direct = read_binary_ply(path)) {  // big scanned or generated meshes: no Assimp copy
      ImportedMesh out;
      out.triangles = static_cast<std::int64_t>(direct->faces.size());
      out.parts.push_back({std::move(*direct), ImportedMaterial{}});
      return out;
    }
  }

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
  if (out.parts.empty()) throw MeshImportError("the file has no triangles");
  return out;
}

}  // namespace snell::io
