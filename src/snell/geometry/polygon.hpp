#pragma once
// POV-Ray `polygon`: flat sub-polygons in one plane, filled by the even-odd rule (a sub-polygon ends
// where a point repeats its first point, so holes are sub-polygons inside others; an unclosed last one
// is closed). Flat: never inside.
#include <span>

#include "snell/geometry/outline.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

class Polygon final : public Shape {
 public:
  /// Throws std::invalid_argument when the points do not span a plane.
  explicit Polygon(std::span<const Vec3> points);

  Bounds3 bounds() const override { return bounds_; }
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3&) const override { return false; }
  std::string_view kind() const override { return "polygon"; }

 private:
  Vec3 origin_, axis_u_, axis_v_, normal_;
  Outline outline_;
  Bounds3 bounds_;
};

}  // namespace snell::geometry
