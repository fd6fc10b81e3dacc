#include "snell/render/explain/tree_json.hpp"

#include <fmt/core.h>

#include <cmath>

#include "snell/render/explain/object_label.hpp"

namespace snell::render::explain {

namespace {

/// Shortest text that reads back to the same double; JSON has no infinities, so those become huge.
std::string num(double v) {
  if (!std::isfinite(v)) v = std::isnan(v) ? 0.0 : std::copysign(1e300, v);
  return fmt::format("{}", v);
}
std::string vec(const math::Vec3& v) {
  return fmt::format("[{}, {}, {}]", num(v.x), num(v.y), num(v.z));
}
std::string rgb(const math::Color& c) {
  return fmt::format("[{}, {}, {}]", num(c.r), num(c.g), num(c.b));
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\')
      out += fmt::format("\\{}", c);
    else if (static_cast<unsigned char>(c) < 0x20)
      out += fmt::format("\\u{:04x}", static_cast<int>(c));
    else
      out += c;
  }
  return out + "\"";
}

std::string object_json(const scene::Object& o) {
  return fmt::format(R"({{"kind": {}, "name": {}, "location": {}}})", quoted(object_kind(o)),
                     o.name.empty() ? "null" : quoted(o.name), quoted(o.where.to_string()));
}

void write_ray(std::string& out, const RayNode& node, const std::string& pad) {
  const std::string in = pad + "  ";
  out += "{\n";
  out += fmt::format("{}\"kind\": \"{}\",\n", in, to_string(node.kind));
  out += fmt::format("{}\"level\": {},\n{}\"weight\": {},\n", in, node.level, in, num(node.weight));
  out += fmt::format("{}\"origin\": {},\n{}\"direction\": {},\n", in, vec(node.ray.origin), in,
                     vec(node.ray.direction));
  if (node.light)
    out += fmt::format("{}\"light\": {{\"index\": {}, \"position\": {}}},\n", in, node.light_index,
                       vec(node.light->position));
  if (node.hit) {
    const scene::SurfaceHit& h = node.surface;
    out += fmt::format(
        "{}\"hit\": {{\"object\": {}, \"solid\": {}, \"distance\": {}, \"point\": {}, \"normal\": {}, "
        "\"entering\": {}}},\n",
        in, object_json(*h.object), h.solid ? object_json(*h.solid) : "null", num(h.t), vec(h.point),
        vec(h.normal), node.entering ? "true" : "false");
  } else {
    out += fmt::format("{}\"hit\": null,\n", in);
  }
  out += fmt::format("{}\"blockers\": [", in);
  for (size_t i = 0; i < node.blockers.size(); ++i)
    out += fmt::format("{}{{\"object\": {}, \"distance\": {}, \"opaque\": {}}}", i ? ", " : "",
                       object_json(*node.blockers[i].object), num(node.blockers[i].distance),
                       node.blockers[i].opaque ? "true" : "false");
  out += "],\n";
  out += fmt::format("{}\"terms\": [", in);
  for (size_t i = 0; i < node.terms.size(); ++i)
    out += fmt::format("{}{{\"term\": \"{}\", \"weight\": {}, \"value\": {}}}", i ? ", " : "",
                       to_string(node.terms[i].term), rgb(node.terms[i].weight), rgb(node.terms[i].value));
  out += "],\n";
  out +=
      fmt::format("{}\"end\": \"{}\",\n{}\"colour\": {},\n", in, to_string(node.end), in, rgb(node.result));
  out += fmt::format("{}\"children\": [", in);
  for (size_t i = 0; i < node.children.size(); ++i) {
    out += i ? ", " : "";
    write_ray(out, node.children[i], in);
  }
  out += fmt::format("]\n{}}}", pad);
}

}  // namespace

std::string tree_json(const PixelExplanation& e, const std::string& scene_file) {
  std::string out = "{\n";
  out += fmt::format("  \"scene\": {},\n  \"pixel\": [{}, {}],\n  \"sample\": {},\n", quoted(scene_file), e.x,
                     e.y, e.sample);
  out += fmt::format("  \"image_point\": [{}, {}],\n  \"colour\": {},\n  \"ray\": ", num(e.position.u),
                     num(e.position.v), rgb(e.colour));
  if (e.tree)
    write_ray(out, *e.tree, "  ");
  else
    out += "null";
  return out + "\n}\n";
}

}  // namespace snell::render::explain
