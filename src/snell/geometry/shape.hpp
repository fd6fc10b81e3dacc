#pragma once
// The Shape interface: one geometric primitive in its own coordinate space. Objects (scene/object.hpp)
// add the transform, texture and flags. Rays reaching a shape are already in its space and their
// direction is NOT unit length (t stays the world-space parameter), so every shape must handle that.
#include <memory>
#include <string_view>
#include <vector>

#include "snell/math/bounds.hpp"
#include "snell/math/ray.hpp"
#include "snell/math/transform.hpp"
#include "snell/math/vec3.hpp"

namespace snell::geometry {

using math::Bounds3;
using math::Ray;
using math::Vec2;
using math::Vec3;

/// A crossing of a ray with a shape's surface, in shape space.
struct LocalHit {
  double t = 0;
  /// Outward geometric normal in shape space (need not be unit length).
  Vec3 normal;
  /// Interpolated normal for smooth shading (smooth_triangle, mesh normals); zero when absent.
  Vec3 shading_normal;
  Vec2 uv;
  /// Shape-specific detail (triangle index, blob component...), -1 when unused.
  int part = -1;
};

using HitList = std::vector<LocalHit>;

class Shape {
 public:
  virtual ~Shape() = default;

  /// Bounds in shape space; `Bounds3::infinite()` for unbounded shapes such as planes.
  virtual Bounds3 bounds() const = 0;
  /// Bounds of the part of the inside that lies in `box` (shape space): a CSG intersection confines
  /// unbounded children with the others' boxes (POV-Ray csg.cpp, CSG::Compute_BBox). By default the
  /// shape's own bounds cut by the box.
  virtual Bounds3 inside_bounds_within(const Bounds3& box) const { return bounds().intersection(box); }
  /// Nearest crossing with t in (t_min, t_max). Returns false when there is none.
  virtual bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const = 0;
  /// Whether intersect would find a crossing (shadow rays): shapes whose hits cost more than their test
  /// (a sphere's uv is an atan2 and an acos) answer without building one.
  virtual bool crosses(const Ray& ray, double t_min, double t_max) const {
    LocalHit hit;
    return intersect(ray, t_min, t_max, hit);
  }
  /// Appends every crossing with t in (t_min, t_max), in increasing t (for CSG and filtered shadows).
  virtual void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const = 0;
  /// The parameters where the ray first crosses the shape and next crosses it again, over all t: for a
  /// convex shape, where it enters and leaves (an isosurface's container). False when there is no second
  /// crossing (a miss, or a graze). By default two calls of intersect; shapes override it with one solve.
  virtual bool span(const Ray& ray, double& t_entry, double& t_exit) const;
  /// Whether `p` (shape space) lies inside the solid. Open/flat shapes answer as POV-Ray does.
  virtual bool inside(const Vec3& p) const = 0;
  /// The same shape moved by `t` into the space `t` maps to, with the same normals and uv at the same
  /// points, or null when this shape cannot take `t` that way (then the object keeps the transform and
  /// moves every ray instead). Objects bake simple placements (translate, scale) into their shapes this
  /// way, as POV-Ray moves a sphere's centre rather than keep a transform.
  virtual std::shared_ptr<const Shape> placed(const math::Transform& /*t*/) const { return nullptr; }
  /// Whether inside() is false everywhere outside bounds(), so that a box test can answer it there. Not
  /// so for a disc (its whole lower half-space is inside, as in POV-Ray); the shapes that are say so.
  virtual bool inside_within_bounds() const { return false; }
  /// The POV-Ray keyword of the shape, for statistics and messages.
  virtual std::string_view kind() const = 0;
};

}  // namespace snell::geometry
