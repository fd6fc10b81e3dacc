#include "snell/render/shadow_media.hpp"

#include <vector>

#include "snell/render/media.hpp"

namespace snell::render {

bool ShadowMedia::has_media(const scene::Object& solid) {
  return solid.interior && !solid.interior->media.empty();
}

void ShadowMedia::cross(const scene::Object& solid, double t, const math::Vec3& outward) {
  if (dot(outward, ray_.direction) < 0) {  // going in
    if (open_count_ < open_.size()) open_[open_count_++] = {&solid, t};
    return;
  }
  for (size_t i = 0; i < open_count_; ++i) {
    if (open_[i].solid != &solid) continue;
    thin(solid, open_[i].t0, t);
    open_[i] = open_[--open_count_];
    return;
  }
  thin(solid, 0, t);  // it held the ray's start
}

void ShadowMedia::thin(const scene::Object& solid, double t0, double t1) {
  if (!(t1 > t0)) return;
  std::vector<const material::Media*> media;
  for (const material::Media& m : solid.interior->media) media.push_back(&m);
  const math::Ray stretch{ray_.at(t0), ray_.direction, ray_.time};
  through_ *= media_transmittance(media, stretch, t1 - t0);
}

math::Color ShadowMedia::transmittance(double end) const {
  ShadowMedia rest = *this;
  for (size_t i = 0; i < open_count_; ++i) rest.thin(*open_[i].solid, open_[i].t0, end);
  return rest.through_;
}

}  // namespace snell::render
