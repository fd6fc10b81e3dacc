#include "snell/geometry/ovus.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "snell/geometry/hit_buffer.hpp"
#include "snell/geometry/polynomial.hpp"

namespace snell::geometry {

Ovus::Ovus(double bottom_radius, double top_radius, double connecting_radius, double distance)
    : bottom_radius_(bottom_radius), top_radius_(top_radius) {
  if (!(bottom_radius > 0) || !(top_radius >= 0) || !std::isfinite(bottom_radius) ||
      !std::isfinite(top_radius))
    throw std::invalid_argument("ovus: both radii must be positive, and the bottom radius strictly so");
  const double b = bottom_radius, t = top_radius;
  const double v = distance > 0 ? distance : b;
  const double big = connecting_radius > 0 ? connecting_radius : 2 * std::max(b, t);
  if (v < b) throw std::invalid_argument("ovus: the distance must be at least the bottom radius");
  if (b + t + v > 2 * big)
    throw std::invalid_argument(
        "ovus: the connecting radius must be at least half the sum of the other three");
  top_center_ = v;
  // The band's profile circle has its centre C = (-h, c) at distance big - b from the bottom centre and
  // big - t from the top centre (it touches both spheres from inside): two circles' intersection.
  const double c = (v * v + (big - b) * (big - b) - (big - t) * (big - t)) / (2 * v);
  const double h2 = (big - b) * (big - b) - c * c;
  if (!(h2 > 0)) {
    // No band: POV-Ray keeps the top sphere alone, centred where the band's circle was.
    top_center_ = c;
    top_radius_ = big;
    bottom_radius_ = 0;
    band_ = {0, c, 0, -big + c, -big + c};
    return;
  }
  const double h = std::sqrt(h2);
  // The seams are the tangent points, on the lines from C through each sphere's centre.
  band_ = {-h, c, big, -c * b / (big - b), v + (v - c) * t / (big - t)};
}

Bounds3 Ovus::bounds() const {
  const double r =
      std::max({bottom_radius_, top_radius_, band_.radius > 0 ? band_.radius + band_.center_rho : 0});
  return {Vec3(-r, std::min(-bottom_radius_, top_center_ - top_radius_), -r),
          Vec3(r, top_center_ + top_radius_, r)};
}

template <typename Sink>
void Ovus::trace(const Ray& ray, double t_min, double t_max, Sink&& sink) const {
  // Each sphere contributes only the cap beyond its seam; the band fills the rest.
  const auto cap = [&](const Vec3& center, double radius, bool below, double seam) {
    if (!(radius > 0)) return;
    const Vec3 oc = ray.origin - center;
    double t0 = 0, t1 = 0;
    if (!solve_quadratic(length_squared(ray.direction), 2 * dot(oc, ray.direction),
                         length_squared(oc) - radius * radius, t0, t1))
      return;
    for (const double t : {t0, t1}) {
      if (!(t > t_min && t < t_max)) continue;
      const Vec3 p = ray.at(t);
      if (below ? p.y < seam : p.y > seam) sink(t, (p - center) / radius);
    }
  };
  cap(Vec3(0), bottom_radius_, true, band_.y_lo);
  cap(Vec3(0, top_center_, 0), top_radius_, false, band_.y_hi);
  if (band_.radius > 0) {
    double ts[4];
    Vec3 normals[4];
    const int n = band_.crossings(ray, t_min, t_max, ts, normals);
    for (int i = 0; i < n; ++i) sink(ts[i], normals[i]);
  }
}

bool Ovus::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  HitBuffer<8> hits(t_min, t_max);
  trace(ray, t_min, t_max, [&](double t, const Vec3& n) { hits.add({t, n, {}, {}, -1}); });
  return hits.nearest(hit);
}

void Ovus::all_hits(const Ray& ray, double t_min, double t_max, HitList& out) const {
  HitBuffer<8> hits(t_min, t_max);
  trace(ray, t_min, t_max, [&](double t, const Vec3& n) { hits.add({t, n, {}, {}, -1}); });
  hits.append_sorted(out);
}

bool Ovus::inside(const Vec3& p) const {
  return length_squared(p) < bottom_radius_ * bottom_radius_ ||
         length_squared(p - Vec3(0, top_center_, 0)) < top_radius_ * top_radius_ || band_.encloses(p);
}

}  // namespace snell::geometry
