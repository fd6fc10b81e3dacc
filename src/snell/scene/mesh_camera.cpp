// Mesh camera rays, following the behaviour of POV-Ray 3.7's mesh_camera (tracepixel.cpp, MESH_CAMERA;
// parser.cpp, Parse_Mesh_Camera): the pixel's column and row index a face, the ray starts at the face's
// centroid moved `offset` along the face normal in the mesh's own space, and both are then carried to the
// world by the mesh's transform (the normal by the inverse transpose).
#include "snell/scene/mesh_camera.hpp"

#include <algorithm>
#include <cmath>

namespace snell::scene {

using math::Vec2;
using math::Vec3;

namespace {

int uv_cell(double t, int cells) {
  return std::clamp(static_cast<int>(std::floor(t * cells)), 0, cells - 1);
}

}  // namespace

MeshCameraRays::MeshCameraRays(const MeshCameraSpec& spec, double offset, bool reverse, int width, int height)
    : spec_(spec), offset_(offset), reverse_(reverse), width_(width), height_(height) {
  for (const MeshCameraMesh& m : spec_.meshes) {
    FaceList list;
    list.to_world = &m.to_world;
    const geometry::MeshData& d = m.mesh->data();
    for (size_t i = 0; i < d.faces.size(); ++i) {
      Face f;
      for (size_t k = 0; k < 3; ++k) f.p[k] = d.vertices[static_cast<size_t>(d.faces[i][k])];
      const Vec3 n = cross(f.p[2] - f.p[0], f.p[1] - f.p[0]);
      if (length_squared(n) == 0) continue;  // degenerate: POV-Ray leaves it out of the mesh
      f.normal = normalize(n);
      if (i < d.normal_indices.size()) {
        std::array<Vec3, 3> vn;
        bool usable = true;
        for (size_t k = 0; k < 3; ++k) {
          vn[k] = d.normals[static_cast<size_t>(d.normal_indices[i][k])];
          if (length_squared(vn[k]) == 0)
            usable = false;
          else
            vn[k] = normalize(vn[k]);
        }
        // Equal vertex normals make a flat triangle in POV-Ray (Parse_Mesh1), which keeps its face normal.
        const bool flat = length_squared(vn[0] - vn[1]) <= 1e-10 && length_squared(vn[0] - vn[2]) <= 1e-10;
        if (usable && !flat) f.vertex_normals = vn;
      }
      if (i < d.uv_indices.size())
        for (size_t k = 0; k < 3; ++k) f.uv[k] = d.uvs[static_cast<size_t>(d.uv_indices[i][k])];
      list.faces.push_back(f);
    }
    meshes_.push_back(std::move(list));
  }
  if (spec_.distribution == 3 && !meshes_.empty()) {
    uv_cells_.resize(static_cast<size_t>(kUvGrid * kUvGrid));
    const auto& faces = meshes_.front().faces;
    for (size_t i = 0; i < faces.size(); ++i) {
      const auto& uv = faces[i].uv;
      const auto [u0, u1] = std::minmax({uv[0].u, uv[1].u, uv[2].u});
      const auto [v0, v1] = std::minmax({uv[0].v, uv[1].v, uv[2].v});
      for (int cv = uv_cell(v0, kUvGrid); cv <= uv_cell(v1, kUvGrid); ++cv)
        for (int cu = uv_cell(u0, kUvGrid); cu <= uv_cell(u1, kUvGrid); ++cu)
          uv_cells_[static_cast<size_t>(cv * kUvGrid + cu)].push_back(static_cast<int>(i));
    }
  }
}

std::optional<math::Ray> MeshCameraRays::ray(double sx, double sy, int ray_number, double time) const {
  if (meshes_.empty()) return std::nullopt;
  // Distribution 3 is continuous in the image; the others index faces by whole pixels.
  if (spec_.distribution == 3) return from_uv(sx, 1 - sy, time);
  const auto column =
      static_cast<size_t>(std::clamp(static_cast<int>(std::floor(sx * width_)), 0, width_ - 1));
  const auto row =
      static_cast<size_t>(std::clamp(static_cast<int>(std::floor(sy * height_)), 0, height_ - 1));
  const auto width = static_cast<size_t>(width_);
  switch (spec_.distribution) {
    case 0: {
      if (ray_number < 0 || static_cast<size_t>(ray_number) >= meshes_.size()) return std::nullopt;
      return from_face(meshes_[static_cast<size_t>(ray_number)], row * width + column, time);
    }
    case 1: {
      // All meshes' faces in one list; ray n of pixel p takes face p + n * width * height, as the reference
      // documents it (POV-Ray 3.7's code adds n * total faces instead, so no ray after the first is traced).
      const size_t pixels = width * static_cast<size_t>(height_);
      size_t face = row * width + column + static_cast<size_t>(ray_number) * pixels;
      for (const FaceList& mesh : meshes_) {
        if (face < mesh.faces.size()) return from_face(mesh, face, time);
        face -= mesh.faces.size();
      }
      return std::nullopt;
    }
    case 2: {
      // Side-by-side sub-cameras: mesh k covers the k-th block of width / meshes columns. Like POV-Ray, the
      // face index is row * (width / meshes) + column with the column counted from the image's left edge,
      // not the block's (so blocks after the first start that many faces further on).
      const size_t block = std::max<size_t>(width / meshes_.size(), 1);
      const size_t mesh = std::min(column / block, meshes_.size() - 1);
      return from_face(meshes_[mesh], row * block + column, time);
    }
    default:
      return std::nullopt;
  }
}

std::optional<math::Ray> MeshCameraRays::from_face(const FaceList& mesh, size_t face, double time) const {
  if (face >= mesh.faces.size()) return std::nullopt;
  const Face& f = mesh.faces[face];
  const Vec3 centroid = (f.p[0] + f.p[1] + f.p[2]) / 3.0;
  const Vec3 origin = centroid + offset_ * f.normal;
  const Vec3 direction = reverse_ ? -f.normal : f.normal;
  return math::Ray{mesh.to_world->point(origin), mesh.to_world->normal(direction), time};
}

std::optional<math::Ray> MeshCameraRays::from_uv(double u, double v, double time) const {
  const FaceList& mesh = meshes_.front();
  for (const int index :
       uv_cells_[static_cast<size_t>(uv_cell(v, kUvGrid) * kUvGrid + uv_cell(u, kUvGrid))]) {
    const Face& f = mesh.faces[static_cast<size_t>(index)];
    const Vec2 &a = f.uv[0], &b = f.uv[1], &c = f.uv[2];
    // Barycentric coordinates of (u, v) in the face's uv triangle (signed areas).
    const double area = (b.u - a.u) * (c.v - a.v) - (c.u - a.u) * (b.v - a.v);
    if (area == 0) continue;
    const double b1 = ((b.u - u) * (c.v - v) - (c.u - u) * (b.v - v)) / area;
    const double b2 = ((c.u - u) * (a.v - v) - (a.u - u) * (c.v - v)) / area;
    const double b3 = 1 - b1 - b2;
    if (b1 < 0 || b2 < 0 || b3 < 0) continue;
    const Vec3 point = b1 * f.p[0] + b2 * f.p[1] + b3 * f.p[2];
    Vec3 normal = f.normal;
    if (spec_.smooth && f.vertex_normals) {
      const auto& n = *f.vertex_normals;
      normal = b1 * n[0] + b2 * n[1] + b3 * n[2];
    }
    // The offset runs along the (possibly interpolated, not renormalised) normal before any reversal, as in
    // POV-Ray.
    const Vec3 origin = point + offset_ * normal;
    return math::Ray{mesh.to_world->point(origin), mesh.to_world->normal(reverse_ ? -normal : normal), time};
  }
  return std::nullopt;
}

}  // namespace snell::scene
