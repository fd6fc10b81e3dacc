#include "snell/geometry/sphere_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "snell/geometry/cone.hpp"
#include "snell/geometry/sphere.hpp"

namespace snell::geometry {
namespace {

// Weights of four control points at s in [0, 1]: the uniform cubic B-spline basis, or Catmull-Rom's
// (which passes through the middle two points).
std::array<double, 4> basis(SweepSpline spline, double s) {
  const double s2 = s * s, s3 = s2 * s;
  if (spline == SweepSpline::b_spline)
    return {(1 - s) * (1 - s) * (1 - s) / 6, (3 * s3 - 6 * s2 + 4) / 6, (-3 * s3 + 3 * s2 + 3 * s + 1) / 6,
            s3 / 6};
  return {0.5 * (-s3 + 2 * s2 - s), 0.5 * (3 * s3 - 5 * s2 + 2), 0.5 * (-3 * s3 + 4 * s2 + s),
          0.5 * (s3 - s2)};
}

bool ray_meets_box(const Ray& ray, const Bounds3& b, double t_min, double t_max) {
  for (int axis = 0; axis < 3; ++axis) {
    const double o = ray.origin[axis], d = ray.direction[axis], lo = b.lo[axis], hi = b.hi[axis];
    if (d == 0) {
      if (o < lo || o > hi) return false;
      continue;
    }
    double t0 = (lo - o) / d, t1 = (hi - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    t_min = std::max(t_min, t0);
    t_max = std::min(t_max, t1);
    if (t_min > t_max) return false;
  }
  return true;
}

}  // namespace

std::vector<SweepSphere> sweep_path(SweepSpline spline, std::span<const SweepSphere> p) {
  if (spline == SweepSpline::linear) return {p.begin(), p.end()};
  std::vector<SweepSphere> path;
  for (size_t i = 0; i + 3 < p.size(); ++i) {
    for (int step = i == 0 ? 0 : 1; step <= kSweepSteps; ++step) {
      const auto w = basis(spline, static_cast<double>(step) / kSweepSteps);
      SweepSphere s;
      for (size_t k = 0; k < 4; ++k) {
        s.center += w[k] * p[i + k].center;
        s.radius += w[k] * p[i + k].radius;
      }
      path.push_back(s);
    }
  }
  return path;
}

SphereSweep::SphereSweep(const std::vector<SweepSphere>& path) {
  if (path.size() < 2) throw std::invalid_argument("sphere_sweep needs at least two spheres on its path");
  const auto add = [&](std::unique_ptr<Shape> shape) {
    const Bounds3 b = shape->bounds();
    bounds_.unite(b);
    parts_.push_back({std::move(shape), b});
  };
  for (size_t i = 0; i < path.size(); ++i) {
    if (!(path[i].radius > 0)) throw std::invalid_argument("sphere_sweep radii must be positive");
    add(std::make_unique<Sphere>(path[i].center, path[i].radius));
    if (i + 1 == path.size()) continue;
    // The cone tangent to both spheres: its half-angle a has sin a = (r1 - r2) / d, and it touches
    // sphere k in the circle of radius r_k cos a, r_k sin a along the axis from its centre.
    const Vec3 axis = path[i + 1].center - path[i].center;
    const double d = length(axis);
    const double r1 = path[i].radius, r2 = path[i + 1].radius;
    if (d <= std::fabs(r1 - r2)) continue;  // one sphere holds the other: nothing between them shows
    const Vec3 w = axis / d;
    const double sin_a = (r1 - r2) / d, cos_a = std::sqrt(1 - sin_a * sin_a);
    add(std::make_unique<Cone>(path[i].center + r1 * sin_a * w, r1 * cos_a,
                               path[i + 1].center + r2 * sin_a * w, r2 * cos_a, true));
  }
}

bool SphereSweep::inside_other(const Vec3& p, size_t part) const {
  for (size_t i = 0; i < parts_.size(); ++i) {
    if (i != part && parts_[i].bounds.contains(p) && parts_[i].shape->inside(p)) return true;
  }
  return false;
}

void SphereSweep::union_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  HitList part_hits;
  for (size_t i = 0; i < parts_.size(); ++i) {
    if (!ray_meets_box(ray, parts_[i].bounds, t_min, t_max)) continue;
    part_hits.clear();
    parts_[i].shape->all_hits(ray, t_min, t_max, part_hits);
    for (LocalHit& h : part_hits) {
      if (inside_other(ray.at(h.t), i)) continue;
      h.part = static_cast<int>(i);
      hits.push_back(h);
    }
  }
  std::sort(hits.begin(), hits.end(), [](const LocalHit& a, const LocalHit& b) { return a.t < b.t; });
}

bool SphereSweep::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  HitList hits;
  union_hits(ray, t_min, t_max, hits);
  if (hits.empty()) return false;
  hit = hits.front();
  return true;
}

void SphereSweep::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  HitList found;
  union_hits(ray, t_min, t_max, found);
  hits.insert(hits.end(), found.begin(), found.end());
}

bool SphereSweep::inside(const Vec3& p) const {
  return bounds_.contains(p) && inside_other(p, parts_.size());
}

}  // namespace snell::geometry
