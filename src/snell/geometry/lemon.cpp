#include "snell/geometry/lemon.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "snell/geometry/hit_buffer.hpp"

namespace snell::geometry {

Lemon::Lemon(const Vec3& base, double base_radius, const Vec3& cap, double cap_radius, double inner_radius,
             bool open)
    : base_(base), open_(open) {
  if (!(base_radius >= 0) || !(cap_radius >= 0) || !(inner_radius >= 0))
    throw std::invalid_argument("lemon: all radii must be positive");
  length_ = length(cap - base);
  if (!(length_ > 1e-12) || !std::isfinite(length_))
    throw std::invalid_argument("lemon: base and cap coincide");
  w_ = (cap - base) / length_;
  u_ = normalize(std::fabs(w_.x) < 0.9 ? cross(w_, Vec3(1, 0, 0)) : cross(w_, Vec3(0, 1, 0)));
  v_ = cross(u_, w_);
  const double a = base_radius / length_, b = cap_radius / length_;
  double r = inner_radius / length_;
  // POV-Ray 3.8's lemon.cpp smallest inner radius, sqrt((a^2 - b^2)^2 + 2 (a^2 + b^2) + 1) / 2 in the
  // unit frame: below it the arc's centre would not lie across the axis.
  const double smallest = std::sqrt((a * a - b * b) * (a * a - b * b) + 2 * (a * a + b * b) + 1) / 2;
  r = std::max(r, smallest);
  // The arc passes through (a, 0) and (b, 1); its centre lies on the chord's perpendicular bisector, on
  // the side away from the rims: midpoint + sqrt(r^2 - chord^2 / 4) * (-1, b - a) / chord.
  const double chord = std::sqrt((b - a) * (b - a) + 1);
  const double offset = std::sqrt(std::max(0.0, r * r - chord * chord / 4)) / chord;
  arc_ = {(a + b) / 2 - offset, 0.5 + offset * (b - a), r, 0, 1};
  base_radius_ = a;
  cap_radius_ = b;
}

Vec3 Lemon::to_unit(const Vec3& p) const {
  const Vec3 d = p - base_;
  return Vec3(dot(d, u_), dot(d, w_), dot(d, v_)) / length_;
}

Vec3 Lemon::from_unit_direction(const Vec3& d) const {
  return u_ * d.x + w_ * d.y + v_ * d.z;
}

Bounds3 Lemon::bounds() const {
  // The widest rim of the unit frame: the arc's bulge when its top lies between the ends, else an end.
  double m = arc_.radius + arc_.center_rho;
  if (arc_.center_y < 0) m = base_radius_;
  if (arc_.center_y > 1) m = cap_radius_;
  m *= length_;
  Bounds3 box;
  for (const Vec3& end : {base_, base_ + w_ * length_})
    for (const double su : {-m, m})
      for (const double sv : {-m, m}) box.unite(end + u_ * su + v_ * sv);
  return box;
}

template <typename Sink>
void Lemon::trace(const Ray& ray, double t_min, double t_max, Sink&& sink) const {
  // The unit frame is a rotation and a uniform scale: t is unchanged.
  const Ray local{to_unit(ray.origin),
                  Vec3(dot(ray.direction, u_), dot(ray.direction, w_), dot(ray.direction, v_)) / length_,
                  ray.time};
  double ts[4];
  Vec3 normals[4];
  const int n = arc_.crossings(local, t_min, t_max, ts, normals);
  for (int i = 0; i < n; ++i) sink(ts[i], from_unit_direction(normals[i]));
  if (open_ || local.direction.y == 0) return;
  for (const double y : {0.0, 1.0}) {
    const double t = (y - local.origin.y) / local.direction.y;
    if (!(t > t_min && t < t_max)) continue;
    const Vec3 p = local.at(t);
    const double rim = y == 0 ? base_radius_ : cap_radius_;
    if (p.x * p.x + p.z * p.z <= rim * rim) sink(t, y == 0 ? -w_ : w_);
  }
}

bool Lemon::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  HitBuffer<6> hits(t_min, t_max);
  trace(ray, t_min, t_max, [&](double t, const Vec3& n) { hits.add({t, n, {}, {}, -1}); });
  return hits.nearest(hit);
}

void Lemon::all_hits(const Ray& ray, double t_min, double t_max, HitList& out) const {
  HitBuffer<6> hits(t_min, t_max);
  trace(ray, t_min, t_max, [&](double t, const Vec3& n) { hits.add({t, n, {}, {}, -1}); });
  hits.append_sorted(out);
}

bool Lemon::inside(const Vec3& p) const {
  return arc_.encloses(to_unit(p));
}

}  // namespace snell::geometry
