#pragma once
// The own accelerators' per-query search for the nearest hit. Plain triangles (a `triangle` object with no
// CSG, motion or `bounded_by`: most objects of a triangle-heavy scene) are tested by their double-precision
// crossing alone, exactly the one Object::intersect would find; only the final hit builds its SurfaceHit
// (normals, uv, texture point). Every other object goes through test_object.
#include <array>
#include <vector>

#include "snell/accel/indexed_objects.hpp"
#include "snell/geometry/triangle.hpp"

namespace snell::accel {

/// A plain triangle's shape and placement (transform null for the identity), or shape null for any other
/// object. The vertices are the shape's own, copied so that a walk testing many triangles reads them from
/// one array instead of chasing each shape (a cache miss apiece).
struct PlainTriangle {
  const scene::Object* object = nullptr;
  const geometry::Triangle* shape = nullptr;
  const math::Transform* transform = nullptr;
  std::array<math::Vec3, 3> vertices{};
  /// Whether the shape has vertex normals (only then does the final hit read the shape), and the
  /// object's `inverse` flag: copies, so that building the final hit reads neither the shape nor the object
  /// (each a cache miss in a large scene).
  bool smooth = false;
  bool inverse = false;
};

PlainTriangle plain_triangle(const scene::Object& object);
/// plain_triangle of each object.
std::vector<PlainTriangle> plain_triangles(const std::vector<const scene::Object*>& objects);

class NearestHit {
 public:
  NearestHit(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind, scene::SurfaceHit& hit)
      : ray_(ray), t_min_(t_min), t_max_(t_max), kind_(kind), hit_(hit) {}

  double t_min() const { return t_min_; }
  double t_max() const { return t_max_; }
  const math::Ray& ray() const { return ray_; }
  scene::RayKind kind() const { return kind_; }

  /// Tests an object (`triangle`: its plain_triangle record); true when it is the nearest hit so far.
  bool test(const scene::Object& object, const PlainTriangle& triangle) {
    if (triangle.shape == nullptr) return test_general(object);
    if (!object.visible_to(kind_)) return false;
    count_object_test(object);
    ObjectTestCounter::count();
    return test_triangle(triangle);
  }
  /// Tests an object that is no plain triangle.
  bool test_general(const scene::Object& object) {
    if (!test_object(object, ray_, t_min_, t_max_, kind_, hit_)) return false;
    t_max_ = hit_.t;
    triangle_ = nullptr;
    found_ = true;
    return true;
  }
  /// For an occlusion query: whether an object that is no plain triangle stops the ray (object_blocks: no
  /// hit built); object() then names it. finish() is not for such queries.
  bool test_blocking(const scene::Object& object) {
    if (!object_blocks(object, ray_, t_min_, t_max_, kind_)) return false;
    triangle_ = &object;
    found_ = true;
    return true;
  }
  /// For an occlusion query: a plain triangle the ray surely crosses within the window (the filter's clear
  /// hit) stops it; object() then names it.
  void blocked_by(const scene::Object& object) {
    triangle_ = &object;
    found_ = true;
  }
  /// Tests a plain triangle visible to the ray's kind, counted already.
  bool test_triangle(const PlainTriangle& triangle) {
    geometry::TriangleHit crossing;
    // Triangle::crossing's test on the same vertices: the same answer, bit for bit.
    const std::array<math::Vec3, 3>& v = triangle.vertices;
    const bool hit =
        triangle.transform
            ? geometry::intersect_triangle(v[0], v[1], v[2], triangle.transform->inverse_ray(ray_), t_min_,
                                           t_max_, crossing)
            : geometry::intersect_triangle(v[0], v[1], v[2], ray_, t_min_, t_max_, crossing);
    if (!hit) return false;
    t_max_ = crossing.t;
    triangle_ = triangle.object;
    plain_ = &triangle;
    crossing_ = crossing;
    found_ = true;
    return true;
  }

  /// The object of the nearest hit so far, or null.
  const scene::Object* object() const { return !found_ ? nullptr : triangle_ ? triangle_ : hit_.object; }

  /// Whether anything was hit; a triangle found last gets its SurfaceHit built now, from the crossing
  /// already found: what Object::intersect would build for a plain triangle (Object::intersect_still: the
  /// shape's hit of the ray moved into object space, which is the ray test_triangle tested, taken to world
  /// space), without testing the triangle again (that test and its object's dispatch were a fifth of a
  /// random ray's time through 100k triangles, docs/benchmark.md).
  bool finish() {
    if (triangle_) {
      static const math::Transform identity;
      hit_ = scene::Object::placed_hit(
          *triangle_, plain_->transform ? *plain_->transform : identity, plain_->inverse, ray_,
          plain_->smooth ? plain_->shape->local_hit(crossing_)
                         : geometry::Triangle::flat_hit(plain_->vertices, crossing_));
    }
    return found_;
  }

 private:
  const math::Ray& ray_;
  double t_min_;
  double t_max_;
  scene::RayKind kind_;
  scene::SurfaceHit& hit_;
  const scene::Object* triangle_ = nullptr;
  /// The record and crossing of the plain triangle triangle_ (valid while triangle_ is one; the record
  /// lives in the accelerator, which outlives the query).
  const PlainTriangle* plain_ = nullptr;
  geometry::TriangleHit crossing_{};
  bool found_ = false;
};

}  // namespace snell::accel
