#include "snell/material/texture.hpp"

#include <algorithm>
#include <vector>

namespace snell::material {

std::shared_ptr<const Texture> Texture::default_texture() {
  static const auto texture = [] {
    auto t = std::make_shared<Texture>();
    t->pigment = std::make_shared<SolidPigment>(Rgbft{});
    return std::shared_ptr<const Texture>(t);
  }();
  return texture;
}

std::shared_ptr<const Texture> Texture::transformed(const math::Transform& t) const {
  auto copy = std::make_shared<Texture>(*this);
  copy->move(t);
  return copy;
}

void Texture::move(const math::Transform& t) {
  transform = t * transform;
  if (below) below = below->transformed(t);
  for (auto& entry : averaged) entry.second = entry.second->transformed(t);
}

std::shared_ptr<const Texture> Texture::layered(const std::shared_ptr<const Texture>& top,
                                                std::shared_ptr<const Texture> bottom) {
  if (!top) return bottom;
  auto copy = std::make_shared<Texture>(*top);
  copy->below = copy->below ? layered(copy->below, std::move(bottom)) : std::move(bottom);
  return copy;
}

namespace {

/// The hit as a layer's patterns see it: the point in the layer's texture space.
PatternPoint layer_point(const Texture& layer, const math::Vec3& world_point, const math::Vec3& world_normal,
                         const math::Vec2& uv, const math::Vec3& ray_direction = {}) {
  PatternPoint pp;
  pp.p = layer.transform.inverse_point(world_point);
  pp.world_normal = world_normal;
  pp.uv = uv;
  pp.ray_direction = ray_direction;
  return pp;
}

Rgbft layer_pigment(const Texture& layer, const math::Vec3& world_point, const math::Vec3& world_normal,
                    const math::Vec2& uv, const math::Vec3& ray_direction) {
  if (layer.selector) {
    // The entries see the point in the mapped texture's space as their "world".
    const PatternPoint pp = layer_point(layer, world_point, world_normal, uv, ray_direction);
    const TextureSelector::Choice c = layer.selector->at(pp);
    const Rgbft first = c.first->pigment_at(c.point, world_normal, uv, ray_direction);
    if (!c.second) return first;
    return lerp(first, c.second->pigment_at(c.point, world_normal, uv, ray_direction), c.weight);
  }
  if (!layer.pigment) return {};
  if (layer.pigment->is_constant()) return layer.pigment->at({});
  return layer.pigment->at(layer_point(layer, world_point, world_normal, uv, ray_direction));
}

}  // namespace

math::Vec3 Texture::shading_normal(const math::Vec3& world_point, const math::Vec3& world_normal,
                                   const math::Vec2& uv) const {
  for (const Texture* layer = this; layer; layer = layer->below.get())
    if (layer->normal || layer->selector) return layer->own_shading_normal(world_point, world_normal, uv);
  return world_normal;
}

Rgbft Texture::own_pigment_at(const math::Vec3& world_point, const math::Vec3& world_normal,
                              const math::Vec2& uv, const math::Vec3& ray_direction) const {
  return layer_pigment(*this, world_point, world_normal, uv, ray_direction);
}

math::Vec3 Texture::own_shading_normal(const math::Vec3& world_point, const math::Vec3& world_normal,
                                       const math::Vec2& uv) const {
  if (!normal && !selector) return world_normal;
  const math::Vec3 local = normalize(transform.inverse_normal(world_normal));
  const PatternPoint pp = layer_point(*this, world_point, world_normal, uv);
  math::Vec3 bent;
  if (selector) {
    // Each entry bends the normal in its own way; POV-Ray blends the results like colours.
    const TextureSelector::Choice c = selector->at(pp);
    bent = c.first->shading_normal(c.point, local, uv);
    if (c.second) bent = bent * (1 - c.weight) + c.second->shading_normal(c.point, local, uv) * c.weight;
  } else {
    bent = normal->perturb(local, pp);
  }
  bent = transform.normal(bent);
  return dot(bent, bent) > 0 ? normalize(bent) : world_normal;
}

const Finish& Texture::finish_at(const math::Vec3& world_point, const math::Vec3& world_normal,
                                 const math::Vec3& ray_direction) const {
  if (!selector) return finish;
  // The same pattern point as the pigment's, normal and ray included: a slope map must pick its finish
  // where it picks its colour.
  const PatternPoint pp = layer_point(*this, world_point, world_normal, {}, ray_direction);
  const TextureSelector::Choice c = selector->at(pp);
  const Texture* dominant = c.second && c.weight > 0.5 ? c.second : c.first;
  return dominant->finish_at(c.point, world_normal, ray_direction);
}

bool Texture::map_entries_at(const math::Vec3& world_point, const math::Vec3& world_normal,
                             const math::Vec3& facing_normal, const math::Vec2& uv,
                             const math::Vec3& ray_direction, MapEntry (&out)[2]) const {
  if (!selector) return false;
  const PatternPoint pp = layer_point(*this, world_point, world_normal, uv, ray_direction);
  const TextureSelector::Choice c = selector->at(pp);
  if (!c.second) return false;
  // The entries live in the mapped texture's space: bend the normal there and bring it back.
  const math::Vec3 local = normalize(transform.inverse_normal(facing_normal));
  const Texture* entries[2] = {c.first, c.second};
  const double weights[2] = {1 - c.weight, c.weight};
  for (int i = 0; i < 2; ++i) {
    const Texture& e = *entries[i];
    out[i].pigment = e.pigment_at(c.point, world_normal, uv, ray_direction);
    out[i].finish = &e.finish_at(c.point, world_normal, ray_direction);
    const math::Vec3 bent = transform.normal(e.shading_normal(c.point, local, uv));
    out[i].normal = dot(bent, bent) > 0 ? normalize(bent) : facing_normal;
    out[i].weight = weights[i];
  }
  return true;
}

bool Texture::may_transmit() const {
  for (const Texture* layer = this; layer; layer = layer->below.get())
    if (!layer->selector && layer->pigment && !layer->pigment->may_transmit()) return false;
  return true;
}

Rgbft Texture::pigment_at(const math::Vec3& world_point, const math::Vec3& world_normal, const math::Vec2& uv,
                          const math::Vec3& ray_direction) const {
  if (!below) return layer_pigment(*this, world_point, world_normal, uv, ray_direction);
  // Front to back, as POV-Ray composites layers (lighting.cpp, ComputeLightedTexture): each layer adds
  // its opaque part, weighted by what the layers above let through, and passes on its filter/transmit.
  math::Color color(0);
  math::Color through(1);
  for (const Texture* layer = this; layer; layer = layer->below.get()) {
    const Rgbft c = layer_pigment(*layer, world_point, world_normal, uv, ray_direction);
    const double opaque = std::max(0.0, 1 - c.filter - c.transmit);
    color += through * c.rgb * opaque;
    through *= c.rgb * c.filter + math::Color(c.transmit);
    if (std::max(through.r, std::max(through.g, through.b)) <= 0) break;
  }
  // Back to one colour: transmit is the untinted part of what passes, filter the tinted rest. With an
  // opaque bottom layer (the usual case) nothing passes and this is exact; otherwise the tint of light
  // passing through the stack is approximated by one filter amount.
  Rgbft out;
  out.transmit = std::clamp(std::min(through.r, std::min(through.g, through.b)), 0.0, 1.0);
  const math::Color tinted = through - math::Color(out.transmit);
  if (out.transmit >= 1) return out;
  out.rgb = (color + tinted) * (1 / (1 - out.transmit));
  const double rgb_sum = out.rgb.r + out.rgb.g + out.rgb.b;
  out.filter = rgb_sum > 0 ? (tinted.r + tinted.g + tinted.b) / rgb_sum : 0;
  return out;
}

}  // namespace snell::material
