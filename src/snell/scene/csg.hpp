#pragma once
// Constructive solid geometry over whole Objects (POV-Ray 3.7 reference, "Constructive Solid Geometry"):
// each child keeps its own transform, texture and interior, so a hit reports the child that was hit.
// As in POV-Ray's csg.cpp, a CSG hit is a hit of one child kept or dropped by inside tests of the others;
// `difference { A B C }` is `intersection { A, inverse B, inverse C }` (the parser inverts B and C), and
// `clipped_by` is an intersection whose clipping children contribute inside tests but no surface.
#include <memory>
#include <vector>

#include "snell/math/bounds.hpp"
#include "snell/math/ray.hpp"

namespace snell::geometry {
class Box;
}

namespace snell::scene {

struct Object;
struct SurfaceHit;

enum class CsgKind {
  /// Every child surface (a union nested in CSG, or declared with inverse).
  union_of,
  /// Child surfaces that no other child contains: no internal surfaces.
  merge,
  /// Child surfaces that every other child contains.
  intersection,
};

class Csg {
 public:
  /// Children are placed in world space (their transforms include the CSG's). Only the first
  /// `surface_children` children can be hit; the rest only clip (all of them when it is 0).
  Csg(CsgKind kind, std::vector<std::shared_ptr<const Object>> children, size_t surface_children = 0);

  /// Nearest kept hit in (t_min, t_max); `hit.object` is the leaf Object hit. `inverted`: the object is
  /// inverted (an odd number of `inverse` on it and the CSG objects around it), so that, as in POV-Ray
  /// (csg.cpp, CSGUnion::Invert), a union keeps only the surfaces that lie in no other child.
  bool intersect(const math::Ray& ray, double t_min, double t_max, SurfaceHit& hit,
                 bool inverted = false) const;
  /// Whether intersect would find a hit (shadow rays): stops at the first kept crossing of any child and
  /// builds no world-space hit for a plain child.
  bool crosses(const math::Ray& ray, double t_min, double t_max, bool inverted = false) const;
  /// Every kept hit in (t_min, t_max), appended in increasing t.
  void all_hits(const math::Ray& ray, double t_min, double t_max, std::vector<SurfaceHit>& hits,
                bool inverted = false) const;
  bool inside(const math::Vec3& world_point, double time = 0) const;
  /// World bounds: union of the children for union and merge, their overlap for an intersection (so a
  /// difference, whose later children are inverted and unbounded, gets the first child's bounds).
  const math::Bounds3& bounds() const { return bounds_; }
  /// Bounds of the points `inside` accepts.
  const math::Bounds3& solid_bounds() const { return solid_bounds_; }

  CsgKind kind() const { return kind_; }
  const std::vector<std::shared_ptr<const Object>>& children() const { return children_; }

 private:
  /// Whether a hit on child `i` at `p` is a surface of the combined solid, combined as `kind`.
  bool keeps(CsgKind kind, size_t i, const math::Vec3& p, double time) const;
  /// How the surfaces combine: an inverted union's are a merge's (the intersection of its complements).
  CsgKind surface_kind(bool inverted) const {
    return inverted && kind_ == CsgKind::union_of ? CsgKind::merge : kind_;
  }

  /// Narrows (t_min, t_max) to the padded bounds of the combined object; false when the ray misses them.
  bool clip_to_bounds(const math::Ray& ray, double& t_min, double& t_max) const;
  /// Whether the ray over (t_min, t_max) can meet surface child `i` (its padded world bounds).
  bool may_hit_child(size_t i, const math::Ray& ray, double t_min, double t_max) const;

  CsgKind kind_;
  std::vector<std::shared_ptr<const Object>> children_;
  size_t surface_children_;
  math::Bounds3 bounds_;
  math::Bounds3 solid_bounds_;
  /// Slightly grown copies of bounds_ and of the surface children's world bounds, computed once: rays
  /// are clipped to them before any child is intersected (POV-Ray's csg.cpp tests each child's bounding
  /// box the same way), so that unbounded children (planes) are only solved where the object can be.
  math::Bounds3 clip_bounds_;
  std::vector<math::Bounds3> child_clip_bounds_;
  /// Per child, a padded box outside which its inside() is just its `inverse` flag (plain shapes that
  /// say inside_within_bounds, and CSG children all of whose leaves do: their solid bounds); infinite
  /// for the others. keeps() asks it before the child's own test:
  /// most points of a difference lie far from most of what is cut away.
  std::vector<math::Bounds3> inside_boxes_;
  /// children_[j]->inside(p, time), answered by inside_boxes_[j] where it can.
  bool child_inside(size_t j, const math::Vec3& p, double time) const;

  /// An intersection (or difference) of still boxes alone (csg_boxes.cpp): its children's slabs, each
  /// ray moved into each box's space once, decide the inside tests; empty for any other CSG.
  struct BoxChild {
    const geometry::Box* box;
    double scale;  // of the child's inverse transform (largest row sum, plus its translation)
    double size;   // the largest coordinate of its corners, in its own space
  };
  std::vector<BoxChild> box_children_;
  static constexpr size_t kMaxBoxChildren = 8;
  void find_box_children();
  /// intersect and crosses over the window already clipped to the bounds, for box_children_.
  bool intersect_boxes(const math::Ray& ray, double t_min, double t_max, SurfaceHit* hit) const;
  /// Whether the hit at t of box child i lies in all the others, as keeps(intersection, ...) says.
  bool boxes_keep(size_t i, double t, const math::Ray& ray, const math::Ray* local) const;
};

}  // namespace snell::scene
