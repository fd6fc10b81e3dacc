#pragma once
#include <array>

#include "snell/geometry/hit_buffer.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// POV-Ray `torus { major, minor }` in the xz plane around the y axis; exact quartic roots.
class Torus final : public Shape {
 public:
  Torus(double major_radius, double minor_radius);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  /// Stops at the first crossing and builds no hit (shadow rays).
  bool crosses(const Ray& ray, double t_min, double t_max) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  bool inside_within_bounds() const override { return true; }
  std::string_view kind() const override { return "torus"; }

 private:
  /// Adds the crossings to `hits`; with `max_roots`, only those of the smallest max_roots roots (see
  /// real_roots). Returns whether a root was refused by `hits` (its t rounded outside the window).
  bool gather(const Ray& ray, HitBuffer<4>& hits, int max_roots = 4) const;
  /// The ray's quartic in u = f + t |d| (a unit direction dn from the point o), and the window of u
  /// that can hold its roots in (t_min, t_max); false when that window is empty.
  struct Quartic {
    Vec3 o, dn;
    double f, dl, u_lo, u_hi;
    std::array<double, 5> coeffs;
  };
  bool quartic_along(const Ray& ray, double t_min, double t_max, Quartic& q) const;
  LocalHit make_hit(const Vec3& p, double t) const;

  double major_, minor_;
};

}  // namespace snell::geometry
