#pragma once
// POV-Ray `lemon { <base>, base_radius, <cap>, cap_radius, inner_radius [open] }` (POV-Ray 3.8 reference,
// "Lemon"; Debian's POV-Ray 3.7.0 lacks it): the solid swept by a circular arc of radius inner_radius
// turned around the axis from base to cap. The arc runs from the base's rim to the cap's rim, bulging
// outwards, with its centre across the axis; flat discs close both ends unless `open`.
#include "snell/geometry/arc_of_revolution.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

class Lemon final : public Shape {
 public:
  /// Throws std::invalid_argument for negative radii or coincident end points. An inner radius below
  /// the smallest one POV-Ray allows is raised to it; `adjusted_inner_radius()` tells.
  Lemon(const Vec3& base, double base_radius, const Vec3& cap, double cap_radius, double inner_radius,
        bool open);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  std::string_view kind() const override { return "lemon"; }

  /// The inner radius actually used (in scene units); larger than requested when it was too small.
  double inner_radius() const { return arc_.radius * length_; }

 private:
  template <typename Sink>
  void trace(const Ray& ray, double t_min, double t_max, Sink&& sink) const;
  /// Scene point to the unit frame: base at the origin, cap at <0, 1, 0>.
  Vec3 to_unit(const Vec3& p) const;
  Vec3 from_unit_direction(const Vec3& d) const;

  Vec3 base_;
  Vec3 u_, w_, v_;  // orthonormal frame, w_ along the axis (the unit frame's y)
  double length_;
  double base_radius_, cap_radius_;  // in the unit frame
  bool open_;
  ArcOfRevolution arc_;  // in the unit frame
};

}  // namespace snell::geometry
