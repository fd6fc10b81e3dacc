#pragma once
// Many round cones in one shape, as an L-system's branches need: each branch is a cone frustum from a
// (radius r0) to b (radius r1) closed by a sphere at each end, which also fills the joints between
// branches. Branches are stored in floats (36 bytes) under one compact BVH (compact_bvh.hpp), about 52 bytes
// per branch in all, so a million of them take tens of megabytes instead of a scene object each; a declared
// branch set is shared by every copy.
#include <memory>
#include <span>
#include <vector>

#include "snell/geometry/shape.hpp"

namespace snell::geometry {

class CompactBvh;

struct RoundCone {
  float a[3];
  /// Unit axis from a to b.
  float axis[3];
  float length;
  float r0, r1;
};

struct BranchInput {
  Vec3 a, b;
  double r0 = 0, r1 = 0;
};

class BranchSet final : public Shape {
 public:
  /// Branches with no length and no radius are left out; throws std::invalid_argument when none remain.
  explicit BranchSet(std::span<const BranchInput> branches);
  ~BranchSet() override;

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  std::string_view kind() const override { return "lsystem"; }

  std::size_t size() const { return cones_.size(); }
  /// Bytes held by the branches and their BVH.
  std::size_t bytes() const;

 private:
  template <class Sink>
  void crossings(const Ray& ray, double t_min, double& t_max, Sink&& sink) const;

  std::vector<RoundCone> cones_;
  std::unique_ptr<CompactBvh> bvh_;
};

}  // namespace snell::geometry
