#include "snell/texture/pattern_normal.hpp"

#include <algorithm>
#include <stdexcept>

#include "snell/geometry/surface_uv.hpp"
#include "snell/texture/map_bracket.hpp"

namespace snell::texture {

namespace {

/// Corners of a regular tetrahedron on the unit sphere; their outer products sum to 4/3 times the identity,
/// so sum_i f(q + h v_i) v_i = (4/3) h grad f + O(h^2). Oriented as POV-Ray's (normal.cpp, Pyramid_Vect:
/// one corner on +y, one in the x-y plane): the O(h^2) error depends on the orientation, and with patterns
/// as fine as the accuracy (granite at scale 0.1) another orientation gives visibly other bumps.
const Vec3 kTetrahedron[4] = {Vec3{0.94280904158206337, -1.0 / 3, 0},
                              Vec3{-0.47140452079103168, -1.0 / 3, 0.81649658092772604},
                              Vec3{-0.47140452079103168, -1.0 / 3, -0.81649658092772604}, Vec3{0, 1, 0}};

/// POV-Ray scales the gradient bending by 5 * 0.02 per unit bump_size (normal.cpp's "fudge factor"), so
/// that `bump_size` means the same for every pattern; with the tetrahedron's 4/3 this is 0.1333 grad.
constexpr double kGradientScale = 5 * 0.02;

/// A normal through the transforms written in a normal block, into pattern space (or back out).
Vec3 to_pattern_space(const WarpList& warps, Vec3 n) {
  for (auto it = warps.warps().rbegin(); it != warps.warps().rend(); ++it)
    if (const auto* t = dynamic_cast<const TransformWarp*>(it->get())) n = t->transform().inverse_normal(n);
  return normalize(n);
}

Vec3 from_pattern_space(const WarpList& warps, Vec3 n) {
  for (const auto& w : warps.warps())
    if (const auto* t = dynamic_cast<const TransformWarp*>(w.get())) n = t->transform().normal(n);
  return normalize(n);
}

}  // namespace

SlopeMap::SlopeMap(std::vector<Entry> entries) : entries_(std::move(entries)) {
  if (entries_.empty()) throw std::invalid_argument("a slope_map needs at least one entry");
  std::stable_sort(entries_.begin(), entries_.end(),
                   [](const Entry& a, const Entry& b) { return a.value < b.value; });
}

double SlopeMap::height(double value) const {
  const MapBracket bracket = map_bracket(entries_, value, [](const Entry& e) { return e.value; });
  const Entry& a = entries_[bracket.lower];
  const Entry& b = entries_[bracket.upper];
  if (bracket.lower == bracket.upper) return b.height;
  const double span = b.value - a.value;
  // Cubic Hermite interpolation: heights at the ends, slopes (per unit value) as end tangents.
  const double t = bracket.weight;
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * a.height + (t3 - 2 * t2 + t) * span * a.slope +
         (-2 * t3 + 3 * t2) * b.height + (t3 - t2) * span * b.slope;
}

PatternNormal::PatternNormal(NormalSpec spec) : spec_(std::move(spec)) {
  if (spec_.uv_mapping) geometry::request_surface_uv();
  if (!spec_.pattern) throw std::invalid_argument("a normal needs a pattern");
  if (!(spec_.accuracy > 0)) throw std::invalid_argument("accuracy must be positive");
  std::stable_sort(spec_.normal_map.begin(), spec_.normal_map.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& e : spec_.normal_map)
    if (!e.second) throw std::invalid_argument("a normal_map entry has no normal");
}

Vec3 PatternNormal::pattern_point(const material::PatternPoint& point) const {
  return spec_.uv_mapping ? Vec3{point.uv.u, point.uv.v, 0} : point.p;
}

Vec3 PatternNormal::bend(const Vec3& q) const {
  if (!spec_.slope_map) {
    if (const auto* own = dynamic_cast<const BumpSource*>(spec_.pattern.get()))
      return own->bump(q) * spec_.bump_size;
  }
  Vec3 sum{0, 0, 0};
  for (const Vec3& v : kTetrahedron) {
    double value = spec_.wave.apply(spec_.pattern->value(q + v * spec_.accuracy));
    if (spec_.slope_map) value = spec_.slope_map->height(value);
    sum = sum + v * value;
  }
  return sum * (-kGradientScale * spec_.bump_size / spec_.accuracy);
}

Vec3 PatternNormal::perturb(const Vec3& normal, const material::PatternPoint& point) const {
  if (!spec_.normal_map.empty()) return perturb_by_map(normal, point);
  const Vec3 q = spec_.warps.apply(pattern_point(point));
  const Vec3 n = to_pattern_space(spec_.warps, normal);
  const auto* setter = dynamic_cast<const NormalSetter*>(spec_.pattern.get());
  if (setter && !spec_.slope_map)
    return from_pattern_space(spec_.warps, setter->set_normal(q, n, spec_.bump_size));
  return from_pattern_space(spec_.warps, n + bend(q));
}

Vec3 PatternNormal::perturb_by_map(const Vec3& normal, const material::PatternPoint& point) const {
  // The entries see the point where this pattern's warps took it (POV-Ray normal.cpp, Perturb_Normal).
  material::PatternPoint warped = point;
  warped.p = spec_.warps.apply(pattern_point(point));
  const double value = spec_.wave.apply(spec_.pattern->value(warped.p));
  const auto& map = spec_.normal_map;
  const MapBracket bracket = map_bracket(map, value);
  const Vec3 b = map[bracket.upper].second->perturb(normal, warped);
  if (bracket.lower == bracket.upper) return b;
  const Vec3 a = map[bracket.lower].second->perturb(normal, warped);
  const Vec3 blend = a * (1 - bracket.weight) + b * bracket.weight;
  return dot(blend, blend) > 0 ? normalize(blend) : normal;
}

Vec3 TransformedNormal::perturb(const Vec3& normal, const material::PatternPoint& point) const {
  material::PatternPoint moved = point;
  moved.p = transform_.inverse_point(point.p);
  const Vec3 n = normalize(transform_.inverse_normal(normal));
  return normalize(transform_.normal(inner_->perturb(n, moved)));
}

}  // namespace snell::texture
