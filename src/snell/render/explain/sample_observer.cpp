#include "snell/render/explain/sample_observer.hpp"

#include <fmt/core.h>

namespace snell::render::explain {

std::vector<std::string> bounce_names(int n) {
  std::vector<std::string> names{"direct"};
  for (int d = 1; d <= n; ++d) {
    names.push_back(fmt::format("reflection{}", d));
    names.push_back(fmt::format("refraction{}", d));
  }
  names.push_back("deeper");
  return names;
}

SampleObserver::SampleObserver(int split_depth)
    : split_depth_(split_depth),
      bucket_count_(split_depth < 0 ? 0 : 2 * static_cast<size_t>(split_depth) + 2) {}

void SampleObserver::reset() {
  first_hit_found_ = false;
  open_.clear();
  has_pending_ = false;
  done_.assign(bucket_count_, math::Color{0, 0, 0});
}

int SampleObserver::bucket_of(scene::RayKind kind, int level) const {
  const int depth = level - 1;
  if (depth <= 0) return 0;
  if (depth > split_depth_) return static_cast<int>(bucket_count_) - 1;
  return 2 * depth - 1 + (kind == scene::RayKind::refraction ? 1 : 0);
}

void SampleObserver::ray_begin(scene::RayKind kind, const math::Ray& ray, int level, double,
                               const scene::Light*) {
  if (kind == scene::RayKind::camera && open_.empty()) camera_ray_ = ray;
  Frame f;
  f.shadow = kind == scene::RayKind::shadow;
  if (!f.shadow && bucket_count_ > 0) {
    f.bucket = bucket_of(kind, level);
    f.buckets.assign(bucket_count_, math::Color{0, 0, 0});
  }
  f.missed = false;
  open_.push_back(std::move(f));
}

void SampleObserver::ray_hit(const scene::SurfaceHit* hit) {
  if (open_.size() == 1 && hit) {
    first_hit_found_ = true;
    first_hit_ = *hit;
  }
  open_.back().missed = hit == nullptr;
}

void SampleObserver::term(RayTerm term, const math::Color& weight, const math::Color& value) {
  if (bucket_count_ == 0) return;
  Frame& f = open_.back();
  if (term == RayTerm::reflected || term == RayTerm::transmitted) {
    // The child ray that just ended brought this term's light: its buckets, scaled by the term's weight.
    if (has_pending_)
      for (size_t i = 0; i < bucket_count_; ++i) f.buckets[i] += weight * pending_.buckets[i];
    has_pending_ = false;
    return;
  }
  f.buckets[static_cast<size_t>(f.bucket)] += value;
}

void SampleObserver::ray_end(const math::Color& result) {
  Frame f = std::move(open_.back());
  open_.pop_back();
  if (f.shadow || bucket_count_ == 0) return;
  if (f.missed) f.buckets[static_cast<size_t>(f.bucket)] += result;
  if (open_.empty()) {
    done_ = std::move(f.buckets);
    return;
  }
  pending_ = std::move(f);
  has_pending_ = true;
}

}  // namespace snell::render::explain
