// `mesh2 { vertex_vectors normal_vectors uv_vectors texture_list face_indices normal_indices uv_indices
// inside_vector }` (POV-Ray 3.7 reference, "Mesh2"): the same triangle data as `mesh`, written as indexed
// lists. Each list starts with its count; commas between items are optional, as everywhere POV-Ray reads
// them.
#include <algorithm>
#include <string>
#include <string_view>

#include "snell/sdl/degenerate_triangles.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/sdl/shape_factory.hpp"

namespace snell::sdl {

namespace {

constexpr int kMaxMeshItems = 50'000'000;  // bounded memory for any claimed count
/// A claimed count reserves at most this many items up front; the rest grows as items are read, so a
/// count the list does not hold costs nothing (issue 12).
constexpr int kMaxReserved = 1 << 16;

/// Bytes each item of a list takes in MeshData, charged against --max-memory for the claimed count.
uint64_t bytes_per_item(std::string_view list) {
  if (list == "vertex_vectors" || list == "normal_vectors") return sizeof(math::Vec3);
  if (list == "uv_vectors") return 2 * sizeof(double);
  if (list == "face_indices") return sizeof(std::array<int, 3>) + sizeof(int);  // with a texture index
  if (list == "normal_indices" || list == "uv_indices") return sizeof(std::array<int, 3>);
  return 0;  // texture_list: textures are parsed (and counted) one by one
}

/// List items are read as arithmetic only, so `<1,-1> <-1,1>` without a comma is two vectors, not a
/// comparison (objects/mesh2.pov writes them so).
math::Vec3 as_vector(const Numeric& n) {
  return n.size == 1 ? math::Vec3(n.v[0], n.v[0], n.v[0]) : math::Vec3(n.v[0], n.v[1], n.v[2]);
}

}  // namespace

int Parser::parse_mesh2_count(const char* list) {
  expect("{", list);
  const scene::SourceLocation where = peek().where;
  const int count = parse_int(list, 0, kMaxMeshItems);
  if (count < 0) fail(where, std::string(list) + " count must not be negative");
  keep_memory(where, static_cast<uint64_t>(count) * bytes_per_item(list), std::string("mesh2 ") + list);
  accept(",");
  return count;
}

void Parser::end_mesh2_list(const char* list, int count, size_t read) {
  accept(",");
  if (!peek().is_symbol("}"))
    fail(peek().where, std::string(list) + " holds more items than its count " + std::to_string(count));
  raw_next();
  if (read != static_cast<size_t>(count))
    fail(peek().where, std::string(list) + " holds " + std::to_string(read) + " items, its count says " +
                           std::to_string(count));
}

/// `{ n, <a,b,c> [, t [, t2, t3]] ... }` index triples checked against the size of what they index.
std::vector<std::array<int, 3>> Parser::parse_mesh2_indices(const char* list, size_t limit,
                                                            std::vector<int>* textures) {
  const int count = parse_mesh2_count(list);
  std::vector<std::array<int, 3>> triples;
  triples.reserve(static_cast<size_t>(std::min(count, kMaxReserved)));
  for (int i = 0; i < count; ++i) {
    if (i > 0) accept(",");
    if (peek().is_symbol("}")) break;
    const scene::SourceLocation where = peek().where;
    const Numeric v = parse_argument_numeric();
    if (v.size < 3) fail(where, std::string(list) + " entries are <a, b, c> vectors");
    std::array<int, 3> t{};
    for (size_t k = 0; k < 3; ++k) {
      const double x = v.v[k];
      if (!(x >= 0 && x < static_cast<double>(limit)))
        fail(where, std::string(list) + " index " + std::to_string(x) + " is outside 0.." +
                        std::to_string(static_cast<long long>(limit) - 1));
      t[k] = static_cast<int>(x);
    }
    triples.push_back(t);
    // face_indices may give one texture index per face (or three, for interpolated textures).
    if (textures && peek().is_symbol(",")) {
      // Only a number right after the comma is a texture index; a '<' starts the next triple.
      raw_next();
      if (starts_numeric() && !peek().is_symbol("<")) {
        textures->push_back(static_cast<int>(parse_argument_numeric().v[0]));
        for (int extra = 0; extra < 2 && peek().is_symbol(","); ++extra) {
          raw_next();
          if (!starts_numeric() || peek().is_symbol("<")) break;
          parse_argument_numeric();
        }
      } else {
        textures->push_back(-1);
      }
    } else if (textures) {
      textures->push_back(-1);
    }
  }
  end_mesh2_list(list, count, triples.size());
  return triples;
}

ParsedObject Parser::parse_mesh2(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "mesh2");
  geometry::MeshData data;
  size_t textures_listed = 0;
  for (;;) {
    const Token t = peek();
    const std::string w = t.kind == Token::Kind::identifier ? t.text : std::string();
    if (w == "vertex_vectors" || w == "normal_vectors") {
      raw_next();
      auto& target = w == "vertex_vectors" ? data.vertices : data.normals;
      const int count = parse_mesh2_count(w.c_str());
      for (int i = 0; i < count && !peek().is_symbol("}"); ++i) {
        if (i > 0) accept(",");
        target.push_back(as_vector(parse_argument_numeric()));
      }
      end_mesh2_list(w.c_str(), count, target.size());
    } else if (w == "uv_vectors") {
      raw_next();
      const int count = parse_mesh2_count("uv_vectors");
      for (int i = 0; i < count && !peek().is_symbol("}"); ++i) {
        if (i > 0) accept(",");
        const Numeric v = parse_argument_numeric();
        data.uvs.push_back({v.v[0], v.size > 1 ? v.v[1] : v.v[0]});
      }
      end_mesh2_list("uv_vectors", count, data.uvs.size());
    } else if (w == "texture_list") {
      raw_next();
      const int count = parse_mesh2_count("texture_list");
      for (int i = 0; i < count && peek().is_word("texture"); ++i) {
        raw_next();
        skip_block("texture");
        ++textures_listed;
      }
      end_mesh2_list("texture_list", count, textures_listed);
      warn(t.where, "mesh2 per-face textures are not supported yet; the mesh's own texture is used");
    } else if (w == "face_indices") {
      raw_next();
      if (data.vertices.empty()) fail(t.where, "face_indices before vertex_vectors");
      data.faces = parse_mesh2_indices("face_indices", data.vertices.size(), &data.texture_indices);
      for (int& index : data.texture_indices)
        if (index >= static_cast<int>(textures_listed)) index = -1;
    } else if (w == "normal_indices") {
      raw_next();
      data.normal_indices = parse_mesh2_indices("normal_indices", data.normals.size(), nullptr);
    } else if (w == "uv_indices") {
      raw_next();
      data.uv_indices = parse_mesh2_indices("uv_indices", data.uvs.size(), nullptr);
    } else if (w == "inside_vector") {
      raw_next();
      data.inside_vector = parse_vector();
    } else {
      break;
    }
  }
  if (data.faces.empty()) fail(keyword.where, "mesh2 has no face_indices");
  // Without normal_indices, normals pair with vertices one to one (POV-Ray: then their counts must agree).
  if (data.normal_indices.empty() && !data.normals.empty()) {
    if (data.normals.size() != data.vertices.size())
      fail(keyword.where, "mesh2 without normal_indices needs as many normal_vectors as vertex_vectors");
    data.normal_indices = data.faces;
  }
  if (!data.normal_indices.empty() && data.normal_indices.size() != data.faces.size())
    fail(keyword.where, "mesh2 normal_indices must have one entry per face");
  if (!data.uv_indices.empty() && data.uv_indices.size() != data.faces.size())
    fail(keyword.where, "mesh2 uv_indices must have one entry per face");
  if (data.uv_indices.empty() && !data.uvs.empty() && data.uvs.size() != data.vertices.size())
    data.uvs.clear();            // POV-Ray ignores uv_vectors it cannot pair with the vertices
  data.texture_indices.clear();  // per-face textures: see the warning above
  if (const size_t n = count_degenerate_faces(data)) warn(keyword.where, degenerate_faces_message(n));
  return finish_shape(std::move(o), keyword, [&] { return shapes::mesh(std::move(data)); });
}

}  // namespace snell::sdl
