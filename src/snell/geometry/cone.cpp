#include "snell/geometry/cone.hpp"

#include <cmath>
#include <stdexcept>

#include "snell/geometry/axial_caps.hpp"
#include "snell/geometry/polynomial.hpp"
#include "snell/geometry/surface_uv.hpp"

namespace snell::geometry {

Cone::Cone(const Vec3& base, double base_radius, const Vec3& cap, double cap_radius, bool open)
    : base_(base), base_radius_(base_radius), cap_radius_(cap_radius), open_(open) {
  const Vec3 axis = cap - base;
  length_ = length(axis);
  if (!is_finite(axis) || !std::isfinite(base_radius) || !std::isfinite(cap_radius))
    throw std::invalid_argument("cone: end points and radii must be finite");
  if (length_ == 0) throw std::invalid_argument("cone: degenerate, base point equals cap point");
  if (base_radius < 0 || cap_radius < 0) throw std::invalid_argument("cone: radii must not be negative");
  if (base_radius == 0 && cap_radius == 0) throw std::invalid_argument("cone: both radii are zero");
  w_ = axis / length_;
  orthonormal_basis(w_, u_, v_);
  slope_ = (cap_radius - base_radius) / length_;
}

std::shared_ptr<const Shape> Cone::placed(const math::Transform& t) const {
  const auto s = t.uniform_scale();
  if (!s) return nullptr;
  return std::make_shared<Cone>(t.point(base_), base_radius_ * *s, t.point(base_ + length_ * w_),
                                cap_radius_ * *s, open_);
}

Bounds3 Cone::bounds() const {
  const Vec3 s{std::sqrt(std::max(0.0, 1 - w_.x * w_.x)), std::sqrt(std::max(0.0, 1 - w_.y * w_.y)),
               std::sqrt(std::max(0.0, 1 - w_.z * w_.z))};
  const Vec3 cap = base_ + length_ * w_;
  Bounds3 b(base_ - base_radius_ * s, base_ + base_radius_ * s);
  b.unite(Bounds3(cap - cap_radius_ * s, cap + cap_radius_ * s));
  return b;
}

template <typename Buffer>
void Cone::gather(const Ray& ray, Buffer& hits) const {
  const Vec3 rel = ray.origin - base_;
  const Vec3 o{dot(rel, u_), dot(rel, v_), dot(rel, w_)};
  const Vec3 d{dot(ray.direction, u_), dot(ray.direction, v_), dot(ray.direction, w_)};

  // x^2 + y^2 = r(z)^2 with r(z(t)) = ra + rb t along the ray.
  const double ra = radius_at(o.z), rb = slope_ * d.z;
  const double a = d.x * d.x + d.y * d.y - rb * rb;
  const double b = 2 * (o.x * d.x + o.y * d.y - ra * rb);
  const double c = o.x * o.x + o.y * o.y - ra * ra;
  double t0, t1;
  if ((a != 0 || b != 0) && solve_quadratic(a, b, c, t0, t1)) {
    for (double t : {t0, t1}) {
      if (!hits.accepts(t)) continue;
      const Vec3 p = o + t * d;
      if (p.z < 0 || p.z > length_) continue;  // also rejects the mirrored nappe beyond the apex
      const double r = radius_at(p.z);
      LocalHit h;
      h.t = t;
      // Gradient of x^2 + y^2 - r(z)^2, halved; at a pointed apex it vanishes, so use the axis.
      Vec3 n = p.x * u_ + p.y * v_ - (r * slope_) * w_;
      if (length_squared(n) == 0) n = slope_ < 0 ? w_ : -w_;
      h.normal = normalize(n);
      if (surface_uv_requested()) h.uv = {0.5 + std::atan2(p.y, p.x) * 0.5 * math::kInvPi, p.z / length_};
      h.part = 0;
      hits.add(h);
      if (t0 == t1) break;
    }
  }
  if (!open_) add_end_caps(o, d, length_, base_radius_, cap_radius_, w_, hits);
}

bool Cone::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  NearestBuffer hits(t_min, t_max);
  gather(ray, hits);
  return hits.nearest(hit);
}

bool Cone::crosses(const Ray& ray, double t_min, double t_max) const {
  AnyBuffer hits(t_min, t_max);
  gather(ray, hits);
  return hits.found();
}

void Cone::all_hits(const Ray& ray, double t_min, double t_max, HitList& out) const {
  HitBuffer<4> hits(t_min, t_max);
  gather(ray, hits);
  hits.append_sorted(out);
}

// POV-Ray (cone.cpp, Cone::Inside) answers for the solid frustum whether or not the cone is open.
bool Cone::inside(const Vec3& p) const {
  const Vec3 rel = p - base_;
  const double z = dot(rel, w_);
  if (z < 0 || z > length_) return false;
  const double x = dot(rel, u_), y = dot(rel, v_), r = radius_at(z);
  return x * x + y * y < r * r;
}

}  // namespace snell::geometry
