#pragma once
// The scene's objects in one flat list, each culled by its box before its own test: no tree to walk. For
// scenes of a few objects this is the cheapest search (POV-Ray's example scenes mostly hold 2 to 20
// top-level objects, where Embree's walk through its user-geometry callbacks, or the BVH's, costs more than
// the boxes it skips; measured in docs/performance.md, "Small scenes"), and `auto` picks it for them.
#include <chrono>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/accel/box_lanes.hpp"
#include "snell/accel/indexed_objects.hpp"

namespace snell::accel {

/// Most bounded objects for which `auto` picks the list. Callgrind instructions per render (80x60) of
/// POV-Ray scenes, list (boxes four at a time) against Embree: 2 objects (csg/granite) -12%, 3 (crystal)
/// -13%, 4 (pigmap, phot_met_glass; boxes one at a time) -6% and -4%, 16 (focalblur, pigment) +3.5% and
/// +8.7%, 18 (wood_1) +0.7%, 76 (golds) +97%.
inline constexpr size_t kBoxListMaxObjects = 8;

/// Whether `auto` should take the list for `scene`: at most kBoxListMaxObjects bounded objects and no mesh,
/// which Embree walks as native triangles (a mesh with its own tree in the list made objects/mesh2.pov
/// 12% dearer).
bool prefers_box_list(const scene::Scene& scene);

class BoxList final : public Accelerator {
 public:
  explicit BoxList(const scene::Scene& scene);
  bool intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                 scene::SurfaceHit& hit) const override;
  const scene::Object* occluder(const math::Ray& ray, double t_min, double t_max,
                                scene::RayKind kind) const override;
  std::string_view name() const override { return "list"; }
  AcceleratorStats stats() const override { return stats_; }

 private:
  /// Built from `indexed`, timed from `start` (so the stats' build time includes sorting the objects).
  BoxList(std::chrono::steady_clock::time_point start, IndexedObjects indexed);

  std::vector<const scene::Object*> bounded_;
  std::vector<const scene::Object*> unbounded_;
  BoxLanes lanes_;  // the boxes of bounded_, four at a time
  AcceleratorStats stats_;
};

}  // namespace snell::accel
