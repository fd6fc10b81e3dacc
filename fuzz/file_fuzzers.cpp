#include "fuzz/file_fuzzers.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include "fuzz/temp_folder.hpp"
#include "snell/io/image_file.hpp"
#include "snell/io/mesh_import.hpp"
#include "snell/io/png_indices.hpp"
#include "snell/render/resume_file.hpp"
#include "snell/texture/density_file.hpp"

namespace snell::fuzz {

namespace {

const std::filesystem::path& private_folder() {
  static const std::filesystem::path folder = make_private_folder("snell-file-fuzz");
  return folder;
}

/// Reads an image file as image_map does; false when the reader refuses it with its own error.
bool read_back(const std::string& path) {
  try {
    const io::Image image = io::read_image(path);
    if (image.rgb.size() != size_t(image.width) * size_t(image.height) * 3) std::abort();
    return true;
  } catch (const io::ImageIoError&) {
    return false;
  }
}

template <typename T>
T read_at(const uint8_t* data, size_t offset) {
  T value;
  std::memcpy(&value, data + offset, sizeof value);
  return value;
}

/// Every index of `faces` names one of `count` elements.
bool indices_in_range(const std::vector<std::array<int, 3>>& faces, size_t count) {
  for (const auto& face : faces)
    for (int index : face)
      if (index < 0 || static_cast<size_t>(index) >= count) return false;
  return true;
}

void check_mesh(const geometry::MeshData& mesh) {
  for (const auto& v : mesh.vertices)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) std::abort();
  if (mesh.faces.empty() || !indices_in_range(mesh.faces, mesh.vertices.size())) std::abort();
  if (!mesh.normal_indices.empty() && (mesh.normal_indices.size() != mesh.faces.size() ||
                                       !indices_in_range(mesh.normal_indices, mesh.normals.size())))
    std::abort();
  if (!mesh.uv_indices.empty() &&
      (mesh.uv_indices.size() != mesh.faces.size() || !indices_in_range(mesh.uv_indices, mesh.uvs.size())))
    std::abort();
}

}  // namespace

const char* const kMeshFuzzExtensions[] = {".obj", ".ply", ".stl", ".3ds", ".gltf", ".glb", ".fbx"};
const size_t kMeshFuzzExtensionCount = sizeof kMeshFuzzExtensions / sizeof kMeshFuzzExtensions[0];

const char* const kImageFuzzExtensions[] = {".tga", ".ppm", ".gif", ".jpg"};
const size_t kImageFuzzExtensionCount = sizeof kImageFuzzExtensions / sizeof kImageFuzzExtensions[0];

std::string write_fuzz_file(const uint8_t* data, size_t size, const std::string& extension) {
  const std::string path = (private_folder() / ("input" + extension)).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) std::abort();
  return path;
}

bool read_png_bytes(const uint8_t* data, size_t size) {
  const std::string path = write_fuzz_file(data, size, ".png");
  try {
    const auto indexed = io::read_png_indices(path);
    if (indexed && indexed->indices.size() != size_t(indexed->width) * size_t(indexed->height)) std::abort();
  } catch (const io::ImageIoError&) {
    return false;
  }
  return read_back(path);
}

bool read_image_bytes(const uint8_t* data, size_t size) {
  if (size == 0) return false;
  const std::string path =
      write_fuzz_file(data + 1, size - 1, kImageFuzzExtensions[data[0] % kImageFuzzExtensionCount]);
  return read_back(path);
}

bool read_resume_bytes(const uint8_t* data, size_t size) {
  const std::string path = write_fuzz_file(data, size, ".snell-resume");
  // Layout in resume_file.hpp: magic (8), version (4), fingerprint (8), width (4), height (4).
  uint64_t fingerprint = 0;
  int32_t width = 64, height = 64;
  if (size >= 28) {
    fingerprint = read_at<uint64_t>(data, 12);
    width = read_at<int32_t>(data, 20);
    height = read_at<int32_t>(data, 24);
  }
  if (width < 1 || width > 1024) width = 64;
  if (height < 1 || height > 1024) height = 64;
  try {
    const render::ResumeData resumed = render::read_resume_file(path, fingerprint, width, height);
    if (resumed.image.width != width || resumed.image.height != height) std::abort();
    return true;
  } catch (const render::ResumeError&) {
    return false;
  }
}

bool read_df3_bytes(const uint8_t* data, size_t size) {
  const std::string path = write_fuzz_file(data, size, ".df3");
  texture::DensityGrid grid;
  try {
    grid = texture::read_df3(path);
  } catch (const std::runtime_error&) {
    return false;
  }
  if (grid.values.size() != size_t(grid.nx) * size_t(grid.ny) * size_t(grid.nz)) std::abort();
  const auto shared = std::make_shared<const texture::DensityGrid>(std::move(grid));
  // Corners, faces and just inside the far faces of the unit cube, where the pattern wraps around.
  const double coordinates[] = {0.0, 1e-9, 0.37, 0.5, 0.999999, std::nextafter(1.0, 0.0)};
  for (int interpolation : {0, 1}) {
    const texture::DensityFilePattern pattern(shared, interpolation);
    for (double x : coordinates)
      for (double y : coordinates)
        for (double z : coordinates) {
          const double value = pattern.value({x, y, z});
          if (!(value >= 0 && value <= 1)) std::abort();
        }
  }
  return true;
}

bool read_mesh_bytes(const uint8_t* data, size_t size) {
  if (size == 0) return false;
  const std::string path =
      write_fuzz_file(data + 1, size - 1, kMeshFuzzExtensions[data[0] % kMeshFuzzExtensionCount]);
  try {
    const io::ImportedMesh mesh = io::import_mesh(path);
    if (mesh.parts.empty()) std::abort();
    for (const io::ImportedPart& part : mesh.parts) check_mesh(part.mesh);
    return true;
  } catch (const io::MeshImportError&) {
    return false;
  }
}

}  // namespace snell::fuzz
