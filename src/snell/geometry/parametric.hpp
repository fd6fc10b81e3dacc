#pragma once
// POV-Ray `parametric { function{x(u,v)} function{y(u,v)} function{z(u,v)} <u0,v0>, <u1,v1>
// [contained_by{..}] [max_gradient G] [accuracy A] [precompute ..] }` (POV-Ray 3.7 reference, "Parametric").
// The surface S(u, v) over the rectangle [u0, u1] x [v0, v1], shown where it lies inside the container.
#include <array>
#include <memory>

#include "snell/function/function.hpp"
#include "snell/geometry/mesh.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

struct ParametricSettings {
  /// x(u, v), y(u, v), z(u, v): functions of three arguments called as (u, v, 0), as POV-Ray's u and v
  /// alias x and y.
  std::array<std::shared_ptr<const function::Function>, 3> functions;
  Vec2 uv_min{0, 0}, uv_max{1, 1};
  /// `contained_by { box | sphere }`; POV-Ray's default is box{-1, 1}.
  std::shared_ptr<const Shape> container;
  /// The parameter step of the normal's finite differences (POV-Ray's `accuracy`).
  double accuracy = 0.001;
  /// Cells per side of the search lattice (POV-Ray's `max_gradient` and `precompute` steer its
  /// subdivision instead; snell reads them but its lattice does not depend on them).
  int lattice = 128;
};

/// Ray casting differs from POV-Ray's interval subdivision of the (u, v) rectangle: the surface is sampled
/// on a lattice and cut into triangles (under the mesh BVH) to find which patch a ray meets, then Newton's
/// method on S(u, v) = o + t d from that triangle's (u, v, t) puts the hit on the true surface. Like
/// POV-Ray's, a parametric has no inside and reports only its nearest crossing; `uv` is (u, v).
class Parametric final : public Shape {
 public:
  explicit Parametric(ParametricSettings settings);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3&) const override { return false; }
  std::string_view kind() const override { return "parametric"; }

  Vec3 point(double u, double v) const;

 private:
  /// Moves (u, v, t) onto the true surface; false when Newton leaves the rectangle or does not converge.
  bool polish(const Ray& ray, double& u, double& v, double& t) const;
  Vec3 normal_at(double u, double v) const;

  ParametricSettings settings_;
  std::unique_ptr<Mesh> lattice_;
};

}  // namespace snell::geometry
