#include "snell/scene/csg.hpp"

#include <algorithm>
#include <stdexcept>

#include "snell/scene/object.hpp"

namespace snell::scene {

Csg::Csg(CsgKind kind, std::vector<std::shared_ptr<const Object>> children, size_t surface_children)
    : kind_(kind), children_(std::move(children)) {
  if (children_.empty()) throw std::invalid_argument("a CSG object needs at least one child");
  for (const auto& c : children_)
    if (!c) throw std::invalid_argument("a CSG child is null");
  surface_children_ = surface_children == 0 ? children_.size() : std::min(surface_children, children_.size());
  if (kind_ == CsgKind::intersection) {
    solid_bounds_ = math::Bounds3::infinite();
    for (const auto& c : children_) solid_bounds_ = solid_bounds_.intersection(c->solid_bounds());
    for (size_t i = 0; i < surface_children_; ++i) bounds_.unite(children_[i]->world_bounds());
    bounds_ = bounds_.intersection(solid_bounds_);
  } else {
    for (const auto& c : children_) {
      bounds_.unite(c->world_bounds());
      solid_bounds_.unite(c->solid_bounds());
    }
  }
}

bool Csg::keeps(size_t i, const math::Vec3& p, double time) const {
  switch (kind_) {
    case CsgKind::union_of:
      return true;
    case CsgKind::merge:
      for (size_t j = 0; j < children_.size(); ++j)
        if (j != i && children_[j]->inside(p, time)) return false;
      return true;
    case CsgKind::intersection:
      for (size_t j = 0; j < children_.size(); ++j)
        if (j != i && !children_[j]->inside(p, time)) return false;
      return true;
  }
  return true;
}

bool Csg::intersect(const math::Ray& ray, double t_min, double t_max, SurfaceHit& hit) const {
  bool found = false;
  std::vector<SurfaceHit> hits;
  for (size_t i = 0; i < surface_children_; ++i) {
    const Object& child = *children_[i];
    if (kind_ == CsgKind::union_of) {
      if (child.intersect(ray, t_min, t_max, hit)) {
        t_max = hit.t;
        found = true;
      }
      continue;
    }
    hits.clear();
    child.all_hits(ray, t_min, t_max, hits);
    for (const SurfaceHit& h : hits) {
      if (!keeps(i, h.point, ray.time)) continue;
      hit = h;
      t_max = h.t;
      found = true;
      break;  // hits come in increasing t: the first kept one is this child's nearest
    }
  }
  return found;
}

void Csg::all_hits(const math::Ray& ray, double t_min, double t_max, std::vector<SurfaceHit>& hits) const {
  const size_t first = hits.size();
  std::vector<SurfaceHit> mine;
  for (size_t i = 0; i < surface_children_; ++i) {
    mine.clear();
    children_[i]->all_hits(ray, t_min, t_max, mine);
    for (const SurfaceHit& h : mine)
      if (keeps(i, h.point, ray.time)) hits.push_back(h);
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
