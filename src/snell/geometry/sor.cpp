#include "snell/geometry/sor.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "snell/geometry/any_crossing.hpp"
#include "snell/geometry/axial_ray.hpp"
#include "snell/geometry/outline.hpp"
#include "snell/geometry/polynomial.hpp"

namespace snell::geometry {

Sor::Sor(std::span<const Vec2> p, bool open) : open_(open) {
  if (p.size() < 4) throw std::invalid_argument("sor needs at least four points");
  for (size_t i = 0; i + 3 < p.size(); ++i) {
    if (!(p[i + 2].v > p[i].v) || !(p[i + 3].v > p[i + 1].v) || !(p[i + 2].v > p[i + 1].v))
      throw std::invalid_argument("sor points must have increasing heights");
    // Squared radius and its slope d(r^2)/dy = 2 r dr/dy at both ends, the slope dr/dy taken from
    // the neighbours as POV-Ray's Compute_Sor does.
    const double k0 = p[i + 1].u * p[i + 1].u, k1 = p[i + 2].u * p[i + 2].u;
    const double m0 = 2 * p[i + 1].u * (p[i + 2].u - p[i].u) / (p[i + 2].v - p[i].v);
    const double m1 = 2 * p[i + 2].u * (p[i + 3].u - p[i + 1].u) / (p[i + 3].v - p[i + 1].v);
    const double h = p[i + 2].v - p[i + 1].v;
    // Hermite basis in w = (y - y0) / h, expanded in powers of w.
    pieces_.push_back(
        {p[i + 1].v,
         p[i + 2].v,
         {k0, h * m0, -3 * k0 - 2 * h * m0 + 3 * k1 - h * m1, 2 * k0 + h * m0 - 2 * k1 + h * m1}});
  }
  for (Piece& piece : pieces_) {
    // The range of r^2 over the piece: at its ends or where the derivative vanishes.
    double w0 = 0, w1 = 0;
    double top = std::max(piece.c[0], evaluate_polynomial(piece.c, 1));
    double bottom = std::min(piece.c[0], evaluate_polynomial(piece.c, 1));
    if (solve_quadratic(3 * piece.c[3], 2 * piece.c[2], piece.c[1], w0, w1)) {
      for (const double w : {w0, w1})
        if (w > 0 && w < 1) {
          top = std::max(top, evaluate_polynomial(piece.c, w));
          bottom = std::min(bottom, evaluate_polynomial(piece.c, w));
        }
    }
    radius_ = std::max(radius_, std::sqrt(std::max(0.0, top)));
    piece.r_min = std::sqrt(std::max(0.0, bottom));
    piece.r_max = std::sqrt(std::max(0.0, top));
  }
  reach_ = AxialReach(radius_, std::max(std::fabs(pieces_.front().y0), std::fabs(pieces_.back().y1)));
}

Bounds3 Sor::bounds() const {
  return {Vec3(-radius_, pieces_.front().y0, -radius_), Vec3(radius_, pieces_.back().y1, radius_)};
}

const Sor::Piece& Sor::piece_at(double y) const {
  for (const Piece& piece : pieces_)
    if (y <= piece.y1) return piece;
  return pieces_.back();
}

double Sor::radius_squared(double y) const {
  const Piece& piece = piece_at(y);
  return evaluate_polynomial(piece.c, (y - piece.y0) / (piece.y1 - piece.y0));
}

template <bool kExistence, typename F>
void Sor::crossings(const Ray& ray, double t_min, const double& t_max, F&& emit) const {
  AxialRay axial;
  if (!axial.prepare(ray) || axial.misses_cylinder(radius_)) return;
  const Vec3 o = axial.o, dn = axial.dn;
  const double a = axial.a, b = axial.b, c = axial.c;
  const auto accept = [&](double u, const Vec3& normal, int part) {
    const double t = axial.t_of(u);
    if (t > t_min && t < t_max) {
      LocalHit hit;
      hit.t = t;
      hit.normal = normal;
      hit.part = part;
      emit(hit);
    }
  };
  const auto side_normal = [&](double u) {
    const Vec3 p = o + u * dn;
    const Piece& piece = piece_at(p.y);
    const double h = piece.y1 - piece.y0, w = (p.y - piece.y0) / h;
    const double slope = (3 * piece.c[3] * w + 2 * piece.c[2]) * w + piece.c[1];
    // Gradient of x^2 + z^2 - r^2(y): outward.
    return Vec3(2 * p.x, -slope / h, 2 * p.z);
  };
  if (std::fabs(dn.y) < 1e-9) {
    // Horizontal: the circle of radius r(o.y) at the ray's height.
    if (o.y < pieces_.front().y0 || o.y > pieces_.back().y1) return;
    double u0 = 0, u1 = 0;
    if (solve_quadratic(a, b, c - radius_squared(o.y), u0, u1)) {
      accept(u0, side_normal(u0), 0);
      if (u1 != u0) accept(u1, side_normal(u1), 0);
    }
    return;
  }
  // The pieces climb in y, so the ray meets their height bands in order (reversed when it goes down): once
  // a band starts beyond t_max, which a nearest-hit caller lowers as it finds hits, no later piece can
  // hold a nearer root.
  const size_t count = pieces_.size();
  const auto heights = axial.heights_within(reach_.reach, axial.u_of(t_min), axial.u_of(t_max));
  for (size_t k = 0; k < count; ++k) {
    const Piece& piece = pieces_[dn.y > 0 ? k : count - 1 - k];
    if (reach_.skips(heights, piece.y0, piece.y1)) continue;
    const auto [t0, t1] = axial.band_span(piece.y0, piece.y1);
    if (t0 >= t_max) break;
    if (t1 <= t_min) continue;
    if (axial.misses_band(piece.y0, piece.y1, piece.r_min, piece.r_max)) continue;
    // u = (y - o.y) / dn.y = alpha + beta w along the piece.
    const double h = piece.y1 - piece.y0;
    const double alpha = (piece.y0 - o.y) / dn.y, beta = h / dn.y;
    const std::array<double, 4> eq{piece.c[0] - (a * alpha * alpha + b * alpha + c),
                                   piece.c[1] - (2 * a * alpha * beta + b * beta),
                                   piece.c[2] - a * beta * beta, piece.c[3]};
    if constexpr (kExistence) {
      // The window of w that maps into (t_min, t_max): a root there is a crossing.
      double w0 = (axial.u_of(t_min) - alpha) / beta, w1 = (axial.u_of(t_max) - alpha) / beta;
      if (w0 > w1) std::swap(w0, w1);
      if (has_root(eq, std::max(w0, -kJointSlack), std::min(w1, 1.0 + kJointSlack))) {
        emit(LocalHit{});
        return;
      }
      continue;
    }
    double roots[3];
    const int n = real_roots(eq, -kJointSlack, 1.0 + kJointSlack, std::span<double>(roots, 3));
    for (int k = 0; k < n; ++k) {
      const double u = alpha + beta * roots[k];
      accept(u, side_normal(u), static_cast<int>(&piece - pieces_.data()));
    }
  }
  if (open_) return;
  for (const bool top : {false, true}) {
    const double y = top ? pieces_.back().y1 : pieces_.front().y0;
    const double u = (y - o.y) / dn.y;
    const double r2 = top ? evaluate_polynomial(pieces_.back().c, 1) : pieces_.front().c[0];
    if (a * u * u + b * u + c <= r2) accept(u, Vec3(0, top ? 1 : -1, 0), -1);
  }
}

bool Sor::crosses(const Ray& ray, double t_min, double t_max) const {
  return any_crossing(t_max,
                      [&](const double& limit, auto&& emit) { crossings<true>(ray, t_min, limit, emit); });
}

bool Sor::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  bool found = false;
  hit.t = t_max;
  crossings(ray, t_min, hit.t, [&](const LocalHit& h) {
    if (h.t < hit.t) {
      hit = h;
      found = true;
    }
  });
  return found;
}

void Sor::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  thread_local HitList found;  // reused: no allocation per ray (crossings never re-enters all_hits)
  found.clear();
  crossings(ray, t_min, t_max, [&](const LocalHit& h) { found.push_back(h); });
  sort_and_drop_joint_duplicates(found, [](const LocalHit& h) { return static_cast<long>(h.part); });
  hits.insert(hits.end(), found.begin(), found.end());
}

bool Sor::inside(const Vec3& p) const {
  if (p.y < pieces_.front().y0 || p.y > pieces_.back().y1) return false;
  return p.x * p.x + p.z * p.z < radius_squared(p.y);
}

}  // namespace snell::geometry
