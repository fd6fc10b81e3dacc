#pragma once
// A direct reader for the common binary little-endian PLY layout (vertex x y z [nx ny nz] [u v], then faces
// as one index list), used before Assimp: Assimp's PLY loader keeps every property of every element in a
// generic tree and needs over 300 bytes per triangle for big files; this reads straight into MeshData.
#include <filesystem>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "snell/geometry/mesh.hpp"

namespace snell::io {

/// A PLY header (Greg Turk's PLY format): the format word and the elements with their properties in order.
struct PlyHeader {
  struct Property {
    std::string name;
    std::string type;        // scalar type, or the index type of a list
    std::string count_type;  // a list's count type; empty for a scalar
  };
  struct Element {
    std::string name;
    long long count = 0;
    std::vector<Property> properties;
  };
  std::string format;  // ascii, binary_little_endian or binary_big_endian
  std::vector<Element> elements;
};

/// Reads the header up to and including `end_header` (the stream is left at the body). Throws
/// MeshImportError for a header that is malformed or never ends; returns nullopt when the file is no PLY.
std::optional<PlyHeader> read_ply_header(std::istream& in);

/// Bytes of a PLY scalar type name (char/uchar/.../double and the sized aliases int8..float64); 0 when the
/// name is unknown.
int ply_scalar_size(const std::string& type);

/// The mesh in `path`, or nullopt when the file is not a PLY of that layout (ASCII, big-endian, extra
/// elements or list properties): the caller then asks Assimp. Throws MeshImportError for a file of that
/// layout that is cut short, has an index out of range or a non-finite vertex.
std::optional<geometry::MeshData> read_binary_ply(const std::filesystem::path& path);

}  // namespace snell::io
