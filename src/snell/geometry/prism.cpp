#include "snell/geometry/prism.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "snell/geometry/any_crossing.hpp"
#include "snell/math/constants.hpp"

namespace snell::geometry {

Prism::Prism(Outline outline, double height1, double height2, Sweep sweep, bool open, bool outline_in_xy)
    : outline_(std::move(outline)),
      h1_(std::min(height1, height2)),
      h2_(std::max(height1, height2)),
      sweep_(sweep),
      open_(open),
      outline_in_xy_(outline_in_xy) {
  if (!std::isfinite(h1_) || !std::isfinite(h2_)) throw std::invalid_argument("prism heights must be finite");
}

Bounds3 Prism::bounds() const {
  const Vec2 lo = outline_.lo(), hi = outline_.hi();
  Bounds3 b;
  // A conic sweep scales the outline by the height: the extremes are at the two end heights.
  for (const double h : {h1_, h2_}) {
    const double s = sweep_ == Sweep::conic ? h : 1.0;
    b.unite(to_local(Vec3(s * lo.u, h, s * lo.v)));
    b.unite(to_local(Vec3(s * hi.u, h, s * hi.v)));
  }
  return b;
}

namespace {

/// [lo, hi]: the values of o + t d for t in [t0, t1] (t1 may be infinite), widened well beyond the rounding
/// of the wall points computed from them.
void span_over(double o, double d, double t0, double t1, double& lo, double& hi) {
  if (d == 0) {
    lo = hi = o;
  } else {
    const double a = o + t0 * d, b = o + t1 * d;
    lo = std::min(a, b);
    hi = std::max(a, b);
  }
  const double scale =
      1 + std::fabs(o) + (std::isfinite(lo) ? std::fabs(lo) : 0) + (std::isfinite(hi) ? std::fabs(hi) : 0);
  lo -= 1e-9 * scale;
  hi += 1e-9 * scale;
}

}  // namespace

template <typename F>
void Prism::crossings(const Ray& local, double t_min, const double& t_max, F&& emit) const {
  // Walls first: a cap costs an outline containment test, skipped once a nearer wall crossing has
  // lowered t_max (or once a shadow ray has found one).
  wall_crossings(local, t_min, t_max, emit);
  if (open_ || local.direction.y == 0) return;
  const Vec3 o = local.origin, d = local.direction;
  // Caps: the planes y = h1 and y = h2, inside the outline (scaled by the height for a conic sweep).
  for (const int cap : {-1, -2}) {
    const double h = cap == -1 ? h1_ : h2_;
    const double scale = sweep_ == Sweep::conic ? h : 1.0;
    if (scale == 0) continue;
    const double t = (h - o.y) / d.y;
    if (!(t > t_min && t < t_max)) continue;
    if (outline_.contains({(o.x + t * d.x) / scale, (o.z + t * d.z) / scale})) emit(Crossing{t, cap, 0});
  }
}

template <typename F>
void Prism::wall_crossings(const Ray& local, double t_min, const double& t_max, F&& emit) const {
  const Vec3 o = local.origin, d = local.direction;
  const auto accept = [&](double t, int piece, double s) {
    if (t > t_min && t < t_max) emit(Crossing{t, piece, s});
  };
  // Walls: the line of the outline plane that the ray's sweep plane cuts.
  Vec2 n;
  double k;
  if (sweep_ == Sweep::linear) {
    n = {d.z, -d.x};
    k = -(n.u * o.x + n.v * o.z);
  } else {
    const Vec3 m = cross(o, d);  // normal of the plane through the apex and the ray
    n = {m.x, m.z};
    k = m.y;
  }
  const double norm = std::hypot(n.u, n.v);
  if (!(norm > 0)) return;  // parallel to the walls
  n = {n.u / norm, n.v / norm};
  k /= norm;
  const auto wall = [&](size_t piece, double s) {
    const Vec2 q = outline_.pieces()[piece].at(s);
    double t;
    if (sweep_ == Sweep::linear) {
      t = std::fabs(d.x) > std::fabs(d.z) ? (q.u - o.x) / d.x : (q.v - o.z) / d.z;
    } else {
      // o + t d = y (q.u, 1, q.v): solve the x or the z equation, whichever is better conditioned.
      const double den_x = d.x - q.u * d.y, den_z = d.z - q.v * d.y;
      t = std::fabs(den_x) > std::fabs(den_z) ? (q.u * o.y - o.x) / den_x : (q.v * o.y - o.z) / den_z;
    }
    const double y = o.y + t * d.y;
    if (y >= h1_ && y <= h2_) accept(t, static_cast<int>(piece), s);
  };
  const auto& pieces = outline_.pieces();
  const double across = d.x * d.x + d.z * d.z;
  if (sweep_ != Sweep::linear || !(across > 0)) {
    outline_.for_each_crossing(n, k, wall);
    return;
  }
  // A linear sweep's wall point at t lies over (o.x, o.z) + t (d.x, d.z): a piece's box bounds the t of its
  // crossings from below. Pieces are solved nearest box first, and not at all once their box lies beyond
  // t_max, which a nearest-hit caller lowers as it finds hits.
  struct Near {
    double t0;
    size_t piece;
  };
  thread_local std::vector<Near> order;  // used up before any other prism's test on this thread
  order.clear();
  // Walls stand between the heights h1 and h2: only that stretch of the ray can cross them.
  double t_low = t_min, t_high = math::kInfinity;
  if (d.y != 0) {
    const double ta = (h1_ - o.y) / d.y, tb = (h2_ - o.y) / d.y;
    const double slack = 1e-9 * (1 + std::fabs(ta) + std::fabs(tb));
    t_low = std::max(t_low, std::min(ta, tb) - slack);
    t_high = std::max(ta, tb) + slack;
  } else if (o.y < h1_ || o.y > h2_) {
    return;
  }
  // The walls' points on the ray lie over the stretch of (o.x, o.z) + t (d.x, d.z) for t in [t_low, t_end]:
  // only pieces whose rectangles meet it are looked at (outline.hpp's piece tree).
  const double t_end = std::min(t_high, t_max);
  Vec2 lo, hi;
  span_over(o.x, d.x, t_low, t_end, lo.u, hi.u);
  span_over(o.z, d.z, t_low, t_end, lo.v, hi.v);
  outline_.for_each_piece_near(lo, hi, n, k, [&](uint32_t i) {
    const CurveSegment& p = pieces[i];
    if (!p.line_may_cross(n, k)) return;
    const double a0 = (p.lo.u - o.x) * d.x, a1 = (p.hi.u - o.x) * d.x;
    const double b0 = (p.lo.v - o.z) * d.z, b1 = (p.hi.v - o.z) * d.z;
    const double t0 = (std::min(a0, a1) + std::min(b0, b1)) / across;
    const double t1 = (std::max(a0, a1) + std::max(b0, b1)) / across;
    const double slack = 1e-9 * (1 + std::fabs(t0) + std::fabs(t1));
    if (t1 + slack <= t_low || t0 - slack >= t_high) return;
    order.push_back({t0 - slack, i});
  });
  std::sort(order.begin(), order.end(), [](const Near& a, const Near& b) { return a.t0 < b.t0; });
  double roots[3];
  for (const Near& near : order) {
    if (near.t0 >= t_max) break;
    const int count = outline_.piece_crossings(near.piece, n, k, roots);
    for (int r = 0; r < count; ++r) wall(near.piece, roots[r]);
  }
}

LocalHit Prism::make_hit(const Ray& local, const Crossing& c) const {
  LocalHit hit;
  hit.t = c.t;
  hit.part = c.piece;
  if (c.piece < 0) {
    hit.normal = to_local(Vec3(0, c.piece == -1 ? -1 : 1, 0));
    return hit;
  }
  const CurveSegment& piece = outline_.pieces()[static_cast<size_t>(c.piece)];
  Vec2 tangent = piece.tangent(c.s);
  if (tangent.u == 0 && tangent.v == 0) tangent = piece.tangent(0.5 + 0.999 * (c.s - 0.5));  // a cusp
  Vec3 n;
  if (sweep_ == Sweep::linear) {
    n = Vec3(tangent.v, 0, -tangent.u);
  } else {
    // Cross product of the surface's two tangents y (u', 0, w') and (u, 1, w), up to sign.
    const Vec2 q = piece.at(c.s);
    n = Vec3(tangent.v, tangent.u * q.v - tangent.v * q.u, -tangent.u);
  }
  n = normalize(n);
  // The even-odd rule fixes which side is solid, not the pieces' direction: look just beyond the wall.
  const Vec3 p = local.at(c.t);
  const double step = 1e-7 * (1 + length(bounds().extent()));
  if (inside_local(p + step * n) && !inside_local(p - step * n)) n = -n;
  hit.normal = to_local(n);
  return hit;
}

bool Prism::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  const Ray local{to_local(ray.origin), to_local(ray.direction), ray.time};
  bool found = false;
  Crossing best{t_max, 0, 0};
  crossings(local, t_min, best.t, [&](const Crossing& c) {
    if (c.t < best.t) {
      best = c;
      found = true;
    }
  });
  if (found) hit = make_hit(local, best);
  return found;
}

bool Prism::crosses(const Ray& ray, double t_min, double t_max) const {
  const Ray local{to_local(ray.origin), to_local(ray.direction), ray.time};
  return any_crossing(t_max, [&](const double& limit, auto&& emit) { crossings(local, t_min, limit, emit); });
}

void Prism::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  const Ray local{to_local(ray.origin), to_local(ray.direction), ray.time};
  thread_local std::vector<Crossing> found;  // reused: no allocation per ray
  found.clear();
  crossings(local, t_min, t_max, [&](const Crossing& c) { found.push_back(c); });
  sort_and_drop_joint_duplicates(found, [](const Crossing& c) { return c.piece; });
  for (const Crossing& c : found) hits.push_back(make_hit(local, c));
}

bool Prism::inside_local(const Vec3& p) const {
  if (p.y < h1_ || p.y > h2_) return false;
  const double scale = sweep_ == Sweep::conic ? p.y : 1.0;
  if (scale == 0) return false;
  return outline_.contains({p.x / scale, p.z / scale});
}

bool Prism::inside(const Vec3& p) const {
  return inside_local(to_local(p));
}

}  // namespace snell::geometry
