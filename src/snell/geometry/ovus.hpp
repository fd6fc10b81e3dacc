#pragma once
// POV-Ray `ovus { bottom_radius, top_radius [radius R] [distance D] }` (POV-Ray 3.7 reference, "Ovus";
// `radius`, `distance` from 3.8): an egg around the y axis. A sphere of radius bottom_radius at the
// origin and one of radius top_radius at <0, D, 0> (D = bottom_radius by default) are joined by a
// spindle-torus band whose profile circle of radius R (default 2 max(bottom, top)) touches both spheres
// from inside.
#include "snell/geometry/arc_of_revolution.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

class Ovus final : public Shape {
 public:
  /// connecting_radius <= 0 and distance <= 0 take POV-Ray's defaults. Throws std::invalid_argument for
  /// the radii POV-Ray rejects.
  Ovus(double bottom_radius, double top_radius, double connecting_radius = 0, double distance = 0);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  std::string_view kind() const override { return "ovus"; }

  /// Heights where the band meets the bottom and the top sphere.
  double bottom_seam() const { return band_.y_lo; }
  double top_seam() const { return band_.y_hi; }
  /// True when the band vanished and the ovus is its top sphere alone (POV-Ray warns then).
  bool is_sphere() const { return band_.radius == 0; }

 private:
  template <typename Sink>
  void trace(const Ray& ray, double t_min, double t_max, Sink&& sink) const;

  double bottom_radius_, top_radius_, top_center_;
  ArcOfRevolution band_;
};

}  // namespace snell::geometry
