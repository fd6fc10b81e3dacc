#include "snell/render/explain/tree_text.hpp"

#include <fmt/core.h>

#include "snell/render/explain/object_label.hpp"

namespace snell::render::explain {

namespace {

std::string vec(const math::Vec3& v) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", v.x, v.y, v.z);
}
std::string rgb(const math::Color& c) {
  return fmt::format("({:.4f}, {:.4f}, {:.4f})", c.r, c.g, c.b);
}

std::string light_label(const RayNode& node) {
  if (!node.light) return "a light";
  return fmt::format("light {} at {}", node.light_index + 1, vec(node.light->position));
}

/// Why the ray ended, in words.
std::string ending(const RayNode& node, const scene::Scene& scene) {
  switch (node.end) {
    case RayEnd::shaded:
      return fmt::format("shaded: colour {}", rgb(node.result));
    case RayEnd::depth_limit:
      return fmt::format("not traced: level {} is past max_trace_level {}", node.level,
                         scene.settings.max_trace_level);
    case RayEnd::adc_bailout:
      return fmt::format("not traced: weight {:.4g} is below adc_bailout {:.4g}", node.weight,
                         scene.settings.adc_bailout);
    case RayEnd::miss:
      return fmt::format("missed everything: background {}", rgb(node.result));
    case RayEnd::total_internal_reflection:
      return "total internal reflection: no refracted ray (the reflected ray takes its place)";
    case RayEnd::light_reached:
      return fmt::format("reached {}: light {}", light_label(node), rgb(node.result));
    case RayEnd::light_blocked: {
      for (const Blocker& b : node.blockers)
        if (b.opaque)
          return fmt::format("blocked by {} at distance {:.6g}", object_label(*b.object), b.distance);
      return "blocked";
    }
    case RayEnd::outside_projection:
      return "the light's projected_through object is not on the way";
  }
  return "";
}

void write_node(std::string& out, const RayNode& node, const scene::Scene& scene, int depth) {
  const std::string pad(static_cast<size_t>(depth) * 4, ' ');
  const std::string body = pad + "  ";
  if (node.kind == scene::RayKind::shadow)
    out += fmt::format("{}- shadow ray to {}\n", pad, light_label(node));
  else
    out += fmt::format("{}- {} ray, level {}, weight {:.4g}\n", pad, to_string(node.kind), node.level,
                       node.weight);
  if (node.end != RayEnd::total_internal_reflection)
    out += fmt::format("{}origin {}  direction {}\n", body, vec(node.ray.origin), vec(node.ray.direction));
  if (node.hit) {
    out += fmt::format("{}hit {} at distance {:.6g}, {}\n", body, object_label(*node.surface.object),
                       node.surface.t, node.entering ? "entering" : "leaving");
    if (node.surface.solid && node.surface.solid != node.surface.object)
      out += fmt::format("{}  (part of {})\n", body, object_label(*node.surface.solid));
    out += fmt::format("{}point {}  normal {}\n", body, vec(node.surface.point), vec(node.surface.normal));
  }
  for (const Blocker& b : node.blockers)
    if (!b.opaque)
      out += fmt::format("{}passes through {} at distance {:.6g} (transparent, tints the light)\n", body,
                         object_label(*b.object), b.distance);
  for (const TermRecord& t : node.terms)
    out += fmt::format("{}+ {:<11} {} = weight {}\n", body, to_string(t.term), rgb(t.value), rgb(t.weight));
  out += fmt::format("{}{}\n", body, ending(node, scene));
  for (const RayNode& child : node.children) write_node(out, child, scene, depth + 1);
}

}  // namespace

std::string tree_text(const PixelExplanation& e, const scene::Scene& scene) {
  std::string out = fmt::format("pixel {},{} sample {} at image point ({:.6g}, {:.6g}): colour {}\n", e.x,
                                e.y, e.sample, e.position.u, e.position.v, rgb(e.colour));
  if (!e.tree) return out + "  the camera has no ray here (black)\n";
  write_node(out, *e.tree, scene, 0);
  return out;
}

}  // namespace snell::render::explain
