// Binary PLY after Greg Turk's PLY format description (1994): an ASCII header of `element NAME COUNT` and
// `property TYPE NAME` / `property list COUNT_TYPE INDEX_TYPE NAME` lines up to `end_header`, then the
// elements' values packed in header order.
#include "snell/io/ply_binary.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "snell/io/mesh_import.hpp"

namespace snell::io {
namespace {

enum class Scalar { i8, u8, i16, u16, i32, u32, f32, f64, unknown };

Scalar scalar_of(const std::string& t) {
  if (t == "char" || t == "int8") return Scalar::i8;
  if (t == "uchar" || t == "uint8") return Scalar::u8;
  if (t == "short" || t == "int16") return Scalar::i16;
  if (t == "ushort" || t == "uint16") return Scalar::u16;
  if (t == "int" || t == "int32") return Scalar::i32;
  if (t == "uint" || t == "uint32") return Scalar::u32;
  if (t == "float" || t == "float32") return Scalar::f32;
  if (t == "double" || t == "float64") return Scalar::f64;
  return Scalar::unknown;
}

int size_of(Scalar s) {
  switch (s) {
    case Scalar::i8:
    case Scalar::u8:
      return 1;
    case Scalar::i16:
    case Scalar::u16:
      return 2;
    case Scalar::i32:
    case Scalar::u32:
    case Scalar::f32:
      return 4;
    case Scalar::f64:
      return 8;
    default:
      return 0;
  }
}

/// The value at `p` (little-endian, as the format line says; x86 and ARM hosts are little-endian too).
double load(Scalar s, const char* p) {
  switch (s) {
    case Scalar::i8:
      return static_cast<signed char>(*p);
    case Scalar::u8:
      return static_cast<unsigned char>(*p);
    case Scalar::i16: {
      std::int16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case Scalar::u16: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case Scalar::i32: {
      std::int32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case Scalar::u32: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case Scalar::f32: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case Scalar::f64: {
      double v;
      std::memcpy(&v, p, 8);
      return v;
    }
    default:
      return 0;
  }
}

struct VertexLayout {
  int stride = 0;
  int x = -1, y = -1, z = -1, nx = -1, ny = -1, nz = -1, u = -1, v = -1;  // byte offsets
  Scalar xs{}, ys{}, zs{}, nxs{}, nys{}, nzs{}, us{}, vs{};
};

void read_exact(std::istream& in, char* to, std::size_t bytes) {
  in.read(to, static_cast<std::streamsize>(bytes));
  if (static_cast<std::size_t>(in.gcount()) != bytes) throw MeshImportError("PLY file is cut short");
}

}  // namespace

int ply_scalar_size(const std::string& type) {
  return size_of(scalar_of(type));
}

std::optional<PlyHeader> read_ply_header(std::istream& in) {
  std::string line;
  if (!std::getline(in, line) || (line != "ply" && line != "ply\r")) return std::nullopt;
  PlyHeader header;
  for (int lines = 0; std::getline(in, line); ++lines) {
    if (lines > 10000) break;
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "format") {
      words >> header.format;
    } else if (word == "element") {
      PlyHeader::Element element;
      words >> element.name >> element.count;
      if (!words || element.count < 0) throw MeshImportError("PLY header has a bad element line: " + line);
      header.elements.push_back(std::move(element));
    } else if (word == "property") {
      if (header.elements.empty()) throw MeshImportError("PLY header has a property before any element");
      PlyHeader::Property property;
      words >> property.type;
      if (property.type == "list") words >> property.count_type >> property.type;
      words >> property.name;
      header.elements.back().properties.push_back(std::move(property));
    } else if (word == "end_header") {
      return header;
    }
  }
  throw MeshImportError("PLY header has no end_header");
}

std::optional<geometry::MeshData> read_binary_ply(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::optional<PlyHeader> header = read_ply_header(in);
  // The layout read here: vertices (scalars only) then faces (one index list), nothing else.
  if (!header || header->format != "binary_little_endian" || header->elements.size() != 2)
    return std::nullopt;
  const PlyHeader::Element& vertices = header->elements[0];
  const PlyHeader::Element& faces = header->elements[1];
  if (vertices.name != "vertex" || faces.name != "face" || faces.properties.size() != 1) return std::nullopt;
  const long long vertex_count = vertices.count, face_count = faces.count;
  const Scalar list_count = scalar_of(faces.properties[0].count_type);
  const Scalar list_index = scalar_of(faces.properties[0].type);
  if (list_count == Scalar::unknown || list_index == Scalar::unknown || list_count == Scalar::f32 ||
      list_count == Scalar::f64)
    return std::nullopt;
  VertexLayout vl;
  for (const PlyHeader::Property& property : vertices.properties) {
    const Scalar s = scalar_of(property.type);
    if (s == Scalar::unknown || !property.count_type.empty()) return std::nullopt;
    struct Slot {
      const char* name;
      int* offset;
      Scalar* scalar;
    };
    const Slot slots[] = {{"x", &vl.x, &vl.xs},    {"y", &vl.y, &vl.ys},    {"z", &vl.z, &vl.zs},
                          {"nx", &vl.nx, &vl.nxs}, {"ny", &vl.ny, &vl.nys}, {"nz", &vl.nz, &vl.nzs},
                          {"u", &vl.u, &vl.us},    {"v", &vl.v, &vl.vs},    {"s", &vl.u, &vl.us},
                          {"t", &vl.v, &vl.vs}};
    for (const Slot& slot : slots)
      if (property.name == slot.name) *slot.offset = vl.stride, *slot.scalar = s;
    vl.stride += size_of(s);
  }
  if (vertex_count <= 0 || face_count <= 0 || vl.x < 0 || vl.y < 0 || vl.z < 0) return std::nullopt;

  geometry::MeshData d;
  const bool normals = vl.nx >= 0 && vl.ny >= 0 && vl.nz >= 0;
  const bool uvs = vl.u >= 0 && vl.v >= 0;
  d.vertices.reserve(static_cast<std::size_t>(vertex_count));
  if (normals) d.normals.reserve(static_cast<std::size_t>(vertex_count));
  if (uvs) d.uvs.reserve(static_cast<std::size_t>(vertex_count));
  std::vector<char> chunk;
  const long long per_chunk = 65536;
  for (long long first = 0; first < vertex_count; first += per_chunk) {
    const long long n = std::min(per_chunk, vertex_count - first);
    chunk.resize(static_cast<std::size_t>(n * vl.stride));
    read_exact(in, chunk.data(), chunk.size());
    for (long long i = 0; i < n; ++i) {
      const char* p = chunk.data() + i * vl.stride;
      const math::Vec3 v{load(vl.xs, p + vl.x), load(vl.ys, p + vl.y), load(vl.zs, p + vl.z)};
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw MeshImportError("vertex " + std::to_string(first + i) +
                              " is not a finite number (NaN or infinity)");
      d.vertices.push_back(v);
      if (normals)
        d.normals.push_back({load(vl.nxs, p + vl.nx), load(vl.nys, p + vl.ny), load(vl.nzs, p + vl.nz)});
      if (uvs) d.uvs.push_back({load(vl.us, p + vl.u), load(vl.vs, p + vl.v)});
    }
  }
  // Faces: a count, then that many indices; polygons are split into a fan of triangles.
  d.faces.reserve(static_cast<std::size_t>(face_count));
  const int count_size = size_of(list_count), index_size = size_of(list_index);
  std::vector<int> polygon;
  char buffer[8];
  for (long long f = 0; f < face_count; ++f) {
    read_exact(in, buffer, static_cast<std::size_t>(count_size));
    const double corners = load(list_count, buffer);
    if (corners < 0 || corners > 1 << 16)
      throw MeshImportError("PLY face " + std::to_string(f) + " has a bad corner count");
    polygon.resize(static_cast<std::size_t>(corners));
    for (int& index : polygon) {
      read_exact(in, buffer, static_cast<std::size_t>(index_size));
      const double value = load(list_index, buffer);
      if (value < 0 || value >= static_cast<double>(vertex_count))
        throw MeshImportError("PLY face " + std::to_string(f) + " names vertex " +
                              std::to_string(static_cast<long long>(value)) + " of " +
                              std::to_string(vertex_count));
      index = static_cast<int>(value);
    }
    for (std::size_t k = 2; k < polygon.size(); ++k)
      d.faces.push_back({polygon[0], polygon[k - 1], polygon[k]});
  }
  if (d.faces.empty()) throw MeshImportError("the file has no triangles");
  if (normals) d.normal_indices = d.faces;
  if (uvs) d.uv_indices = d.faces;
  return d;
}

}  // namespace snell::io
