#pragma once
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// POV-Ray `plane { normal, distance }`: the points p with n.p = d for the normalised n; as in POV-Ray the
/// distance is NOT rescaled by the normal's length. The inside is the half-space the normal points away from.
class Plane final : public Shape {
 public:
  Plane(const Vec3& normal, double distance);

  /// The half-space of the inside when the normal lies along an axis (it holds the surface too), as POV-Ray
  /// bounds such planes in a CSG intersection (quadric.cpp, Compute_Plane_Min_Max); else everything.
  Bounds3 bounds() const override { return bounds_; }
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  bool crosses(const Ray& ray, double t_min, double t_max) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override { return dot(normal_, p) < distance_; }
  std::string_view kind() const override { return "plane"; }

  const Vec3& normal() const { return normal_; }
  double distance() const { return distance_; }

 private:
  /// The ray's parameter where it crosses the plane, when that lies in (t_min, t_max).
  bool crossing(const Ray& ray, double t_min, double t_max, double& t) const;
  Vec3 normal_;
  double distance_;
  Bounds3 bounds_ = Bounds3::infinite();
};

}  // namespace snell::geometry
