#include "snell/render/explain/tree_svg.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "snell/render/explain/object_label.hpp"

namespace snell::render::explain {

namespace {

using math::Vec3;

constexpr double kSize = 640;  // the drawing's larger side in SVG units

struct Plan {
  PlanAxes axes;
  double lo_a = 0, lo_b = 0, scale = 1, height = kSize;
  double x(const Vec3& p) const { return (p[axes.across] - lo_a) * scale + 20; }
  /// SVG's y grows downwards; the plan's up axis grows upwards.
  double y(const Vec3& p) const { return height - 20 - (p[axes.up] - lo_b) * scale; }
};

std::string escape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

/// Where a ray's drawn segment ends: its hit, its light, its blocker, or a stretch into the distance.
Vec3 ray_end_point(const RayNode& n, double far) {
  if (n.hit) return n.surface.point;
  if (n.kind == scene::RayKind::shadow) {
    for (const Blocker& b : n.blockers)
      if (b.opaque) return n.ray.origin + n.ray.direction * b.distance;
    if (n.light) return n.light->position;
  }
  if (n.end == RayEnd::total_internal_reflection) return n.ray.origin;
  // Rays never traced (depth limit, adc_bailout) are drawn as short stubs.
  if (n.end == RayEnd::depth_limit || n.end == RayEnd::adc_bailout)
    return n.ray.origin + n.ray.direction * far * 0.05;
  return n.ray.origin + n.ray.direction * far;
}

void gather_points(const RayNode& n, std::vector<Vec3>& points) {
  points.push_back(n.ray.origin);
  if (n.hit) points.push_back(n.surface.point);
  for (const RayNode& c : n.children) gather_points(c, points);
}

const char* ray_colour(scene::RayKind kind) {
  switch (kind) {
    case scene::RayKind::camera:
      return "#222222";
    case scene::RayKind::reflection:
      return "#1f5fd0";
    case scene::RayKind::refraction:
      return "#1a9a3a";
    case scene::RayKind::shadow:
      return "#e08a00";
  }
  return "#000";
}

void draw_rays(std::string& out, const RayNode& n, const Plan& plan, double far) {
  const Vec3 a = n.ray.origin, b = ray_end_point(n, far);
  if (n.end == RayEnd::total_internal_reflection) {
    out += fmt::format(R"(<text x="{:.1f}" y="{:.1f}" font-size="11" fill="#b00">TIR</text>)"
                       "\n",
                       plan.x(a) + 4, plan.y(a) + 12);
  } else {
    const bool blocked = n.end == RayEnd::light_blocked;
    const bool stub = n.end == RayEnd::depth_limit || n.end == RayEnd::adc_bailout;
    out += fmt::format(
        R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}" stroke-width="1.5"{}>)"
        "<title>{} ray, level {}: {}</title></line>\n",
        plan.x(a), plan.y(a), plan.x(b), plan.y(b),
        blocked ? "#b00000" : (stub ? "#999999" : ray_colour(n.kind)),
        n.kind == scene::RayKind::shadow || stub ? R"( stroke-dasharray="5,3")" : "", to_string(n.kind),
        n.level, to_string(n.end));
  }
  if (n.hit)
    out += fmt::format(R"(<circle cx="{:.1f}" cy="{:.1f}" r="3" fill="{}"/>)"
                       "\n",
                       plan.x(b), plan.y(b), ray_colour(n.kind));
  for (const RayNode& c : n.children) draw_rays(out, c, plan, far);
}

}  // namespace

PlanAxes plan_axes(const Vec3& d) {
  int dropped = 1;
  for (const int a : {0, 2})
    if (std::fabs(d[a]) < std::fabs(d[dropped]) - 1e-12) dropped = a;
  const int across = dropped == 0 ? 2 : 0;
  const int up = dropped == 2 ? 1 : (dropped == 0 ? 1 : 2);
  return {across, up, dropped};
}

std::string tree_svg(const PixelExplanation& e, const scene::Scene& scene) {
  const Vec3 camera = scene.camera.location;
  const Vec3 direction = e.tree ? e.tree->ray.direction : Vec3(0, 0, 1);
  Plan plan;
  plan.axes = plan_axes(direction);
  // The plan spans the camera, the lights and every point of the ray tree.
  std::vector<Vec3> points{camera};
  for (const scene::Light& l : scene.lights) points.push_back(l.position);
  if (e.tree) gather_points(*e.tree, points);
  double lo_a = 1e300, hi_a = -1e300, lo_b = 1e300, hi_b = -1e300;
  for (const Vec3& p : points) {
    lo_a = std::min(lo_a, p[plan.axes.across]), hi_a = std::max(hi_a, p[plan.axes.across]);
    lo_b = std::min(lo_b, p[plan.axes.up]), hi_b = std::max(hi_b, p[plan.axes.up]);
  }
  const double pad = 0.1 * std::max({hi_a - lo_a, hi_b - lo_b, 1.0});
  lo_a -= pad, hi_a += pad, lo_b -= pad, hi_b += pad;
  const double span = std::max(hi_a - lo_a, hi_b - lo_b);
  plan.scale = kSize / span;
  plan.lo_a = lo_a, plan.lo_b = lo_b;
  const double width = (hi_a - lo_a) * plan.scale + 40;
  plan.height = (hi_b - lo_b) * plan.scale + 40;
  const double far = span;  // misses are drawn across the whole plan

  const char axis_names[] = "xyz";
  std::string out = fmt::format(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="{:.0f}" height="{:.0f}" viewBox="0 0 {:.0f} {:.0f}">)"
      "\n<rect width=\"100%\" height=\"100%\" fill=\"#fbfbf7\"/>\n"
      R"(<text x="6" y="14" font-size="12" font-family="sans-serif">pixel {},{} sample {}: plan {} across, {} up</text>)"
      "\n",
      width, plan.height, width, plan.height, e.x, e.y, e.sample, axis_names[plan.axes.across],
      axis_names[plan.axes.up]);
  out += "<g font-family=\"sans-serif\" font-size=\"11\">\n";
  // Object outlines from their bounds: a sphere as a circle (its box's inscribed ellipse), others as boxes.
  for (const auto& object : scene.objects) {
    const math::Bounds3 b = object->world_bounds();
    if (!b.is_finite()) continue;
    const double x0 = plan.x(b.lo), x1 = plan.x(b.hi), y0 = plan.y(b.hi), y1 = plan.y(b.lo);
    const std::string label = escape(object_label(*object));
    if (object_kind(*object) == "sphere")
      out += fmt::format(
          R"(<ellipse cx="{:.1f}" cy="{:.1f}" rx="{:.1f}" ry="{:.1f}" fill="#dde8f0" stroke="#667"><title>{}</title></ellipse>)"
          "\n",
          (x0 + x1) / 2, (y0 + y1) / 2, (x1 - x0) / 2, (y1 - y0) / 2, label);
    else
      out += fmt::format(
          R"(<rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" fill="#e8e4dc" stroke="#776"><title>{}</title></rect>)"
          "\n",
          x0, y0, x1 - x0, y1 - y0, label);
    if (!object->name.empty())
      out += fmt::format(R"(<text x="{:.1f}" y="{:.1f}" fill="#445">{}</text>)"
                         "\n",
                         x0, y0 - 3, escape(object->name));
  }
  if (e.tree) draw_rays(out, *e.tree, plan, far);
  out += fmt::format(
      R"(<path d="M {:.1f} {:.1f} l -7 12 l 14 0 z" fill="#222"/><text x="{:.1f}" y="{:.1f}">camera</text>)"
      "\n",
      plan.x(camera), plan.y(camera) - 6, plan.x(camera) + 9, plan.y(camera) + 8);
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Vec3 p = scene.lights[i].position;
    out += fmt::format(
        R"(<circle cx="{:.1f}" cy="{:.1f}" r="6" fill="#ffd21f" stroke="#a80"/><text x="{:.1f}" y="{:.1f}">light {}</text>)"
        "\n",
        plan.x(p), plan.y(p), plan.x(p) + 9, plan.y(p) + 4, i + 1);
  }
  out += "</g>\n";
  // Key.
  const double ky = plan.height - 8;
  out += fmt::format(
      R"(<g font-family="sans-serif" font-size="11"><text x="6" y="{0:.0f}" fill="#222222">camera</text><text x="56" y="{0:.0f}" fill="#1f5fd0">reflected</text><text x="118" y="{0:.0f}" fill="#1a9a3a">refracted</text><text x="182" y="{0:.0f}" fill="#e08a00">shadow</text><text x="230" y="{0:.0f}" fill="#b00000">blocked</text></g>)"
      "\n</svg>\n",
      ky);
  return out;
}

}  // namespace snell::render::explain
