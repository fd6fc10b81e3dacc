// Ray / round-cone crossings: the frustum side solved as a quadratic in t, the end caps as spheres; a
// crossing that lies inside another piece of the same cone is an inner surface and is dropped.
#include "snell/geometry/branch_set.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "snell/geometry/compact_bvh.hpp"
#include "snell/math/constants.hpp"

namespace snell::geometry {

namespace {

struct Piece {
  Vec3 a, axis;
  double length, r0, r1;
  explicit Piece(const RoundCone& c)
      : a(c.a[0], c.a[1], c.a[2]),
        axis(c.axis[0], c.axis[1], c.axis[2]),
        length(c.length),
        r0(c.r0),
        r1(c.r1) {}
  Vec3 b() const { return a + axis * length; }
  double slope() const { return length > 0 ? (r1 - r0) / length : 0; }
};

constexpr double kInnerTolerance = 1e-6;

bool inside_ball(const Vec3& p, const Vec3& c, double r) {
  return length_squared(p - c) < r * r * (1 - kInnerTolerance);
}

bool inside_frustum(const Piece& k, const Vec3& p) {
  const Vec3 w = p - k.a;
  const double s = dot(w, k.axis);
  if (!(s > 0 && s < k.length)) return false;
  const double r = k.r0 + k.slope() * s;
  return length_squared(w) - s * s < r * r * (1 - kInnerTolerance);
}

/// Crossing candidates of one cone: up to 2 per piece, with their outward normals (unnormalised).
struct Candidates {
  double t[6];
  Vec3 n[6];
  int piece[6];
  int count = 0;
  void add(double tt, const Vec3& nn, int p) { t[count] = tt, n[count] = nn, piece[count] = p, ++count; }
};

void sphere_candidates(const Ray& ray, const Vec3& c, double r, int piece, Candidates& out) {
  const Vec3 oc = ray.origin - c;
  const double a = length_squared(ray.direction), b = dot(oc, ray.direction), cc = length_squared(oc) - r * r;
  const double disc = b * b - a * cc;
  if (!(disc >= 0) || r <= 0) return;
  const double root = std::sqrt(disc);
  for (const double t : {(-b - root) / a, (-b + root) / a}) out.add(t, ray.at(t) - c, piece);
}

// The side |w - (w.u)u| = r0 + k (w.u) with w = o + t d - a; squared it is quadratic in t.
void frustum_candidates(const Ray& ray, const Piece& k, Candidates& out) {
  const Vec3 oa = ray.origin - k.a;
  const double slope = k.slope();
  const double sa = dot(oa, k.axis), sd = dot(ray.direction, k.axis);
  const double ra = k.r0 + slope * sa, rd = slope * sd;
  const double qa = length_squared(ray.direction) - sd * sd - rd * rd;
  const double qb = dot(oa, ray.direction) - sa * sd - ra * rd;
  const double qc = length_squared(oa) - sa * sa - ra * ra;
  if (std::abs(qa) < 1e-300) return;
  const double disc = qb * qb - qa * qc;
  if (!(disc >= 0)) return;
  const double root = std::sqrt(disc);
  for (const double t : {(-qb - root) / qa, (-qb + root) / qa}) {
    const Vec3 w = ray.at(t) - k.a;
    const double s = dot(w, k.axis);
    const double r = k.r0 + slope * s;
    if (!(s >= 0 && s <= k.length) || r <= 0) continue;
    out.add(t, (w - k.axis * s) - k.axis * (r * slope), 0);
  }
}

/// Whether the crossing of `piece` at p is on the cone's outer surface (inside none of the other pieces).
bool on_outer_surface(const Piece& k, int piece, const Vec3& p) {
  if (piece != 0 && inside_frustum(k, p)) return false;
  if (piece != 1 && inside_ball(p, k.a, k.r0)) return false;
  if (piece != 2 && inside_ball(p, k.b(), k.r1)) return false;
  return true;
}

}  // namespace

BranchSet::BranchSet(std::span<const BranchInput> branches) {
  std::vector<Bounds3> boxes;
  boxes.reserve(branches.size());
  cones_.reserve(branches.size());
  for (const BranchInput& in : branches) {
    const double length = std::sqrt(length_squared(in.b - in.a));
    if (!(in.r0 >= 0 && in.r1 >= 0) || (length == 0 && std::max(in.r0, in.r1) == 0)) continue;
    const Vec3 axis = length > 0 ? (in.b - in.a) / length : Vec3(0, 1, 0);
    const auto f = [](double v) { return static_cast<float>(v); };
    cones_.push_back({{f(in.a.x), f(in.a.y), f(in.a.z)},
                      {f(axis.x), f(axis.y), f(axis.z)},
                      f(length),
                      f(in.r0),
                      f(in.r1)});
    const Piece k(cones_.back());
    Bounds3 box(k.a - Vec3(k.r0), k.a + Vec3(k.r0));
    box.unite(k.b() - Vec3(k.r1)).unite(k.b() + Vec3(k.r1));
    boxes.push_back(box);
  }
  if (cones_.empty()) throw std::invalid_argument("the L-system draws no branches");
  bvh_ = std::make_unique<CompactBvh>(boxes);
  boxes = {};
  // Store the cones in the tree's order, so its leaves index them directly: permute in place, cycle by
  // cycle (slot i takes cone order[i]), marking finished slots in a bit per cone.
  const std::vector<std::uint32_t>& order = bvh_->order();
  std::vector<bool> done(cones_.size(), false);
  for (std::size_t start = 0; start < cones_.size(); ++start) {
    if (done[start]) continue;
    const RoundCone first = cones_[start];
    std::size_t slot = start;
    while (order[slot] != start) {
      cones_[slot] = cones_[order[slot]];
      done[slot] = true;
      slot = order[slot];
    }
    cones_[slot] = first;
    done[slot] = true;
  }
  bvh_->drop_order();
}

BranchSet::~BranchSet() = default;

Bounds3 BranchSet::bounds() const {
  return bvh_->bounds();
}

std::size_t BranchSet::bytes() const {
  return cones_.capacity() * sizeof(RoundCone) + bvh_->bytes();
}

template <class Sink>
void BranchSet::crossings(const Ray& ray, double t_min, double& t_max, Sink&& sink) const {
  bvh_->traverse(ray, t_min, t_max, [&](int index, double& t_limit) {
    const Piece k(cones_[static_cast<std::size_t>(index)]);
    Candidates c;
    frustum_candidates(ray, k, c);
    sphere_candidates(ray, k.a, k.r0, 1, c);
    sphere_candidates(ray, k.b(), k.r1, 2, c);
    for (int i = 0; i < c.count; ++i) {
      if (!(c.t[i] > t_min && c.t[i] < t_limit)) continue;
      if (!on_outer_surface(k, c.piece[i], ray.at(c.t[i]))) continue;
      LocalHit hit;
      hit.t = c.t[i];
      hit.normal = c.n[i];
      hit.part = index;
      const double s = dot(ray.at(c.t[i]) - k.a, k.axis);
      hit.uv = {k.length > 0 ? std::clamp(s / k.length, 0.0, 1.0) : 0.0, 0.0};
      sink(hit, t_limit);
    }
  });
}

bool BranchSet::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  bool found = false;
  double t_far = t_max;
  crossings(ray, t_min, t_far, [&](const LocalHit& h, double& t_limit) {
    if (h.t >= t_limit) return;
    t_limit = h.t;
    hit = h;
    found = true;
  });
  return found;
}

void BranchSet::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  const std::size_t first = hits.size();
  double t_far = t_max;
  crossings(ray, t_min, t_far, [&](const LocalHit& h, double&) { hits.push_back(h); });
  std::sort(hits.begin() + static_cast<std::ptrdiff_t>(first), hits.end(),
            [](const LocalHit& a, const LocalHit& b) { return a.t < b.t; });
}

bool BranchSet::inside(const Vec3& p) const {
  // A ray segment of zero length visits exactly the leaves whose boxes contain p.
  const Ray probe{p, Vec3(1, 1, 1), 0};
  double t_far = 0;
  bool found = false;
  bvh_->traverse(probe, 0.0, t_far, [&](int index, double&) {
    if (found) return;
    const Piece k(cones_[static_cast<std::size_t>(index)]);
    found = inside_frustum(k, p) || inside_ball(p, k.a, k.r0) || inside_ball(p, k.b(), k.r1);
  });
  return found;
}

}  // namespace snell::geometry
