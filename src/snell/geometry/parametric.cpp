#include "snell/geometry/parametric.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "snell/math/constants.hpp"

namespace snell::geometry {

Parametric::Parametric(ParametricSettings settings) : settings_(std::move(settings)) {
  for (const auto& f : settings_.functions) {
    if (!f) throw std::invalid_argument("parametric: needs three functions");
    if (f->arity() != 3) throw std::invalid_argument("parametric: a function must take (u, v) as x, y, z");
  }
  if (!settings_.container) throw std::invalid_argument("parametric: missing container");
  if (!(settings_.accuracy > 0)) throw std::invalid_argument("parametric: accuracy must be positive");
  Vec2& lo = settings_.uv_min;
  Vec2& hi = settings_.uv_max;
  if (lo.u > hi.u) std::swap(lo.u, hi.u);  // POV-Ray orders the corners
  if (lo.v > hi.v) std::swap(lo.v, hi.v);
  const int n = std::clamp(settings_.lattice, 2, 1024);
  MeshData data;
  data.vertices.reserve(static_cast<size_t>((n + 1) * (n + 1)));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double u = lo.u + (hi.u - lo.u) * i / n, v = lo.v + (hi.v - lo.v) * j / n;
      const Vec3 p = point(u, v);
      data.vertices.push_back(is_finite(p) ? p : Vec3(0));
      data.uvs.push_back({u, v});
    }
  const auto at = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::array<int, 3> a{at(i, j), at(i + 1, j), at(i + 1, j + 1)};
      const std::array<int, 3> b{at(i, j), at(i + 1, j + 1), at(i, j + 1)};
      for (const auto& face : {a, b}) {
        const Vec3 e1 =
            data.vertices[static_cast<size_t>(face[1])] - data.vertices[static_cast<size_t>(face[0])];
        const Vec3 e2 =
            data.vertices[static_cast<size_t>(face[2])] - data.vertices[static_cast<size_t>(face[0])];
        if (!(length_squared(cross(e1, e2)) > 0)) continue;  // collapsed cells (poles) find nothing
        data.faces.push_back(face);
        data.uv_indices.push_back(face);
      }
    }
  if (data.faces.empty()) throw std::invalid_argument("parametric: the surface has no area");
  lattice_ = std::make_unique<Mesh>(std::move(data));
}

Vec3 Parametric::point(double u, double v) const {
  const double args[3] = {u, v, 0};
  return {settings_.functions[0]->call(args), settings_.functions[1]->call(args),
          settings_.functions[2]->call(args)};
}

Bounds3 Parametric::bounds() const {
  return settings_.container->bounds().intersection(lattice_->bounds());
}

Vec3 Parametric::normal_at(double u, double v) const {
  // Forward differences with step `accuracy` in u and v, as POV-Ray's Parametric::Normal.
  const double h = settings_.accuracy;
  const Vec3 p = point(u, v);
  return cross(point(u + h, v) - p, point(u, v + h) - p);
}

bool Parametric::polish(const Ray& ray, double& u, double& v, double& t) const {
  const Vec2 lo = settings_.uv_min, hi = settings_.uv_max;
  const double span = std::max(hi.u - lo.u, hi.v - lo.v);
  const double h = 1e-6 * span;  // central differences for the Jacobian
  const double scale = length(lattice_->bounds().extent());
  for (int iteration = 0; iteration < 12; ++iteration) {
    const Vec3 residual = point(u, v) - ray.at(t);
    if (!is_finite(residual)) return false;
    if (length(residual) < 1e-10 * scale) return true;
    const Vec3 su = (point(u + h, v) - point(u - h, v)) / (2 * h);
    const Vec3 sv = (point(u, v + h) - point(u, v - h)) / (2 * h);
    // Solve [su sv -d] (du, dv, dt) = -residual by Cramer's rule.
    const Vec3 nd = -ray.direction;
    const double det = dot(su, cross(sv, nd));
    if (!(std::fabs(det) > 0)) return false;
    const Vec3 r = -residual;
    u += dot(r, cross(sv, nd)) / det;
    v += dot(su, cross(r, nd)) / det;
    t += dot(su, cross(sv, r)) / det;
    const double slack = 1e-9 * span;
    if (u < lo.u - slack || u > hi.u + slack || v < lo.v - slack || v > hi.v + slack) return false;
  }
  return length(point(u, v) - ray.at(t)) < 1e-6 * scale;
}

bool Parametric::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  HitList candidates;
  lattice_->all_hits(ray, t_min, t_max, candidates);
  bool found = false;
  for (const LocalHit& c : candidates) {
    if (found && c.t >= hit.t) break;
    double u = c.uv.u, v = c.uv.v, t = c.t;
    // Off the lattice's facet onto the surface; a failed polish keeps the facet's hit.
    if (!polish(ray, u, v, t)) u = c.uv.u, v = c.uv.v, t = c.t;
    if (!(t > t_min && t < t_max) || (found && t >= hit.t)) continue;
    if (!settings_.container->inside(ray.at(t))) continue;
    hit = LocalHit{};
    hit.t = t;
    hit.normal = normal_at(u, v);
    if (!(length_squared(hit.normal) > 0) || !is_finite(hit.normal)) hit.normal = c.normal;
    hit.uv = {u, v};
    found = true;
  }
  return found;
}

void Parametric::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  LocalHit hit;
  if (intersect(ray, t_min, t_max, hit)) hits.push_back(hit);
}

}  // namespace snell::geometry
