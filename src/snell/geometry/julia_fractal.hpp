#pragma once
#include <array>

#include "snell/geometry/shape.hpp"

namespace snell::geometry {

using Vec4 = std::array<double, 4>;

/// POV-Ray `julia_fractal` (POV-Ray 3.7 reference, "Julia Fractal"): a 3D slice of the 4D Julia set of
/// z <- f(z) + c over quaternions or hypercomplex numbers, for f = sqr or cube. A point (x, y, z) stands for
/// the 4D point x e1 + y e2 + z e3 + distance n, where n is the slice normal and e1..e3 complete it to an
/// orthonormal basis. The solid is the set of points that stay within |z| <= 2 for max_iteration steps, as
/// POV-Ray draws it; rays march by the Julia set's distance estimate (Hart, Sandin & Kauffman 1989, "Ray
/// tracing deterministic 3-D fractals", SIGGRAPH: d = |z| ln|z| / (k |z'|) for the power k) and bisect.
class JuliaFractal final : public Shape {
 public:
  enum class Algebra { quaternion, hypercomplex };
  struct Settings {
    Vec4 c{};
    Algebra algebra = Algebra::quaternion;
    int power = 2;  // 2: sqr, 3: cube
    int max_iteration = 20;
    /// POV-Ray's `precision`: the shortest march step is 0.01 / precision.
    double precision = 20;
    Vec4 slice_normal{0, 0, 0, 1};
    double slice_distance = 0;
  };
  explicit JuliaFractal(const Settings& settings);

  Bounds3 bounds() const override { return {Vec3(-kBailoutRadius), Vec3(kBailoutRadius)}; }
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override { return distance_estimate(p) <= 0; }
  std::string_view kind() const override { return "julia_fractal"; }

  /// A lower bound of the distance to the set, 0 inside it.
  double distance_estimate(const Vec3& p) const;

  /// |z| beyond which the iteration escapes (POV-Ray's bailout |z|^2 > 4).
  static constexpr double kBailoutRadius = 2;

 private:
  Vec4 lift(const Vec3& p) const;
  /// One iteration z <- z^power + c.
  Vec4 step(const Vec4& z) const;
  /// Smooth escape potential whose gradient gives normals.
  double potential(const Vec3& p) const;

  Settings s_;
  Vec4 e_[3];
  /// Shortest march step: features of the set thinner than this may be missed.
  double min_step_;
};

}  // namespace snell::geometry
