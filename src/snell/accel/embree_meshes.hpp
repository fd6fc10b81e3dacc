#pragma once
// Meshes as Embree's native triangles: each distinct mesh becomes one Embree scene of float triangles,
// placed by an instance per object that uses it (so a mesh placed a thousand times is stored once). Embree
// then picks the nearest triangle in float; an intersection filter redoes each candidate in double
// precision (Mesh::face_hit) and accepts it only when it is nearer than the best double hit so far, so
// hits, normals and textures stay what Object::intersect gives. Included only by embree_accelerator.cpp
// (it needs <embree3/rtcore.h>).
#include <embree3/rtcore.h>

#include <unordered_map>

#include "snell/geometry/mesh.hpp"
#include "snell/scene/object.hpp"

namespace snell::accel {

/// Meshes with fewer faces stay user geometry (their own double-precision BVH). Embree's float walk plus
/// the double confirmation of its candidate (triangle_filter) pays already for small meshes: POV-Ray's
/// objects/mesh2.pov, six meshes of 24 faces, took 15% fewer instructions with them native (threshold 64
/// -> 8, the image unchanged). Below a block of eight faces, the instance costs more than it saves.
inline constexpr size_t kNativeMeshMinFaces = 8;

/// The most triangles the copies of one mesh (one per object showing it) may take to be placed in world
/// space each (MeshSceneCache::attach_in_world) rather than instanced: a few MiB of float vertices and
/// Embree nodes at most, for one level of walk instead of two.
inline constexpr size_t kWorldMeshTriangles = 65536;

/// Largest coordinate of a box handed to Embree: its builder silently drops primitives whose bounds leave
/// its valid float range (|x| < 1.844e18, FLT_LARGE in Embree's sources).
inline constexpr double kMaxEmbreeCoordinate = 1e18;

/// Whether Embree can walk a box: finite, not empty and inside kMaxEmbreeCoordinate.
bool embree_can_hold(const math::Bounds3& box);

/// The mesh of a still, non-CSG object without `bounded_by` whose own vertices Embree can hold in float,
/// or null. The caller checks the object's world box with embree_can_hold.
const geometry::Mesh* native_mesh_of(const scene::Object& object);

/// Embree scenes of float triangles, one per distinct mesh, released with the cache.
class MeshSceneCache {
 public:
  MeshSceneCache(RTCDevice device, void* filter_user_data, RTCFilterFunctionN filter)
      : device_(device), user_data_(filter_user_data), filter_(filter) {}
  ~MeshSceneCache();
  MeshSceneCache(const MeshSceneCache&) = delete;
  MeshSceneCache& operator=(const MeshSceneCache&) = delete;

  /// The committed scene of `mesh`, built on first use.
  RTCScene scene_of(const geometry::Mesh& mesh);
  /// Attaches `mesh` to `top` as triangles placed in world space by `object`'s transform, for small
  /// meshes (kWorldMeshTriangles): one level of Embree's walk instead of two (an instance's ray moved into
  /// its space and a second tree). Returns the geometry id.
  unsigned attach_in_world(RTCScene top, const geometry::Mesh& mesh, const scene::Object& object);
  size_t triangles() const { return triangles_; }

 private:
  RTCDevice device_;
  void* user_data_;
  RTCFilterFunctionN filter_;
  std::unordered_map<const geometry::Mesh*, RTCScene> scenes_;
  size_t triangles_ = 0;
};

/// Attaches an instance of `mesh_scene` placed by `object`'s transform to `top`; returns its geometry id.
unsigned attach_mesh_instance(RTCDevice device, RTCScene top, RTCScene mesh_scene,
                              const scene::Object& object);

}  // namespace snell::accel
