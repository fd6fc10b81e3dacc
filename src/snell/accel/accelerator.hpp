#pragma once
// Ray queries over the whole scene. Back ends: Embree (default), an own SAH BVH, an octree, a uniform grid
// and brute force. Unbounded objects (planes) are tested apart from the structure.
#include <memory>
#include <string>
#include <string_view>

#include "snell/scene/scene.hpp"

namespace snell::accel {

struct AcceleratorStats {
  size_t objects = 0;
  size_t unbounded_objects = 0;
  double build_seconds = 0;
  /// Nodes (grid: cells) and bytes of the structure; 0 where not known (Embree, brute force).
  size_t nodes = 0;
  size_t memory_bytes = 0;
  /// Embree only: triangles stored natively (each distinct mesh once) and the instances placing them.
  size_t native_triangles = 0;
  size_t mesh_instances = 0;
};

class Accelerator {
 public:
  virtual ~Accelerator() = default;
  /// Nearest hit with t in (t_min, t_max) among objects visible to `kind`.
  virtual bool intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                         scene::SurfaceHit& hit) const = 0;
  /// For shadow rays through opaque scenes: some object visible to `kind` hit with t in (t_min, t_max)
  /// (the one found first, not necessarily the nearest), or null. Stops at the first hit, and builds no
  /// SurfaceHit for the caller; this default asks intersect().
  virtual const scene::Object* occluder(const math::Ray& ray, double t_min, double t_max,
                                        scene::RayKind kind) const;
  virtual std::string_view name() const = 0;
  virtual AcceleratorStats stats() const = 0;
};

/// The back ends' names, for messages: "list" culls each object by its box (no tree), "none" is brute force.
inline constexpr std::string_view kAcceleratorKinds = "embree, bvh, octree, grid, list or none";

/// Whether make_accelerator knows `kind`.
bool is_accelerator_kind(std::string_view kind);

/// `kind` is one of kAcceleratorKinds. Throws std::invalid_argument for unknown kinds.
std::unique_ptr<Accelerator> make_accelerator(std::string_view kind, const scene::Scene& scene);

}  // namespace snell::accel
