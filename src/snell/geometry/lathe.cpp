#include "snell/geometry/lathe.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "snell/geometry/any_crossing.hpp"
#include "snell/geometry/axial_ray.hpp"
#include "snell/geometry/polynomial.hpp"

namespace snell::geometry {
namespace {

using Cubic = std::array<double, 4>;
using Sextic = std::array<double, 7>;

Sextic product(const Cubic& p, const Cubic& q) {
  Sextic r{};
  for (size_t i = 0; i < 4; ++i)
    for (size_t j = 0; j < 4; ++j) r[i + j] += p[i] * q[j];
  return r;
}

}  // namespace

Lathe::Lathe(Outline profile) : profile_(std::move(profile)) {
  radius_ = std::max(std::fabs(profile_.lo().u), std::fabs(profile_.hi().u));
  reach_ = AxialReach(radius_, std::max(std::fabs(profile_.lo().v), std::fabs(profile_.hi().v)));
}

Bounds3 Lathe::bounds() const {
  return {Vec3(-radius_, profile_.lo().v, -radius_), Vec3(radius_, profile_.hi().v, radius_)};
}

template <bool kExistence, typename F>
void Lathe::crossings(const Ray& ray, double t_min, const double& t_max, F&& emit) const {
  AxialRay axial;
  if (!axial.prepare(ray) || axial.misses_cylinder(radius_)) return;
  const Vec3 o = axial.o, dn = axial.dn;
  const double a = axial.a, b = axial.b, c = axial.c;
  const auto accept = [&](double u, size_t piece, double s) {
    const double t = axial.t_of(u);
    if (t > t_min && t < t_max) emit(Crossing{t, piece, s});
  };
  // The quadratic for u at a profile point of radius r, for rays nearly perpendicular to the axis.
  const auto radial_solutions = [&](double r, double u_guess, bool both, size_t piece, double s) {
    double u0 = 0, u1 = 0;
    if (!solve_quadratic(a, b, c - r * r, u0, u1)) {
      if (!both) accept(u_guess, piece, s);
      return;
    }
    if (both) {
      accept(u0, piece, s);
      if (u1 != u0) accept(u1, piece, s);
    } else {
      accept(std::fabs(u0 - u_guess) < std::fabs(u1 - u_guess) ? u0 : u1, piece, s);
    }
  };
  const bool horizontal = std::fabs(dn.y) < 1e-9;
  const auto& pieces = profile_.pieces();
  if (horizontal) {
    for (size_t i = 0; i < pieces.size(); ++i) {
      const CurveSegment& piece = pieces[i];
      const double slack = 1e-9 * (1 + std::fabs(o.y));
      if (o.y < piece.lo.v - slack || o.y > piece.hi.v + slack) continue;
      const Cubic r{piece.d.u, piece.c.u, piece.b.u, piece.a.u};
      const Cubic y{piece.d.v - o.y, piece.c.v, piece.b.v, piece.a.v};
      std::array<double, 3> roots{};
      const int n = real_roots(y, -kJointSlack, 1.0 + kJointSlack, std::span<double>(roots));
      for (int k = 0; k < n; ++k) radial_solutions(evaluate_polynomial(r, roots[k]), 0, true, i, roots[k]);
    }
    return;
  }
  // The pieces whose height band the ray crosses within (t_min, t_max) near its ring, nearest band first:
  // once a band starts beyond t_max (which a nearest-hit caller lowers as it finds hits) no later piece
  // can hold a nearer root, and its sextic is never solved (as POV-Ray's per-segment bounding cylinders).
  struct Band {
    double t0, t1;
    size_t piece;
  };
  thread_local std::vector<Band> bands;
  bands.clear();
  const auto heights = axial.heights_within(reach_.reach, axial.u_of(t_min), axial.u_of(t_max));
  for (size_t i = 0; i < pieces.size(); ++i) {
    const CurveSegment& piece = pieces[i];
    if (reach_.skips(heights, piece.lo.v, piece.hi.v)) continue;
    const auto [t0, t1] = axial.band_span(piece.lo.v, piece.hi.v);
    if (t1 <= t_min || t0 >= t_max) continue;
    const double r_max = std::max(std::fabs(piece.lo.u), std::fabs(piece.hi.u));
    const double r_min = piece.lo.u > 0 ? piece.lo.u : piece.hi.u < 0 ? -piece.hi.u : 0;
    if (axial.misses_band(piece.lo.v, piece.hi.v, r_min, r_max)) continue;
    bands.push_back({t0, t1, i});
  }
  std::sort(bands.begin(), bands.end(), [](const Band& p, const Band& q) { return p.t0 < q.t0; });
  for (const Band& band : bands) {
    if (band.t0 >= t_max) break;
    const size_t i = band.piece;
    const CurveSegment& piece = pieces[i];
    const Cubic r{piece.d.u, piece.c.u, piece.b.u, piece.a.u};
    const Cubic y{piece.d.v - o.y, piece.c.v, piece.b.v, piece.a.v};  // height above the ray's origin
    std::array<double, 6> roots{};
    // dn.y^2 r(s)^2 = a Y(s)^2 + b dn.y Y(s) + c dn.y^2, with Y(s) = y(s) - o.y = u dn.y.
    const Sextic r2 = product(r, r), y2 = product(y, y);
    Sextic eq{};
    for (size_t k = 0; k < 7; ++k) eq[k] = a * y2[k] - dn.y * dn.y * r2[k];
    for (size_t k = 0; k < 4; ++k) eq[k] += b * dn.y * y[k];
    eq[0] += c * dn.y * dn.y;
    if constexpr (kExistence) {
      // A root's crossing is at its height on the piece, inside the band (u from the height, as below):
      // with the whole band in the window, that a root exists is enough.
      if (std::fabs(dn.y) > 0.1 && band.t0 > t_min && band.t1 < t_max) {
        if (has_root(eq, -kJointSlack, 1.0 + kJointSlack)) {
          emit(Crossing{band.t0, i, 0});
          return;
        }
        continue;
      }
    }
    const int n = real_roots(eq, -kJointSlack, 1.0 + kJointSlack, roots);
    for (int k = 0; k < n; ++k) {
      const double u = evaluate_polynomial(y, roots[k]) / dn.y;
      if (std::fabs(dn.y) > 0.1) {
        accept(u, i, roots[k]);
      } else {
        // Nearly horizontal: u from the height is ill-conditioned; take the radial solution nearest it.
        radial_solutions(evaluate_polynomial(r, roots[k]), u, false, i, roots[k]);
      }
    }
  }
}

LocalHit Lathe::make_hit(const Ray& ray, const Crossing& c) const {
  LocalHit hit;
  hit.t = c.t;
  hit.part = static_cast<int>(c.piece);
  const Vec3 p = ray.at(c.t);
  const double rho = std::sqrt(p.x * p.x + p.z * p.z);
  const Vec3 radial = rho > 0 ? Vec3(p.x / rho, 0, p.z / rho) : Vec3(1, 0, 0);
  const CurveSegment& piece = profile_.pieces()[c.piece];
  Vec2 tangent = piece.tangent(c.s);
  if (tangent.u == 0 && tangent.v == 0) tangent = piece.tangent(0.5 + 0.999 * (c.s - 0.5));  // a cusp
  Vec3 n = normalize(tangent.v * radial + Vec3(0, -tangent.u, 0));
  // The profile's direction does not say which side is solid; look just beyond the surface.
  const double step = 1e-7 * (1 + radius_ + profile_.hi().v - profile_.lo().v);
  if (inside(p + step * n) && !inside(p - step * n)) n = -n;
  hit.normal = n;
  hit.uv = {0.5 + std::atan2(p.z, p.x) * 0.5 * math::kInvPi, c.s};
  return hit;
}

bool Lathe::crosses(const Ray& ray, double t_min, double t_max) const {
  return any_crossing(t_max,
                      [&](const double& limit, auto&& emit) { crossings<true>(ray, t_min, limit, emit); });
}

bool Lathe::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  bool found = false;
  Crossing best{t_max, 0, 0};
  crossings(ray, t_min, best.t, [&](const Crossing& c) {
    if (c.t < best.t) {
      best = c;
      found = true;
    }
  });
  if (found) hit = make_hit(ray, best);
  return found;
}

void Lathe::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  std::vector<Crossing> found;
  crossings(ray, t_min, t_max, [&](const Crossing& c) { found.push_back(c); });
  sort_and_drop_joint_duplicates(found, [](const Crossing& c) { return static_cast<long>(c.piece); });
  for (const Crossing& c : found) hits.push_back(make_hit(ray, c));
}

bool Lathe::inside(const Vec3& p) const {
  // Even-odd rule in the profile plane; r >= 0 makes the axis close an open profile.
  return profile_.contains({std::sqrt(p.x * p.x + p.z * p.z), p.y});
}

}  // namespace snell::geometry
