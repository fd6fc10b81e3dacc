#include "snell/scene/csg.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>

#include "snell/scene/object.hpp"

namespace snell::scene {

namespace {

/// `b` grown by a margin well above the rounding of hit points on its faces (relative 1e-7 of the
/// coordinates, as intersection routines in double keep more than 9 digits), so that a hit exactly on a
/// bounding face is never clipped away. Infinite sides stay infinite.
math::Bounds3 padded(const math::Bounds3& b) {
  if (b.empty()) return b;
  math::Bounds3 r = b;
  for (int a = 0; a < 3; ++a) {
    const double lo = b.lo[a], hi = b.hi[a];
    if (std::isfinite(lo)) r.lo[a] = lo - (1e-7 + 1e-7 * std::fabs(lo));
    if (std::isfinite(hi)) r.hi[a] = hi + (1e-7 + 1e-7 * std::fabs(hi));
  }
  return r;
}

/// A hit list reused by later calls on this thread, one per level of CSG nesting (a child may be CSG
/// itself and use its own while the parent's is live), so that testing a ray allocates nothing.
class ScratchHits {
 public:
  ScratchHits() : list_(take()) { list_.clear(); }
  ~ScratchHits() { --depth(); }
  ScratchHits(const ScratchHits&) = delete;
  ScratchHits& operator=(const ScratchHits&) = delete;
  std::vector<SurfaceHit>& list() { return list_; }

 private:
  static size_t& depth() {
    thread_local size_t level = 0;
    return level;
  }
  static std::vector<SurfaceHit>& take() {
    thread_local std::deque<std::vector<SurfaceHit>> pool;  // a deque keeps references on growth
    if (depth() == pool.size()) pool.emplace_back();
    return pool[depth()++];
  }
  std::vector<SurfaceHit>& list_;
};

/// Whether the points `o` counts inside (its `inverse` included) all lie within o.solid_bounds(): not
/// so where a shape's inside leaves its bounds (a disc's half-space) or the object moves.
bool solid_bounds_hold(const Object& o) {
  if (o.motion) return false;
  if (o.flags.inverse) return true;  // its solid bounds are infinite
  if (o.csg) {
    for (const auto& c : o.csg->children())
      if (!solid_bounds_hold(*c)) return false;
    return true;
  }
  return o.shape && o.shape->inside_within_bounds();
}

/// A box outside which `child` is never inside (before its `inverse`), for the quick test of
/// Csg::child_inside: a plain shape's bounds where its inside lies within them, a CSG child's solid bounds
/// where they hold for all its children (most points of the benchmark's sockets then skip its merges
/// without testing their children); infinite otherwise.
math::Bounds3 inside_box(const Object& child) {
  if (child.motion) return math::Bounds3::infinite();
  if (child.csg) {
    for (const auto& c : child.csg->children())
      if (!solid_bounds_hold(*c)) return math::Bounds3::infinite();
    return padded(child.csg->solid_bounds());
  }
  if (child.shape && child.shape->inside_within_bounds()) return padded(child.world_bounds());
  return math::Bounds3::infinite();
}

}  // namespace

Csg::Csg(CsgKind kind, std::vector<std::shared_ptr<const Object>> children, size_t surface_children)
    : kind_(kind), children_(std::move(children)) {
  if (children_.empty()) throw std::invalid_argument("a CSG object needs at least one child");
  for (const auto& c : children_)
    if (!c) throw std::invalid_argument("a CSG child is null");
  surface_children_ = surface_children == 0 ? children_.size() : std::min(surface_children, children_.size());
  if (kind_ == CsgKind::intersection) {
    solid_bounds_ = math::Bounds3::infinite();
    for (const auto& c : children_) solid_bounds_ = solid_bounds_.intersection(c->solid_bounds());
    // Unbounded children (quadrics, planes at an angle) confined to what the others allow, twice so
    // that a child confined late can still narrow one before it.
    for (int pass = 0; pass < 2 && !solid_bounds_.empty(); ++pass)
      for (const auto& c : children_) solid_bounds_ = c->solid_bounds_within(solid_bounds_);
    for (size_t i = 0; i < surface_children_; ++i) bounds_.unite(children_[i]->world_bounds());
    bounds_ = bounds_.intersection(solid_bounds_);
  } else {
    for (const auto& c : children_) {
      bounds_.unite(c->world_bounds());
      solid_bounds_.unite(c->solid_bounds());
    }
  }
  clip_bounds_ = padded(bounds_);
  for (size_t i = 0; i < surface_children_; ++i)
    child_clip_bounds_.push_back(padded(children_[i]->world_bounds()));
  for (const auto& c : children_) inside_boxes_.push_back(inside_box(*c));
  find_box_children();
}

bool Csg::child_inside(size_t j, const math::Vec3& p, double time) const {
  if (!inside_boxes_[j].contains(p)) return children_[j]->flags.inverse;
  return children_[j]->inside(p, time);
}

bool Csg::clip_to_bounds(const math::Ray& ray, double& t_min, double& t_max) const {
  if (clip_bounds_.empty()) return false;
  return clip_bounds_.clip(ray, t_min, t_max);
}

bool Csg::may_hit_child(size_t i, const math::Ray& ray, double t_min, double t_max) const {
  const math::Bounds3& b = child_clip_bounds_[i];
  return !b.empty() && b.clip(ray, t_min, t_max);
}

bool Csg::keeps(CsgKind kind, size_t i, const math::Vec3& p, double time) const {
  switch (kind) {
    case CsgKind::union_of:
      return true;
    case CsgKind::merge:
      for (size_t j = 0; j < children_.size(); ++j)
        if (j != i && child_inside(j, p, time)) return false;
      return true;
    case CsgKind::intersection:
      for (size_t j = 0; j < children_.size(); ++j)
        if (j != i && !child_inside(j, p, time)) return false;
      return true;
  }
  return true;
}

bool Csg::intersect(const math::Ray& ray, double t_min, double t_max, SurfaceHit& hit, bool inverted) const {
  const CsgKind kind = surface_kind(inverted);
  bool found = false;
  if (!clip_to_bounds(ray, t_min, t_max)) return false;
  if (!box_children_.empty()) return intersect_boxes(ray, t_min, t_max, &hit);
  ScratchHits scratch;
  std::vector<SurfaceHit>& hits = scratch.list();
  for (size_t i = 0; i < surface_children_; ++i) {
    if (!may_hit_child(i, ray, t_min, t_max)) continue;
    const Object& child = *children_[i];
    if (kind == CsgKind::union_of) {
      if (child.intersect(ray, t_min, t_max, hit, inverted)) {
        t_max = hit.t;
        found = true;
      }
      continue;
    }
    if (!child.csg && !child.motion) {
      // A plain shape: the other children decide on the hit point alone, so only the hit kept becomes a
      // world-space hit (its normals transformed) - most candidates of a difference or intersection are not.
      thread_local geometry::HitList local;  // used up before the next child's test starts
      local.clear();
      child.shape->all_hits(child.transform.inverse_ray(ray), t_min, t_max, local);
      for (const geometry::LocalHit& l : local) {
        if (!keeps(kind, i, ray.at(l.t), ray.time)) continue;
        hit = child.to_world(ray, l);
        t_max = l.t;
        found = true;
        break;  // hits come in increasing t: the first kept one is this child's nearest
      }
      continue;
    }
    hits.clear();
    child.all_hits(ray, t_min, t_max, hits, inverted);
    for (const SurfaceHit& h : hits) {
      if (!keeps(kind, i, h.point, ray.time)) continue;
      hit = h;
      t_max = h.t;
      found = true;
      break;  // hits come in increasing t: the first kept one is this child's nearest
    }
  }
  return found;
}

bool Csg::crosses(const math::Ray& ray, double t_min, double t_max, bool inverted) const {
  const CsgKind kind = surface_kind(inverted);
  if (!clip_to_bounds(ray, t_min, t_max)) return false;
  if (!box_children_.empty()) return intersect_boxes(ray, t_min, t_max, nullptr);
  for (size_t i = 0; i < surface_children_; ++i) {
    if (!may_hit_child(i, ray, t_min, t_max)) continue;
    const Object& child = *children_[i];
    const bool plain = !child.csg && !child.motion;
    if (kind == CsgKind::union_of) {
      if (plain) {
        if (child.shape->crosses(child.transform.inverse_ray(ray), t_min, t_max)) return true;
        continue;
      }
      // A CSG child answers alike (its inversion composed as Object::intersect_still composes it).
      if (!child.motion) {
        if (child.csg->crosses(ray, t_min, t_max, inverted != child.flags.inverse)) return true;
        continue;
      }
      thread_local SurfaceHit scratch;  // Object::intersect calls no crosses while it is in use
      if (child.intersect(ray, t_min, t_max, scratch, inverted)) return true;
      continue;
    }
    if (plain) {
      thread_local geometry::HitList local;  // used up before the next child's test starts
      local.clear();
      child.shape->all_hits(child.transform.inverse_ray(ray), t_min, t_max, local);
      for (const geometry::LocalHit& l : local)
        if (keeps(kind, i, ray.at(l.t), ray.time)) return true;
      continue;
    }
    ScratchHits scratch;
    std::vector<SurfaceHit>& hits = scratch.list();
    child.all_hits(ray, t_min, t_max, hits, inverted);
    for (const SurfaceHit& h : hits)
      if (keeps(kind, i, h.point, ray.time)) return true;
  }
  return false;
}

void Csg::all_hits(const math::Ray& ray, double t_min, double t_max, std::vector<SurfaceHit>& hits,
                   bool inverted) const {
  const CsgKind kind = surface_kind(inverted);
  const size_t first = hits.size();
  if (!clip_to_bounds(ray, t_min, t_max)) return;
  ScratchHits scratch;
  std::vector<SurfaceHit>& mine = scratch.list();
  for (size_t i = 0; i < surface_children_; ++i) {
    if (!may_hit_child(i, ray, t_min, t_max)) continue;
    const Object& child = *children_[i];
    if (!child.csg && !child.motion) {
      // As in intersect: only the kept hits of a plain shape become world-space hits.
      thread_local geometry::HitList local;  // used up before the next child's test starts
      local.clear();
      child.shape->all_hits(child.transform.inverse_ray(ray), t_min, t_max, local);
      for (const geometry::LocalHit& l : local)
        if (keeps(kind, i, ray.at(l.t), ray.time)) hits.push_back(child.to_world(ray, l));
      continue;
    }
    mine.clear();
    child.all_hits(ray, t_min, t_max, mine, inverted);
    for (const SurfaceHit& h : mine)
      if (keeps(kind, i, h.point, ray.time)) hits.push_back(h);
  }
  std::stable_sort(hits.begin() + static_cast<std::ptrdiff_t>(first), hits.end(),
                   [](const SurfaceHit& a, const SurfaceHit& b) { return a.t < b.t; });
}

bool Csg::inside(const math::Vec3& p, double time) const {
  if (kind_ == CsgKind::intersection) {
    for (const auto& c : children_)
      if (!c->inside(p, time)) return false;
    return true;
  }
  for (const auto& c : children_)
    if (c->inside(p, time)) return true;
  return false;
}

}  // namespace snell::scene
