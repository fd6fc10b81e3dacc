#include "snell/geometry/cylinder.hpp"

#include <cmath>
#include <stdexcept>

#include "snell/geometry/axial_caps.hpp"
#include "snell/geometry/polynomial.hpp"
#include "snell/geometry/surface_uv.hpp"

namespace snell::geometry {

Cylinder::Cylinder(const Vec3& base, const Vec3& cap, double radius, bool open)
    : base_(base), radius_(radius), open_(open) {
  const Vec3 axis = cap - base;
  length_ = length(axis);
  if (!is_finite(axis) || !std::isfinite(radius))
    throw std::invalid_argument("cylinder: end points and radius must be finite");
  if (length_ == 0) throw std::invalid_argument("cylinder: degenerate, base point equals cap point");
  if (radius <= 0) throw std::invalid_argument("cylinder: radius must be positive");
  w_ = axis / length_;
  orthonormal_basis(w_, u_, v_);
}

std::shared_ptr<const Shape> Cylinder::placed(const math::Transform& t) const {
  const auto s = t.uniform_scale();
  if (!s) return nullptr;
  return std::make_shared<Cylinder>(t.point(base_), t.point(base_ + length_ * w_), radius_ * *s, open_);
}

Bounds3 Cylinder::bounds() const {
  // Each end disc spans radius * sqrt(1 - w_i^2) along axis i.
  const Vec3 e{radius_ * std::sqrt(std::max(0.0, 1 - w_.x * w_.x)),
               radius_ * std::sqrt(std::max(0.0, 1 - w_.y * w_.y)),
               radius_ * std::sqrt(std::max(0.0, 1 - w_.z * w_.z))};
  const Vec3 cap = base_ + length_ * w_;
  Bounds3 b(base_ - e, base_ + e);
  b.unite(Bounds3(cap - e, cap + e));
  return b;
}

template <typename Buffer>
void Cylinder::gather(const Ray& ray, Buffer& hits) const {
  const Vec3 rel = ray.origin - base_;
  const Vec3 o{dot(rel, u_), dot(rel, v_), dot(rel, w_)};
  const Vec3 d{dot(ray.direction, u_), dot(ray.direction, v_), dot(ray.direction, w_)};
  const double r2 = radius_ * radius_;

  double t0, t1;
  const double a = d.x * d.x + d.y * d.y;
  if (a > 0) {
    // A ray that misses the infinite cylinder misses the caps too (they lie inside it): most rays tested
    // against a thin cylinder stop here.
    if (!solve_quadratic(a, 2 * (o.x * d.x + o.y * d.y), o.x * o.x + o.y * o.y - r2, t0, t1)) return;
    for (double t : {t0, t1}) {
      if (!hits.accepts(t)) continue;
      const Vec3 p = o + t * d;
      if (p.z < 0 || p.z > length_) continue;
      LocalHit h;
      h.t = t;
      h.normal = (p.x * u_ + p.y * v_) / radius_;
      if (surface_uv_requested()) h.uv = {0.5 + std::atan2(p.y, p.x) * 0.5 * math::kInvPi, p.z / length_};
      h.part = 0;
      hits.add(h);
      if (t0 == t1) break;
    }
  }
  if (!open_) add_end_caps(o, d, length_, radius_, radius_, w_, hits);
}

bool Cylinder::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  NearestBuffer hits(t_min, t_max);
  gather(ray, hits);
  return hits.nearest(hit);
}

bool Cylinder::crosses(const Ray& ray, double t_min, double t_max) const {
  AnyBuffer hits(t_min, t_max);
  gather(ray, hits);
  return hits.found();
}

void Cylinder::all_hits(const Ray& ray, double t_min, double t_max, HitList& out) const {
  HitBuffer<4> hits(t_min, t_max);
  gather(ray, hits);
  hits.append_sorted(out);
}

// POV-Ray (cone.cpp, Cone::Inside) answers for the solid volume whether or not the cylinder is open.
bool Cylinder::inside(const Vec3& p) const {
  const Vec3 rel = p - base_;
  const double z = dot(rel, w_);
  if (z < 0 || z > length_) return false;
  const double x = dot(rel, u_), y = dot(rel, v_);
  return x * x + y * y < radius_ * radius_;
}

}  // namespace snell::geometry
