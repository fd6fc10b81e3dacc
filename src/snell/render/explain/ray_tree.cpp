#include "snell/render/explain/ray_tree.hpp"

#include <stdexcept>

namespace snell::render::explain {

std::string_view to_string(RayEnd end) {
  switch (end) {
    case RayEnd::shaded:
      return "shaded";
    case RayEnd::depth_limit:
      return "depth_limit";
    case RayEnd::adc_bailout:
      return "adc_bailout";
    case RayEnd::miss:
      return "miss";
    case RayEnd::total_internal_reflection:
      return "total_internal_reflection";
    case RayEnd::light_reached:
      return "light_reached";
    case RayEnd::light_blocked:
      return "light_blocked";
    case RayEnd::outside_projection:
      return "outside_projection";
  }
  return "?";
}

std::string_view to_string(scene::RayKind kind) {
  switch (kind) {
    case scene::RayKind::camera:
      return "camera";
    case scene::RayKind::reflection:
      return "reflected";
    case scene::RayKind::refraction:
      return "refracted";
    case scene::RayKind::shadow:
      return "shadow";
  }
  return "?";
}

std::string_view to_string(RayTerm term) {
  switch (term) {
    case RayTerm::ambient:
      return "ambient";
    case RayTerm::emitted:
      return "emitted";
    case RayTerm::diffuse:
      return "diffuse";
    case RayTerm::phong:
      return "phong";
    case RayTerm::specular:
      return "specular";
    case RayTerm::reflected:
      return "reflected";
    case RayTerm::transmitted:
      return "transmitted";
  }
  return "?";
}

void RayTreeRecorder::ray_begin(scene::RayKind kind, const math::Ray& ray, int level, double weight,
                                const scene::Light* light) {
  RayNode node;
  node.kind = kind;
  node.ray = ray;
  node.level = level;
  node.weight = weight;
  node.light = light;
  if (light) node.light_index = static_cast<int>(light - scene_.lights.data());
  // The integrator's own order of tests: depth first, then adc_bailout (whitted.cpp, trace).
  if (kind != scene::RayKind::shadow) {
    if (level > scene_.settings.max_trace_level)
      node.end = RayEnd::depth_limit;
    else if (weight < scene_.settings.adc_bailout)
      node.end = RayEnd::adc_bailout;
  }
  if (open_.empty()) {
    if (root_) throw std::logic_error("RayTreeRecorder records one camera ray");
    root_ = std::make_unique<RayNode>(std::move(node));
    open_.push_back(root_.get());
  } else {
    open_.back()->children.push_back(std::move(node));
    open_.push_back(&open_.back()->children.back());
  }
}

void RayTreeRecorder::ray_hit(const scene::SurfaceHit* hit) {
  RayNode& node = *open_.back();
  node.hit = hit != nullptr;
  node.end = hit ? RayEnd::shaded : RayEnd::miss;
  if (!hit) return;
  node.surface = *hit;
  node.entering = dot(hit->normal, node.ray.direction) < 0;
}

void RayTreeRecorder::shadow_blocker(const scene::SurfaceHit& hit, bool opaque) {
  RayNode& node = *open_.back();
  // Distances from the shaded point, not from the shadow ray's offset origin.
  node.blockers.push_back({hit.object, length(hit.point - node.ray.origin), opaque});
}

void RayTreeRecorder::term(RayTerm term, const math::Color& weight, const math::Color& value) {
  open_.back()->terms.push_back({term, weight, value});
}

void RayTreeRecorder::total_internal_reflection() {
  RayNode& parent = *open_.back();
  RayNode leaf;
  leaf.kind = scene::RayKind::refraction;
  leaf.ray = {parent.surface.point, parent.ray.direction, parent.ray.time};
  leaf.level = parent.level + 1;
  leaf.weight = 0;
  leaf.end = RayEnd::total_internal_reflection;
  parent.children.push_back(std::move(leaf));
}

void RayTreeRecorder::ray_end(const math::Color& result) {
  RayNode& node = *open_.back();
  node.result = result;
  if (node.kind == scene::RayKind::shadow) {
    bool blocked = false;
    for (const Blocker& b : node.blockers) blocked = blocked || b.opaque;
    if (blocked)
      node.end = RayEnd::light_blocked;
    else if (node.blockers.empty() && result.is_black() && node.light &&
             !node.light->projected_through.empty())
      node.end = RayEnd::outside_projection;
    else
      node.end = RayEnd::light_reached;
  }
  open_.pop_back();
}

}  // namespace snell::render::explain
