#pragma once
// An Object is what the scene holds and the accelerator indexes: a shape in its own space, the transform
// that places it, its texture and interior, and POV-Ray's object flags.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "snell/geometry/shape.hpp"
#include "snell/material/interior.hpp"
#include "snell/material/texture.hpp"
#include "snell/math/transform.hpp"
#include "snell/scene/motion.hpp"
#include "snell/scene/photon_settings.hpp"
#include "snell/scene/source_location.hpp"

namespace snell::scene {

using math::Ray;
using math::Vec3;

/// What a ray is for; objects flagged `no_image`, `no_reflection` or `no_shadow` are invisible to it.
enum class RayKind { camera, reflection, refraction, shadow };

struct ObjectFlags {
  bool no_shadow = false;
  bool no_image = false;
  bool no_reflection = false;
  bool hollow = false;
  bool inverse = false;
  bool double_illuminate = false;
  /// `photons {}` in the object (scene/photon_settings.hpp).
  ObjectPhotons photons;
};

struct Object;
class Csg;

/// A ray-surface hit in world space, ready for shading.
struct SurfaceHit {
  double t = 0;
  Vec3 point;
  /// Unit geometric normal, outward from the solid (not yet flipped toward the ray).
  Vec3 normal;
  /// Unit shading normal (smooth triangles); equals `normal` when the shape has none.
  Vec3 shading_normal;
  math::Vec2 uv;
  /// Where textures are evaluated: `point` moved back to the object's still pose (equal to `point` for an
  /// object without motion), so a moving object carries its texture along.
  Vec3 texture_point;
  const Object* object = nullptr;
  /// The scene-level object whose solid this surface bounds: `object` itself, or the CSG object that
  /// contains it. Interiors are entered and left per solid (a ray may enter a glass merge through one
  /// child and leave through another).
  const Object* solid = nullptr;
  int part = -1;
};

struct Object {
  /// Null for a CSG object (then `csg` is set).
  std::shared_ptr<const geometry::Shape> shape;
  /// Set for intersection, difference, merge, clipped objects and unions inside CSG (scene/csg.hpp). Its
  /// children are already in world space, so `transform` stays the identity; hits name the child hit.
  std::shared_ptr<const Csg> csg;
  /// Object space -> world space.
  math::Transform transform;
  /// Never null once the scene is built (the default texture stands in).
  std::shared_ptr<const material::Texture> texture;
  /// Null means the default interior (ior 1).
  std::shared_ptr<const material::Interior> interior;
  ObjectFlags flags;
  /// World box of the object's `bounded_by` objects, if it has any: accelerators test the object only for
  /// rays that hit this box.
  std::optional<math::Bounds3> bounded_by;
  /// Motion blur: where the geometry (and `bounded_by` box) is at a ray's time; null for a still object.
  std::shared_ptr<const Motion> motion;
  /// The `#declare` name the object came from, if any; and where it was written.
  std::string name;
  SourceLocation where;

  /// Nearest hit with t in (t_min, t_max) of a world ray. `outer_inverse`: the object lies inside an odd
  /// number of inverted CSG objects, which POV-Ray pushes down to every child (csg.cpp, CSG::Invert): an
  /// inverted union becomes the intersection of its inverted children and loses its inner surfaces.
  bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit,
                 bool outer_inverse = false) const;
  /// Whether intersect would find a hit: an occlusion test, which for a plain shape builds no world-space
  /// hit (its normals, uv and texture point are a large part of a shadow ray's cost).
  bool blocks(const Ray& ray, double t_min, double t_max) const;
  /// Every hit with t in (t_min, t_max), appended in increasing t (for CSG).
  void all_hits(const Ray& ray, double t_min, double t_max, std::vector<SurfaceHit>& hits,
                bool outer_inverse = false) const;
  /// World-space bounds (infinite for unbounded shapes, or when a transform makes them so); for a moving
  /// object, over all times.
  math::Bounds3 world_bounds() const;
  /// Whether the point is inside the solid at `time` (the time matters only for moving objects).
  bool inside(const Vec3& world_point, double time = 0) const;
  /// Bounds of the points `inside` accepts (infinite for inverted objects), for CSG bounds.
  math::Bounds3 solid_bounds() const;
  /// Bounds of the inside's part within `box` (world space): tighter than solid_bounds() for unbounded
  /// shapes that the box confines (a quadric between planes), for CSG intersection bounds.
  math::Bounds3 solid_bounds_within(const math::Bounds3& box) const;
  bool visible_to(RayKind kind) const {
    switch (kind) {
      case RayKind::camera:
        return !flags.no_image;
      case RayKind::reflection:
        return !flags.no_reflection;
      case RayKind::refraction:
        return !flags.no_image;
      case RayKind::shadow:
        return !flags.no_shadow;
    }
    return true;
  }
  /// intersect and all_hits for the object's still geometry (no motion applied).
  bool intersect_still(const Ray& ray, double t_min, double t_max, SurfaceHit& hit,
                       bool outer_inverse = false) const;
  void all_hits_still(const Ray& ray, double t_min, double t_max, std::vector<SurfaceHit>& hits,
                      bool outer_inverse = false) const;
  /// Moves a simple placement (translate, scale) into the shape itself when the shape can take it
  /// (Shape::placed), so that no ray has to be moved into the object's space; moving objects keep it.
  void bake_placement();
  /// Builds the world-space hit from a shape-space hit of `world_ray` (transformed into object space).
  SurfaceHit to_world(const Ray& world_ray, const geometry::LocalHit& local) const {
    return placed_hit(*this, transform, flags.inverse, world_ray, local);
  }
  /// to_world of `object` given its transform and inverse flag (for callers that keep copies of them
  /// beside the object, and so need not read it: an accelerator's nearest triangle).
  static SurfaceHit placed_hit(const Object& object, const math::Transform& transform, bool inverse,
                               const Ray& world_ray, const geometry::LocalHit& local);
};

}  // namespace snell::scene
