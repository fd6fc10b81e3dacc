#include "snell/render/explain/layer_picture.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace snell::render::explain {

namespace {

constexpr int kLegendHeight = 44;
const Rgb8 kInk{235, 235, 235};
const Rgb8 kPaper{24, 24, 24};

std::string number(double v) {
  if (std::fabs(v) >= 1e5 || (v != 0 && std::fabs(v) < 1e-2)) return fmt::format("{:.2e}", v);
  return fmt::format("{:.4g}", v);
}

/// The picture with room for the legend, and the title written in it.
Picture with_legend(int width, int height, const std::string& title) {
  Picture p(width, height + kLegendHeight, kPaper);
  p.text(4, height + 4, title, kInk, Picture::text_width(title) + 8 > width ? 1 : 2);
  return p;
}

}  // namespace

math::Color ramp_color(double t) {
  static const math::Color stops[] = {
      {0.05, 0.03, 0.30}, {0.45, 0.10, 0.55}, {0.85, 0.25, 0.25}, {0.98, 0.60, 0.10}, {1.00, 1.00, 0.75}};
  if (!(t > 0)) return stops[0];
  if (t >= 1) return stops[4];
  const double s = t * 4;
  const int i = static_cast<int>(s);
  const double f = s - i;
  return stops[i] * (1 - f) + stops[i + 1] * f;
}

math::Color id_color(int id) {
  if (id < 0) return {0, 0, 0};
  // Hues spread by the golden angle, so neighbouring ids differ; two brightness levels for more contrast.
  const double hue = std::fmod(id * 0.618033988749895, 1.0) * 6;
  const double value = id % 2 ? 0.75 : 1.0;
  const int sector = static_cast<int>(hue);
  const double f = hue - sector;
  const double s = 0.7, p = value * (1 - s), q = value * (1 - s * f), t = value * (1 - s * (1 - f));
  switch (sector % 6) {
    case 0:
      return {value, t, p};
    case 1:
      return {q, value, p};
    case 2:
      return {p, value, t};
    case 3:
      return {p, q, value};
    case 4:
      return {t, p, value};
    default:
      return {value, p, q};
  }
}

Picture heatmap_picture(const std::string& title, const std::vector<float>& values, int width, int height) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const float v : values)
    if (std::isfinite(v)) lo = std::min(lo, double(v)), hi = std::max(hi, double(v));
  if (!(lo <= hi)) lo = hi = 0;
  const double span = hi > lo ? hi - lo : 1;
  Picture p = with_legend(width, height, title);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float v = values[static_cast<size_t>(y) * width + x];
      p.set(x, y, std::isfinite(v) ? to_rgb8(ramp_color((v - lo) / span)) : Rgb8{});
    }
  // The scale bar: the ramp from the minimum (left) to the maximum (right), with ticks and numbers.
  const int x0 = 4, x1 = std::max(width - 4, x0 + 1), bar = height + 17;
  for (int x = x0; x < x1; ++x)
    p.fill_rect(x, bar, x + 1, bar + 8, to_rgb8(ramp_color(double(x - x0) / (x1 - x0 - 1))));
  const std::string low = number(lo), mid = number((lo + hi) / 2), high = number(hi);
  p.fill_rect(x0, bar + 8, x0 + 1, bar + 11, kInk);
  p.fill_rect(x1 - 1, bar + 8, x1, bar + 11, kInk);
  p.fill_rect((x0 + x1) / 2, bar + 8, (x0 + x1) / 2 + 1, bar + 11, kInk);
  p.text(x0, bar + 13, low, kInk);
  p.text((x0 + x1 - Picture::text_width(mid)) / 2, bar + 13, mid, kInk);
  p.text(x1 - Picture::text_width(high), bar + 13, high, kInk);
  return p;
}

std::vector<float> query_cost(const Layer& cost) {
  std::vector<float> v(cost.values.size() / 3);
  for (size_t i = 0; i < v.size(); ++i) v[i] = cost.values[i * 3] + cost.values[i * 3 + 1];
  return v;
}

Picture layer_picture(const Layer& layer, int width, int height) {
  const size_t nc = layer.channels.size();
  const size_t n = static_cast<size_t>(width) * height;
  if (layer.name == "cost")
    return heatmap_picture("COST: NODES+OBJECTS TESTED", query_cost(layer), width, height);
  if (nc == 1 && !layer.is_id) {
    const std::map<std::string, std::string> titles{
        {"depth", "DEPTH (DISTANCE)"}, {"samples", "SAMPLES PER PIXEL"}, {"time", "TIME (NS)"}};
    const auto it = titles.find(layer.name);
    return heatmap_picture(it != titles.end() ? it->second : layer.name, layer.values, width, height);
  }
  if (layer.is_id) {
    Picture p = with_legend(width, height, layer.name + " ID");
    std::vector<int> seen;
    for (size_t i = 0; i < n; ++i) {
      const int id = static_cast<int>(layer.values[i]);
      p.set(static_cast<int>(i % width), static_cast<int>(i / width), to_rgb8(id_color(id)));
      if (id >= 0 && std::find(seen.begin(), seen.end(), id) == seen.end()) seen.push_back(id);
    }
    // The key: a swatch and the number of each id in the picture, as many as fit.
    std::sort(seen.begin(), seen.end());
    int x = 4;
    for (const int id : seen) {
      const std::string label = std::to_string(id);
      const int w = 12 + Picture::text_width(label) + 4;
      if (x + w > width) break;
      p.fill_rect(x, height + 20, x + 10, height + 30, to_rgb8(id_color(id)));
      x = p.text(x + 12, height + 20, label, kInk) + 4;
    }
    return p;
  }
  // Vectors: each channel's range mapped to 0..1 (normals from -1..1), shown as red, green, blue.
  std::vector<double> lo(nc, -1), hi(nc, 1);
  if (layer.name != "normal")
    for (size_t c = 0; c < nc; ++c) {
      lo[c] = std::numeric_limits<double>::infinity(), hi[c] = -lo[c];
      for (size_t i = 0; i < n; ++i) {
        const double v = layer.values[i * nc + c];
        if (std::isfinite(v)) lo[c] = std::min(lo[c], v), hi[c] = std::max(hi[c], v);
      }
      if (layer.name == "albedo") lo[c] = 0, hi[c] = std::max(hi[c], 1.0);
    }
  Picture p = with_legend(width, height, layer.name);
  for (size_t i = 0; i < n; ++i) {
    double rgb[3] = {0, 0, 0};
    for (size_t c = 0; c < nc && c < 3; ++c) {
      const double span = hi[c] > lo[c] ? hi[c] - lo[c] : 1;
      rgb[c] = (layer.values[i * nc + c] - lo[c]) / span;
    }
    p.set(static_cast<int>(i % width), static_cast<int>(i / width), to_rgb8({rgb[0], rgb[1], rgb[2]}));
  }
  std::string key;
  for (size_t c = 0; c < nc && c < 3; ++c)
    key += fmt::format("{}{}={}", c ? " " : "", layer.channels[c], "RGB"[c]);
  p.text(4, height + 20, key, kInk);
  return p;
}

}  // namespace snell::render::explain
