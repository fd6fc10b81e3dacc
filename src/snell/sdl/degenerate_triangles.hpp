#pragma once
// Triangles whose corners lie on a line or coincide (issue 12, faults in scenes). POV-Ray 3.7 warns
// "Degenerate triangle. Please remove." for a lone triangle and silently skips such faces of a mesh
// (parser.cpp, Parse_Triangle and Parse_Mesh); snell warns in both cases, once per mesh, and the faces
// render nothing: they have no normal, so shading them would give NaN.
#include <algorithm>
#include <cstddef>
#include <string>

#include "snell/geometry/mesh.hpp"
#include "snell/math/vec3.hpp"

namespace snell::sdl {

/// True when the triangle has no area, relative to its size (so a tiny but proper triangle is kept).
inline bool is_degenerate_triangle(const math::Vec3& a, const math::Vec3& b, const math::Vec3& c) {
  const math::Vec3 ab = b - a, ac = c - a;
  const double scale = std::max(math::length_squared(ab), math::length_squared(ac));
  const double area2 = math::length_squared(math::cross(ab, ac));
  return !(area2 > 1e-24 * scale * scale) || !(scale > 0);
}

inline size_t count_degenerate_faces(const geometry::MeshData& data) {
  size_t count = 0;
  for (const auto& f : data.faces)
    count += is_degenerate_triangle(data.vertices[static_cast<size_t>(f[0])],
                                    data.vertices[static_cast<size_t>(f[1])],
                                    data.vertices[static_cast<size_t>(f[2])]);
  return count;
}

inline std::string degenerate_faces_message(size_t count) {
  return std::to_string(count) + (count == 1 ? " triangle has" : " triangles have") +
         " no area (corners on one line); not rendered";
}

}  // namespace snell::sdl
