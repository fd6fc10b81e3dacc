#pragma once
#include <array>
#include <vector>

#include "snell/geometry/shape.hpp"
#include "snell/math/transform.hpp"

namespace snell::geometry {

/// One POV-Ray blob component: `sphere { center, radius, strength }` or
/// `cylinder { end1, end2, radius, strength }` (the old `component strength, radius, center` is a sphere).
struct BlobComponent {
  enum class Kind { sphere, cylinder };
  Kind kind = Kind::sphere;
  Vec3 center;  // sphere centre, or cylinder end 1
  Vec3 end;     // cylinder end 2
  double radius = 1;
  double strength = 1;
  math::Transform transform;  // component's own transform (component space -> blob space)
};

/// POV-Ray `blob`: the surface where the summed field of the components equals `threshold`; each
/// component contributes strength * (1 - (r/R)^2)^2 inside its radius R (POV-Ray 3.7 documentation,
/// "Blob"). Roots are found exactly on the piecewise quartic along the ray.
class Blob final : public Shape {
 public:
  Blob(double threshold, std::vector<BlobComponent> components);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  std::string_view kind() const override { return "blob"; }

  /// The summed field at p (blob space).
  double density(const Vec3& p) const;
  double threshold() const { return threshold_; }

 private:
  /// One component's share of the field along a ray: sum_i c[i] s^i on [s0, s1] (s: local ray parameter).
  struct Piece {
    double s0, s1;
    std::array<double, 5> c;
  };
  void collect_pieces(const BlobComponent& comp, const Ray& ray, std::vector<Piece>& pieces) const;
  void find_roots(const Ray& ray, double t_min, double t_max, bool first_only, HitList& out) const;
  LocalHit make_hit(const Vec3& p, double t) const;
  Bounds3 influence_bounds() const;

  double threshold_;
  std::vector<BlobComponent> components_;
  Bounds3 bounds_;  // influence_bounds(), which every ray clips against
};

}  // namespace snell::geometry
