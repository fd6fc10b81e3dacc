// Model files: size checks and binary PLY here, everything else through the Assimp plugin
// (assimp_plugin_abi.hpp), loaded on the first import.
#include "snell/io/mesh_import.hpp"

#include <mutex>

#include "snell/io/assimp_plugin_abi.hpp"
#include "snell/io/plugin_loader.hpp"
#include "snell/io/ply_binary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

namespace snell::io {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// The plugin's entry point, loaded once; throws MeshImportError when the plugin cannot be loaded.
SnellAssimpImport assimp_import() {
  static std::once_flag once;
  static SnellAssimpImport entry = nullptr;
  static std::string error;
  std::call_once(once, [] {
    void* handle = open_plugin("libsnell_assimp.so", error);
    entry = reinterpret_cast<SnellAssimpImport>(plugin_symbol(handle, "snell_assimp_import"));
    if (handle && !entry) error = "libsnell_assimp.so lacks snell_assimp_import";
  });
  if (!entry) throw MeshImportError("cannot load the mesh importer: " + error);
  return entry;
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

  ImportedMesh out;
  char error[1024] = {};
  if (assimp_import()(path.c_str(), &out, error, sizeof error) != 0) throw MeshImportError(error);
  if (out.parts.empty()) throw MeshImportError("the file has no triangles");
  return out;
}

}  // namespace snell::io
