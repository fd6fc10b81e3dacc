#pragma once
// Embree 3 back end. Embree only builds and walks the BVH over padded float boxes; every surface test is
// Object::intersect in double precision, so Embree decides which objects to try, never what is hit. The
// exception are meshes of 64+ triangles: native float triangles, each hit redone in double by a filter
// before Embree may keep it (embree_meshes.hpp).
// <embree3/rtcore.h> stays in the .cpp (pimpl) so that including this header costs nothing.
#include <memory>
#include <vector>

#include "snell/accel/accelerator.hpp"

namespace snell::accel {

class EmbreeAccelerator final : public Accelerator {
 public:
  /// Builds the BVH. Throws std::runtime_error with Embree's message when Embree reports an error.
  explicit EmbreeAccelerator(const scene::Scene& scene);
  ~EmbreeAccelerator() override;
  EmbreeAccelerator(const EmbreeAccelerator&) = delete;
  EmbreeAccelerator& operator=(const EmbreeAccelerator&) = delete;

  /// Safe to call from many threads at once (rtcIntersect1 on a committed scene is read-only).
  bool intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                 scene::SurfaceHit& hit) const override;
  /// rtcOccluded1: traversal ends at the first object hit.
  const scene::Object* occluder(const math::Ray& ray, double t_min, double t_max,
                                scene::RayKind kind) const override;
  std::string_view name() const override { return "embree"; }
  AcceleratorStats stats() const override { return stats_; }

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
  AcceleratorStats stats_;
};

/// Starts Embree's one-time set-up (its task scheduler; about 5 ms, paid by the first device and scene of
/// a process) on a background thread, so that it overlaps parsing; the first EmbreeAccelerator waits for
/// it. Call early (the CLI does before it parses).
void warm_up_embree();

}  // namespace snell::accel
