#pragma once
// POV-Ray `sphere_sweep`: the volume a sphere of varying radius sweeps along a spline. A linear piece is
// exactly two spheres joined by the cone tangent to both; b_spline and cubic_spline pieces are
// approximated by kSweepSteps linear steps each (POV-Ray solves the curved envelope numerically).
// The solid is the union of these parts; a crossing counts when it lies inside no other part.
#include <memory>
#include <span>
#include <vector>

#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// A sphere of the sweep: centre and radius.
struct SweepSphere {
  Vec3 center;
  double radius = 0;
};

enum class SweepSpline { linear, b_spline, cubic };

/// Linear steps per curved spline piece.
inline constexpr int kSweepSteps = 16;

/// The spheres along the sweep's path: the given ones for linear splines, sampled along a uniform cubic
/// B-spline or a Catmull-Rom spline otherwise (POV-Ray 3.7 reference, "Sphere Sweep").
std::vector<SweepSphere> sweep_path(SweepSpline spline, std::span<const SweepSphere> points);

class SphereSweep final : public Shape {
 public:
  explicit SphereSweep(const std::vector<SweepSphere>& path);

  Bounds3 bounds() const override { return bounds_; }
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  bool inside_within_bounds() const override { return true; }
  std::string_view kind() const override { return "sphere_sweep"; }

 private:
  struct Part {
    std::unique_ptr<Shape> shape;
    Bounds3 bounds;
  };
  bool inside_other(const Vec3& p, size_t part) const;
  /// Surface crossings of the union, sorted.
  void union_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const;

  std::vector<Part> parts_;
  Bounds3 bounds_;
};

}  // namespace snell::geometry
