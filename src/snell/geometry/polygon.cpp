#include "snell/geometry/polygon.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace snell::geometry {
namespace {

// Newell's method: the summed cross products of consecutive points give the plane's normal, robust to
// collinear triples and to the sub-polygons' orientations cancelling only partially.
Vec3 newell_normal(std::span<const Vec3> p) {
  Vec3 n;
  for (size_t i = 0; i < p.size(); ++i) n += cross(p[i], p[(i + 1) % p.size()]);
  return n;
}

Vec3 any_perpendicular(const Vec3& n) {
  return std::fabs(n.x) < 0.9 ? normalize(cross(n, Vec3(1, 0, 0))) : normalize(cross(n, Vec3(0, 1, 0)));
}

std::vector<CurveSegment> planar_pieces(std::span<const Vec3> points, const Vec3& origin, const Vec3& u,
                                        const Vec3& v) {
  std::vector<Vec2> flat;
  for (const Vec3& p : points) flat.push_back({dot(p - origin, u), dot(p - origin, v)});
  // As POV-Ray does, an unclosed last sub-polygon is closed by its first point.
  Vec2 first_of_last;
  if (!outline_closed(SplineKind::linear, flat, first_of_last)) flat.push_back(first_of_last);
  return prism_pieces(SplineKind::linear, flat);
}

}  // namespace

Polygon::Polygon(std::span<const Vec3> points)
    : origin_(points.empty() ? Vec3() : points[0]),
      normal_(newell_normal(points)),
      outline_({line_segment({0, 0}, {1, 0})}) {
  if (points.size() < 3) throw std::invalid_argument("polygon needs at least three points");
  // Distinct points that span a triangle give the plane when the sub-polygons' areas cancel out.
  if (length(normal_) < 1e-12) {
    for (size_t i = 2; i < points.size() && length(normal_) < 1e-12; ++i)
      normal_ = cross(points[1] - points[0], points[i] - points[0]);
  }
  if (length(normal_) < 1e-12) throw std::invalid_argument("polygon points do not span a plane");
  normal_ = normalize(normal_);
  axis_u_ = any_perpendicular(normal_);
  axis_v_ = cross(normal_, axis_u_);
  outline_ = Outline(planar_pieces(points, origin_, axis_u_, axis_v_));
  for (const Vec3& p : points) bounds_.unite(p);
}

bool Polygon::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  const double den = dot(normal_, ray.direction);
  if (den == 0) return false;
  const double t = dot(normal_, origin_ - ray.origin) / den;
  if (!(t > t_min && t < t_max)) return false;
  const Vec3 q = ray.at(t) - origin_;
  const Vec2 uv{dot(q, axis_u_), dot(q, axis_v_)};
  if (!outline_.contains(uv)) return false;
  hit = LocalHit{};
  hit.t = t;
  hit.normal = normal_;
  hit.uv = uv;
  return true;
}

void Polygon::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  LocalHit hit;
  if (intersect(ray, t_min, t_max, hit)) hits.push_back(hit);
}

}  // namespace snell::geometry
