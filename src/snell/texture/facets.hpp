#pragma once
// `normal { facets [size s] [coords c] [metric m] }` (POV-Ray 3.7 reference, "facets"; behaviour of
// POV-Ray's normal.cpp facets()), a pattern for normals only:
// - without coords the normal itself, times 1/size, is snapped to the nearest of one random point per
//   unit cube, so a curved surface looks cut into flat facets;
// - with coords c the surface point (times 1/size) picks the nearest point, whose noise vector, made
//   tangent to the surface, tilts the normal by c: flat-looking cells on any surface.
// The random points are POV-Ray's (povray_point_in_cube), so the facets lie where POV-Ray's do.
#include "snell/texture/pattern.hpp"

namespace snell::texture {

struct FacetsParams {
  double size = 0.1;
  double coords = 0;
  /// 2 Euclidean; 1 POV-Ray's signed sum dx+dy+dz; others sum |d_i|^m.
  double metric = 2;
};

class FacetsPattern final : public ValuePattern, public NormalSetter {
 public:
  explicit FacetsPattern(const FacetsParams& params = {}) : params_(params) {}
  /// facets has no value of its own (POV-Ray refuses it outside normals): 0.
  double value(const Vec3&) const override { return 0; }
  Vec3 set_normal(const Vec3& p, const Vec3& n, double bump_size) const override;
  const FacetsParams& params() const { return params_; }
  /// The random point nearest to q (cell space) under the metric.
  Vec3 nearest_point(const Vec3& q) const;

 private:
  FacetsParams params_;
};

}  // namespace snell::texture
