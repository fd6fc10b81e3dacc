#pragma once
// POV-Ray `lathe`: a 2D profile (r, y) of spline pieces revolved around the y axis. A ray meets the
// surface where r(s)^2 equals the ray's squared distance from the axis at height y(s); eliminating t
// gives a polynomial of degree up to 6 in s per piece (as in POV-Ray's lathe.cpp).
#include "snell/geometry/axial_ray.hpp"
#include "snell/geometry/outline.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

class Lathe final : public Shape {
 public:
  /// Profile pieces with u = r (distance from the y axis) and v = y.
  explicit Lathe(Outline profile);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  /// Stops at the first crossing and builds no hit (shadow rays).
  bool crosses(const Ray& ray, double t_min, double t_max) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  std::string_view kind() const override { return "lathe"; }

 private:
  struct Crossing {
    double t;
    size_t piece;
    double s;
  };
  /// With kExistence (shadow rays), a piece whose height band lies inside (t_min, t_max) is only shown to
  /// have a root (has_root) and emitted without refining it.
  template <bool kExistence = false, typename F>
  void crossings(const Ray& ray, double t_min, const double& t_max, F&& emit) const;
  LocalHit make_hit(const Ray& ray, const Crossing& c) const;

  Outline profile_;
  double radius_;
  AxialReach reach_;  // for skipping the pieces a ray passes out of reach of
};

}  // namespace snell::geometry
