#include "snell/geometry/box.hpp"

#include <cmath>
#include <stdexcept>

namespace snell::geometry {

Box::Box(const Vec3& corner1, const Vec3& corner2) : lo_(min(corner1, corner2)), hi_(max(corner1, corner2)) {
  if (!is_finite(lo_) || !is_finite(hi_)) throw std::invalid_argument("box: corners must be finite");
}

std::shared_ptr<const Shape> Box::placed(const math::Transform& t) const {
  if (!t.axis_scale()) return nullptr;
  return std::make_shared<Box>(t.point(lo_), t.point(hi_));
}

Bounds3 Box::bounds() const {
  return {lo_, hi_};
}

bool Box::slabs(const Ray& ray, double& t0, double& t1, int& axis0, int& axis1) const {
  // Slab method (Kay & Kajiya 1986), remembering which slab gave the entry and the exit.
  t0 = -math::kInfinity, t1 = math::kInfinity;
  axis0 = -1, axis1 = -1;
  for (int a = 0; a < 3; ++a) {
    const double d = ray.direction[a];
    if (d == 0) {
      if (ray.origin[a] < lo_[a] || ray.origin[a] > hi_[a]) return false;
      continue;
    }
    double tn = (lo_[a] - ray.origin[a]) / d;
    double tf = (hi_[a] - ray.origin[a]) / d;
    if (tn > tf) std::swap(tn, tf);
    if (tn > t0) {
      t0 = tn;
      axis0 = a;
    }
    if (tf < t1) {
      t1 = tf;
      axis1 = a;
    }
  }
  return !(t0 > t1 || axis0 < 0);
}

bool Box::span(const Ray& ray, double& t_entry, double& t_exit) const {
  int axis0, axis1;
  // As two intersect calls would find them: the second crossing must lie strictly beyond the first.
  return slabs(ray, t_entry, t_exit, axis0, axis1) && t_exit > t_entry;
}

LocalHit Box::face_hit(const Ray& ray, double t, int axis, double sign) const {
  LocalHit h;
  h.t = t;
  h.normal[axis] = sign;
  const Vec3 p = ray.at(t);
  const Vec3 e = hi_ - lo_;
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  h.uv = {e[a] > 0 ? (p[a] - lo_[a]) / e[a] : 0, e[b] > 0 ? (p[b] - lo_[b]) / e[b] : 0};
  h.part = axis;
  return h;
}

LocalHit Box::slab_hit(const Ray& ray, double t, int axis, bool leaving) const {
  // Entering through a face whose outward normal opposes the direction, leaving through one along it.
  return face_hit(ray, t, axis, (ray.direction[axis] > 0) == leaving ? 1.0 : -1.0);
}

template <typename Buffer>
void Box::gather(const Ray& ray, Buffer& hits) const {
  double t0, t1;
  int axis0, axis1;
  if (!slabs(ray, t0, t1, axis0, axis1)) return;
  if (hits.accepts(t0)) hits.add(slab_hit(ray, t0, axis0, false));
  if (hits.accepts(t1) && t1 != t0) hits.add(slab_hit(ray, t1, axis1, true));
}

bool Box::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  // The entry precedes the exit: once it is kept the window closes and the exit is never built.
  NearestBuffer hits(t_min, t_max);
  gather(ray, hits);
  return hits.nearest(hit);
}

bool Box::crosses(const Ray& ray, double t_min, double t_max) const {
  double t0, t1;
  int axis0, axis1;
  if (!slabs(ray, t0, t1, axis0, axis1)) return false;
  return (t0 > t_min && t0 < t_max) || (t1 > t_min && t1 < t_max && t1 != t0);
}

void Box::all_hits(const Ray& ray, double t_min, double t_max, HitList& out) const {
  HitBuffer<2> hits(t_min, t_max);
  gather(ray, hits);
  hits.append_sorted(out);
}

// POV-Ray's Box::Inside counts the faces as inside.
bool Box::inside(const Vec3& p) const {
  return bounds().contains(p);
}

}  // namespace snell::geometry
