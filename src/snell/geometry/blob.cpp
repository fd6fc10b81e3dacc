#include "snell/geometry/blob.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "snell/geometry/polynomial.hpp"

namespace snell::geometry {
namespace {

struct ComponentPoint {
  Vec3 offset;  // from the nearest point of the component's skeleton (centre or segment) to p
  double q;     // |offset|^2 / R^2
};

// Nearest skeleton point in component space: the centre, or the segment end1-end2 (hemispherical ends,
// POV-Ray documentation "Blob": cylindrical components).
ComponentPoint skeleton_offset(const BlobComponent& c, const Vec3& p) {
  Vec3 nearest = c.center;
  if (c.kind == BlobComponent::Kind::cylinder) {
    const Vec3 axis = c.end - c.center;
    const double len2 = length_squared(axis);
    if (len2 > 0) nearest = c.center + std::clamp(dot(p - c.center, axis) / len2, 0.0, 1.0) * axis;
  }
  const Vec3 off = p - nearest;
  return {off, length_squared(off) / (c.radius * c.radius)};
}

}  // namespace

Blob::Blob(double threshold, std::vector<BlobComponent> components)
    : threshold_(threshold), components_(std::move(components)) {
  if (!std::isfinite(threshold) || threshold <= 0)
    throw std::invalid_argument("blob: threshold must be positive");
  if (components_.empty()) throw std::invalid_argument("blob: needs at least one component");
  for (const BlobComponent& c : components_) {
    if (!std::isfinite(c.radius) || c.radius <= 0)
      throw std::invalid_argument("blob: component radius must be positive");
    if (!std::isfinite(c.strength) || !is_finite(c.center) || !is_finite(c.end))
      throw std::invalid_argument("blob: component values must be finite");
  }
  bounds_ = influence_bounds();
}

Bounds3 Blob::bounds() const {
  return bounds_;
}

Bounds3 Blob::influence_bounds() const {
  // The field never exceeds the sum of the positive components, and the threshold is positive, so the
  // surface lies within their spheres of influence.
  Bounds3 b;
  for (const BlobComponent& c : components_) {
    if (c.strength <= 0) continue;
    const Vec3 r(c.radius);
    Bounds3 local(c.center - r, c.center + r);
    if (c.kind == BlobComponent::Kind::cylinder) local.unite(Bounds3(c.end - r, c.end + r));
    b.unite(c.transform.is_identity() ? local : c.transform.bounds(local));
  }
  return b;
}

double Blob::density(const Vec3& p) const {
  double sum = 0;
  for (const BlobComponent& c : components_) {
    const Vec3 pc = c.transform.is_identity() ? p : c.transform.inverse_point(p);
    const double q = skeleton_offset(c, pc).q;
    if (q < 1) sum += c.strength * (1 - q) * (1 - q);
  }
  return sum;
}

bool Blob::inside(const Vec3& p) const {
  return density(p) > threshold_;
}

void Blob::collect_pieces(const BlobComponent& comp, const Ray& ray, std::vector<Piece>& pieces) const {
  const Ray r = comp.transform.is_identity() ? ray : comp.transform.inverse_ray(ray);
  const double inv_r2 = 1 / (comp.radius * comp.radius);
  // q(s) = A s^2 + B s + C on [lo, hi]; the component adds strength (1 - q)^2 where q < 1.
  const auto add = [&](double a, double b, double c, double lo, double hi) {
    a *= inv_r2;
    b *= inv_r2;
    c *= inv_r2;
    double q0 = lo, q1 = hi;
    if (a <= 0) {
      // Ray parallel to a cylinder's axis: constant distance (a < 0 only by rounding).
      a = b = 0;
      if (c >= 1) return;
    } else if (!solve_quadratic(a, b, c - 1, q0, q1)) {
      return;
    }
    lo = std::max(lo, q0);
    hi = std::min(hi, q1);
    if (!(lo < hi)) return;
    const double s = comp.strength;
    pieces.push_back({lo,
                      hi,
                      {s * (1 - 2 * c + c * c), s * (2 * b * c - 2 * b), s * (b * b + 2 * a * c - 2 * a),
                       s * 2 * a * b, s * a * a}});
  };
  const auto sphere_at = [&](const Vec3& centre, double lo, double hi) {
    const Vec3 f = r.origin - centre;
    add(dot(r.direction, r.direction), 2 * dot(f, r.direction), dot(f, f), lo, hi);
  };
  const double inf = math::kInfinity;
  const Vec3 axis = comp.end - comp.center;
  const double len = length(axis);
  if (comp.kind == BlobComponent::Kind::sphere || len == 0) return sphere_at(comp.center, -inf, inf);

  // Cylinder: the distance to the segment is the distance to the axis line where the projection h lies
  // on the segment, and to the nearer end beyond it.
  const Vec3 w = axis / len;
  const Vec3 f = r.origin - comp.center;
  const double h0 = dot(f, w), h1 = dot(r.direction, w);
  double s_at0 = -inf, s_atl = inf;  // where h crosses 0 and len (ordered along the ray below)
  if (h1 != 0) {
    s_at0 = -h0 / h1;
    s_atl = (len - h0) / h1;
  } else if (h0 < 0 || h0 > len) {
    return sphere_at(h0 < 0 ? comp.center : comp.end, -inf, inf);
  }
  const double mid_lo = h1 != 0 ? std::min(s_at0, s_atl) : -inf,
               mid_hi = h1 != 0 ? std::max(s_at0, s_atl) : inf;
  const Vec3& first_end = h1 >= 0 ? comp.center : comp.end;  // the end the ray passes before the middle
  const Vec3& last_end = h1 >= 0 ? comp.end : comp.center;
  add(dot(r.direction, r.direction) - h1 * h1, 2 * (dot(f, r.direction) - h0 * h1), dot(f, f) - h0 * h0,
      mid_lo, mid_hi);
  if (h1 != 0) {
    sphere_at(first_end, -inf, mid_lo);
    sphere_at(last_end, mid_hi, inf);
  }
}

LocalHit Blob::make_hit(const Vec3& p, double t) const {
  // Normal = -grad(field); d/dp of s (1 - q)^2 is -4 s (1 - q) offset / R^2, carried to blob space by the
  // inverse transpose of the component transform.
  Vec3 n;
  for (const BlobComponent& c : components_) {
    const Vec3 pc = c.transform.is_identity() ? p : c.transform.inverse_point(p);
    const ComponentPoint cp = skeleton_offset(c, pc);
    if (cp.q >= 1) continue;
    const Vec3 g = (4 * c.strength * (1 - cp.q) / (c.radius * c.radius)) * cp.offset;
    n += c.transform.is_identity() ? g : c.transform.normal(g);
  }
  LocalHit hit;
  hit.t = t;
  hit.normal = length_squared(n) > 0 ? normalize(n) : Vec3(0, 1, 0);
  return hit;
}

void Blob::find_roots(const Ray& ray, double t_min, double t_max, bool first_only, HitList& out) const {
  const Bounds3& box = bounds_;
  if (box.empty()) return;
  double t0 = t_min, t1 = t_max;
  if (!box.clip(ray, t0, t1)) return;
  const double dl = length(ray.direction);
  if (!(dl > 0) || !std::isfinite(t0) || !std::isfinite(t1)) return;
  // Local parameter s = (t - t0) |d| along a unit direction from the box entry: keeps the quartics'
  // coefficients of the blob's size whatever the distance to the eye.
  const Ray local{ray.at(t0), ray.direction / dl, ray.time};
  const double s_end = (t1 - t0) * dl;
  if (!(s_end > 0)) return;

  // Per-thread scratch, kept between rays: allocating these per ray was a tenth of blob.pov's time.
  thread_local std::vector<Piece> pieces;
  thread_local std::vector<double> cuts;
  pieces.clear();
  for (const BlobComponent& c : components_) collect_pieces(c, local, pieces);
  cuts.assign({0.0, s_end});
  for (const Piece& p : pieces) {
    if (p.s0 > 0 && p.s0 < s_end) cuts.push_back(p.s0);
    if (p.s1 > 0 && p.s1 < s_end) cuts.push_back(p.s1);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double a = cuts[i], b = cuts[i + 1];
    std::array<double, 5> sum{};
    bool any = false;
    for (const Piece& p : pieces) {
      if (p.s0 > a || p.s1 < b) continue;
      for (int k = 0; k < 5; ++k) sum[k] += p.c[k];
      any = true;
    }
    if (!any) continue;
    sum[0] -= threshold_;
    std::array<double, 4> roots{};
    const int n = real_roots(sum, a, b, roots);
    for (int k = 0; k < n; ++k) {
      const double t = t0 + roots[k] / dl;
      if (!(t > t_min && t < t_max)) continue;
      out.push_back(make_hit(local.at(roots[k]), t));
      if (first_only) return;
    }
  }
}

bool Blob::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  thread_local HitList hits;  // scratch, as find_roots' own
  hits.clear();
  find_roots(ray, t_min, t_max, true, hits);
  if (hits.empty()) return false;
  hit = hits.front();
  return true;
}

void Blob::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  find_roots(ray, t_min, t_max, false, hits);
}

}  // namespace snell::geometry
