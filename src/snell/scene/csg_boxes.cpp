// CSG intersections and differences of boxes alone (a frame cut from a block, csg_granite.pov's holes):
// the general path tests each child's bounds, builds every crossing of every child with its face and uv,
// and moves each candidate point into every other child's space for its inside test. Here each ray is moved
// into each box's space once; a candidate's inside tests compare its point there with the box, and only the
// kept crossing is built. Same hits as the general path: where a point lies so near a face of another
// box that rounding could tell the two tests apart, the general test (child_inside) decides.
#include <algorithm>
#include <cmath>

#include "snell/geometry/box.hpp"
#include "snell/scene/csg.hpp"
#include "snell/scene/object.hpp"

namespace snell::scene {

namespace {

/// A bound on how far the inverse transform moves magnitudes: its largest row sum plus its translation.
double inverse_scale(const math::Transform& t) {
  const math::Vec3 cx = t.inverse_vector({1, 0, 0}), cy = t.inverse_vector({0, 1, 0}),
                   cz = t.inverse_vector({0, 0, 1});
  const math::Vec3 rows{std::fabs(cx.x) + std::fabs(cy.x) + std::fabs(cz.x),
                        std::fabs(cx.y) + std::fabs(cy.y) + std::fabs(cz.y),
                        std::fabs(cx.z) + std::fabs(cy.z) + std::fabs(cz.z)};
  return max_component(abs(rows)) + max_component(abs(t.inverse_point({0, 0, 0})));
}

}  // namespace

void Csg::find_box_children() {
  if (kind_ != CsgKind::intersection || children_.size() > kMaxBoxChildren) return;
  std::vector<BoxChild> found;
  for (const auto& c : children_) {
    const auto* box = c->csg || c->motion ? nullptr : dynamic_cast<const geometry::Box*>(c->shape.get());
    if (!box) return;
    found.push_back({box, inverse_scale(c->transform),
                     std::max(max_component(abs(box->lo())), max_component(abs(box->hi())))});
  }
  box_children_ = std::move(found);
}

bool Csg::boxes_keep(size_t i, double t, const math::Ray& ray, const math::Ray* local) const {
  const math::Vec3 p = ray.at(t);
  const double reach = 1 + max_component(abs(p));
  for (size_t j = 0; j < box_children_.size(); ++j) {
    if (j == i) continue;
    const geometry::Box& box = *box_children_[j].box;
    const math::Vec3 q = local[j].at(t);
    // Rounding in either route to the box's space is below 1e-15 of these magnitudes: a point farther
    // than a millionth of that from every face is where child_inside would find it.
    const double margin =
        1e-9 * (1 + max_component(abs(q)) + 2 * box_children_[j].size + box_children_[j].scale * reach);
    bool within = true, clear = true;
    for (int a = 0; a < 3; ++a) {
      const double below = q[a] - box.lo()[a], above = box.hi()[a] - q[a];
      if (below < -margin || above < -margin) {
        within = false;
        break;
      }
      if (below <= margin || above <= margin) clear = false;
    }
    if (within && !clear) {
      if (!child_inside(j, p, ray.time)) return false;
      continue;
    }
    if (within == children_[j]->flags.inverse) return false;
  }
  return true;
}

bool Csg::intersect_boxes(const math::Ray& ray, double t_min, double t_max, SurfaceHit* hit) const {
  // Left uninitialised (clearing the array cost a sixth of this function): only the first n are read.
  union LocalRays {
    LocalRays() {}
    math::Ray at[kMaxBoxChildren];
  } rays;
  math::Ray* local = rays.at;
  for (size_t j = 0; j < box_children_.size(); ++j) local[j] = children_[j]->transform.inverse_ray(ray);
  bool found = false;
  for (size_t i = 0; i < surface_children_; ++i) {
    double t0, t1;
    int axis0, axis1;
    const geometry::Box& box = *box_children_[i].box;
    if (!box.slabs(local[i], t0, t1, axis0, axis1)) continue;
    // Box::all_hits's crossings in its order: the entry, then the exit where it differs.
    for (int k = 0; k < 2; ++k) {
      if (k == 1 && t1 == t0) break;
      const double t = k == 0 ? t0 : t1;
      if (!(t > t_min && t < t_max) || !boxes_keep(i, t, ray, local)) continue;
      if (!hit) return true;
      *hit = children_[i]->to_world(ray, box.slab_hit(local[i], t, k == 0 ? axis0 : axis1, k == 1));
      t_max = t;
      found = true;
      break;
    }
  }
  return found;
}

}  // namespace snell::scene
