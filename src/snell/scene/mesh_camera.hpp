#pragma once
// POV-Ray 3.7's experimental `mesh_camera` (reference "Mesh Camera"; behaviour as POV-Ray's tracepixel.cpp
// implements it): each pixel's ray leaves a face of one of the camera meshes, from the face's centroid (or,
// for distribution 3, the point whose uv coordinates are the pixel's) along the face normal.
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "snell/geometry/mesh.hpp"
#include "snell/math/ray.hpp"
#include "snell/math/transform.hpp"

namespace snell::scene {

/// One `mesh { ... }` of a mesh_camera: its triangles in object space and its object-to-world transform.
struct MeshCameraMesh {
  std::shared_ptr<const geometry::Mesh> mesh;
  math::Transform to_world;
};

/// `mesh_camera { rays_per_pixel distribution_type [max_distance] mesh {...}... [smooth] }`.
struct MeshCameraSpec {
  int rays_per_pixel = 1;
  /// 0: ray n of pixel p uses face p of mesh n; 1: all meshes' faces in one list, ray n of pixel p uses face
  /// p + n * width * height; 2: the image is split into one column block per mesh, side by side; 3: the
  /// pixel's (u, v) picks the face of the first mesh whose uv triangle contains it.
  int distribution = 0;
  /// Camera rays find nothing farther than this; 0 for no limit.
  double max_distance = 0;
  /// Distribution 3 only: interpolate the vertex normals of smooth triangles.
  bool smooth = false;
  std::vector<MeshCameraMesh> meshes;
};

/// Makes the rays of a mesh camera for an image of width x height pixels.
class MeshCameraRays {
 public:
  /// `offset` moves each ray's origin along its direction (POV-Ray uses the camera's location.z);
  /// `reverse` shoots against the face normals (POV-Ray: direction.z < 0).
  MeshCameraRays(const MeshCameraSpec& spec, double offset, bool reverse, int width, int height);

  int rays_per_pixel() const { return spec_.rays_per_pixel; }
  /// Ray `ray_number` (0-based, below rays_per_pixel) for image point (sx, sy) in [0,1]^2, y down; nothing
  /// when the pixel has no face (POV-Ray traces no ray there). The direction is not normalised.
  std::optional<math::Ray> ray(double sx, double sy, int ray_number, double time) const;

 private:
  /// A non-degenerate triangle (POV-Ray drops degenerate ones, so they take no face index).
  struct Face {
    std::array<math::Vec3, 3> p;
    /// POV-Ray's face normal: unit cross(P3 - P1, P2 - P1) (mesh.cpp, Compute_Mesh_Triangle).
    math::Vec3 normal;
    std::optional<std::array<math::Vec3, 3>> vertex_normals;
    std::array<math::Vec2, 3> uv{};
  };
  struct FaceList {
    std::vector<Face> faces;
    const math::Transform* to_world = nullptr;
  };

  std::optional<math::Ray> from_face(const FaceList& mesh, size_t face, double time) const;
  std::optional<math::Ray> from_uv(double u, double v, double time) const;

  MeshCameraSpec spec_;
  double offset_;
  bool reverse_;
  int width_, height_;
  std::vector<FaceList> meshes_;
  /// Distribution 3: for each cell of a kUvGrid x kUvGrid grid over uv [0,1]^2, the faces of the first mesh
  /// whose uv bounding box touches it, in face order.
  static constexpr int kUvGrid = 32;
  std::vector<std::vector<int>> uv_cells_;
};

}  // namespace snell::scene
