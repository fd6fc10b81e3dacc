#pragma once
// Own bounding volume hierarchy over the scene's bounded objects (geometry/wide_bvh.hpp: eight-wide SAH
// tree, float boxes). Plain triangles (nearest_hit.hpp) sit in leaves of their own, packed eight to a
// TriangleBlock and filtered in single precision, eight or four lanes at a time; the few that may be hit
// are tested in double precision as Object::intersect would, and only the nearest builds a SurfaceHit.
// An occlusion query stops on a lane the filter calls a clear hit without that test.
// Unbounded objects are tested apart, as in the Embree back end.
#include <cstdint>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/accel/nearest_hit.hpp"
#include "snell/geometry/triangle_block.hpp"
#include "snell/geometry/wide_bvh.hpp"

namespace snell::accel {

class Bvh final : public Accelerator {
 public:
  explicit Bvh(const scene::Scene& scene);
  bool intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                 scene::SurfaceHit& hit) const override;
  /// Ends the walk at the first hit.
  const scene::Object* occluder(const math::Ray& ray, double t_min, double t_max,
                                scene::RayKind kind) const override;
  std::string_view name() const override { return "bvh"; }
  AcceleratorStats stats() const override { return stats_; }

 private:
  /// A leaf label with this bit names a block of triangles_, else the first of its objects in objects_.
  static constexpr uint32_t kTriangleLeaf = 1u << 31;

  /// The walk with `nearest` testing what the leaves hold; kAnyHit (occlusion queries) ends it at the first
  /// hit, on a lane the filter calls a clear hit where it can (triangle_block.hpp).
  template <int L, bool kAnyHit>
  void walk(NearestHit& nearest) const;

  geometry::WideBvh tree_;
  std::vector<const scene::Object*> objects_;  // in leaf order
  std::vector<PlainTriangle> triangles_;       // by the blocks' ids
  /// triangles_[i].object: what an occlusion query reads of a clear hit (8 bytes, not the 104 of a record).
  std::vector<const scene::Object*> triangle_objects_;
  std::vector<geometry::TriangleBlock> blocks_;
  /// The blocks' largest error scales: the filter's error terms are computed once per query from them.
  geometry::TriangleScales scales_;
  std::vector<const scene::Object*> unbounded_;
  AcceleratorStats stats_;
};

}  // namespace snell::accel
