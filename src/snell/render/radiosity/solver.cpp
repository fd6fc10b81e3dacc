#include "snell/render/radiosity/solver.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace snell::render::radiosity {

using math::Color;
using math::Vec3;

namespace {

/// POV-Ray widens the error bound for rays of little weight by this much less their weight
/// (radiosity.cpp, WEIGHT_ERROR_BOUND_OFFSET).
constexpr double kWeightErrorOffset = 0.25;
/// A gather whose nearest hit is closer than this fraction of the largest reuse distance is not kept: the
/// point is wedged between surfaces and its rays are unreliable (radiosity.cpp, GatherLight).
constexpr double kTooNear = 1e-4;

}  // namespace

std::vector<Vec3> cosine_directions(int count) {
  std::vector<Vec3> directions;
  directions.reserve(static_cast<size_t>(std::max(count, 0)));
  // Golden-angle spiral: point i at radius sqrt((i + 1/2) / count) covers equal disc areas.
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double u = (i + 0.5) / count;
    const double r = std::sqrt(u);
    const double phi = golden_angle * i;
    directions.push_back(Vec3{r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u))});
  }
  return directions;
}

void orthonormal_frame(const Vec3& n, Vec3& t, Vec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = Vec3{1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = Vec3{c, sign + n.y * n.y * a, -n.y};
}

BounceSettings bounce_settings(const scene::RadiositySettings& s, int depth) {
  // radiosity.cpp, GetRecursionSettings: half the rays per bounce (at least 5), reuse counts nearest_count,
  // 2, 1, error bound and reuse distances doubled per bounce, trace level 1.5 per bounce, weight
  // (brightness / 2) per bounce.
  BounceSettings b;
  const double doubling = std::ldexp(1.0, depth);
  b.rays = std::max(5, static_cast<int>(s.count / doubling));
  b.reuse_count = depth == 0 ? s.nearest_count : depth == 1 ? std::min(2, s.nearest_count) : 1;
  b.error_factor = doubling;
  b.minimum_reuse = s.minimum_reuse * doubling;
  b.maximum_reuse = s.maximum_reuse * doubling;
  // POV-Ray counts a camera ray as level 1 after TraceRay's increment; the gather ray starts from
  // int(1.5 (depth + 1)) and is incremented likewise.
  b.trace_level = static_cast<int>(1.5 * (depth + 1)) + 1;
  b.ray_weight = std::pow(0.5 * s.brightness, depth + 1);
  b.directions = cosine_directions(b.rays);
  return b;
}

Solver::Solver(const scene::RadiositySettings& settings, const Vec3& camera,
               std::shared_ptr<memory::Budget> budget, int max_trace_level)
    : settings_(settings), camera_(camera), budget_(std::move(budget)), max_trace_level_(max_trace_level) {
  const double widest = std::max(1.0, settings.low_error_factor) * settings.error_bound + kWeightErrorOffset;
  for (int depth = 0; depth < settings.recursion_limit; ++depth) {
    bounces_.push_back(bounce_settings(settings, depth));
    cache_.emplace_back(widest * bounces_.back().error_factor);
  }
}

Solver::~Solver() {
  if (budget_ && charged_ > 0) budget_->release(charged_);
}

TileRecords Solver::empty_tile(bool final_pass) const {
  TileRecords tile;
  tile.open = true;
  tile.final_pass = final_pass;
  for (const RecordGrid& grid : cache_) tile.by_depth.emplace_back(grid.reach_factor());
  return tile;
}

void Solver::begin_tile(TraceContext& context) const {
  context.radiosity_tile = empty_tile(true);
}

bool Solver::gather(const Vec3& point, const Vec3& normal, int depth, TraceContext& context,
                    const GatherRay& trace, Record& record) const {
  const BounceSettings& b = bounces_[static_cast<size_t>(depth)];
  const double to_eye = length(camera_ - point);
  const double least_radius = to_eye * b.minimum_reuse, most_radius = to_eye * b.maximum_reuse;
  Vec3 t, u;
  orthonormal_frame(normal, t, u);
  // The gather ray's weight: never below the radiosity adc_bailout (radiosity.cpp, GatherLight).
  const double weight = std::max(settings_.adc_bailout + 1e-6, b.ray_weight);
  const int level = std::min(b.trace_level, max_trace_level_);
  Color sum(0);
  double inverse_distances = 0, nearest = math::kInfinity;
  Vec3 to_nearest = normal;
  ++context.radiosity_depth;
  for (const Vec3& d : b.directions) {
    const Vec3 direction = d.x * t + d.y * u + d.z * normal;
    context.hit_distance = math::kInfinity;
    Color seen = trace(direction, level, weight);
    const double distance = context.hit_distance;
    // max_sample caps each ray's brightness (POV-Ray 3.7 reference, "max_sample").
    if (settings_.max_sample > 0 && seen.max() > settings_.max_sample)
      seen *= settings_.max_sample / seen.max();
    sum += seen;
    inverse_distances += 1 / distance;
    if (distance < nearest) {
      nearest = distance;
      to_nearest = direction;
    }
  }
  --context.radiosity_depth;
  const double rays = static_cast<double>(b.directions.size());
  record.point = point;
  record.normal = normal;
  record.irradiance = sum * (1 / rays);
  record.to_nearest = to_nearest;
  record.nearest_distance = nearest;
  const double harmonic_mean = inverse_distances > 0 ? rays / inverse_distances : math::kInfinity;
  record.harmonic_mean = std::clamp(harmonic_mean, least_radius, std::max(least_radius, most_radius));
  return nearest > most_radius * kTooNear;
}

Color Solver::ambient(const Vec3& point, const Vec3& normal, double ray_weight, TraceContext& context,
                      const GatherRay& trace) const {
  const int depth = context.radiosity_depth;
  const BounceSettings& b = bounces_[static_cast<size_t>(depth)];
  TileRecords& tile = context.radiosity_tile;
  const bool final_pass = !tile.open || tile.final_pass;
  // radiosity.cpp, ComputeAmbient: the pretrace works to a tighter bound (low_error_factor), rays of
  // little weight to a looser one.
  double bound = settings_.error_bound * (final_pass ? 1.0 : settings_.low_error_factor);
  if (ray_weight < kWeightErrorOffset) bound += kWeightErrorOffset - ray_weight;
  const ReuseQuery query{point, normal, bound * b.error_factor, final_pass && depth == 0};
  Blend blend;
  cache_[static_cast<size_t>(depth)].gather(query, blend);
  if (tile.open) tile.by_depth[static_cast<size_t>(depth)].gather(query, blend);

  // Enough nearby records: interpolate. The final pass settles for any record unless always_sample.
  Color light;
  const bool enough = blend.weight * 4 >= b.reuse_count;
  if (enough || (final_pass && !settings_.always_sample && blend.weight > 0)) {
    light = blend.mean();
  } else {
    Record record;
    const bool keep = gather(point, normal, depth, context, trace, record);
    if (final_pass) final_gathers_.fetch_add(1, std::memory_order_relaxed);
    // The new record joins the ones found, with weight 1.
    light = (blend.weighted + record.irradiance) * (1 / (blend.weight + 1));
    if (keep && tile.open) tile.by_depth[static_cast<size_t>(depth)].insert(record);
  }
  // gray_threshold pulls the colour towards its grey (radiosity.cpp, ComputeAmbient).
  const double g = settings_.gray_threshold;
  light = light * (1 - g) + Color(light.grey() * g);
  return light * settings_.brightness;
}

void Solver::merge(std::vector<TileRecords>& tiles) {
  // Tiles of one pass cannot see each other's records, so near their borders they gather twice where a
  // single-threaded pretrace would have reused: a record is dropped when the records before it (in tile
  // order) already cover its point as a pretrace lookup would require. This keeps lookups fast.
  for (TileRecords& tile : tiles)
    for (size_t depth = 0; depth < tile.by_depth.size(); ++depth)
      for (const Record& r : tile.by_depth[depth].records()) {
        if (cache_full_) return;
        const BounceSettings& b = bounces_[depth];
        const ReuseQuery query{r.point, r.normal,
                               settings_.error_bound * settings_.low_error_factor * b.error_factor, false};
        Blend covered;
        cache_[depth].gather(query, covered);
        if (covered.weight * 4 >= b.reuse_count) continue;
        if (budget_) {
          try {
            budget_->charge(RecordGrid::bytes_per_record(), "radiosity cache");
            charged_ += RecordGrid::bytes_per_record();
          } catch (const memory::BudgetExceeded&) {
            // Past --max-memory the cache stops growing; later points gather without it.
            cache_full_ = true;
            return;
          }
        }
        cache_[depth].insert(r);
      }
}

std::string Solver::summary() const {
  std::string per_depth;
  uint64_t bytes = 0;
  for (size_t depth = 0; depth < cache_.size(); ++depth) {
    per_depth += fmt::format("{}{}", depth == 0 ? "" : " + ", cache_[depth].size());
    bytes += cache_[depth].bytes();
  }
  return fmt::format(
      "radiosity: {} pretrace passes ({} rays), cache {} records by bounce ({:.1f} KiB){}, {} gathers in the "
      "final pass",
      pretrace_passes_, pretrace_rays_, per_depth, static_cast<double>(bytes) / 1024,
      cache_full_ ? " (stopped at --max-memory)" : "", final_gathers_.load());
}

}  // namespace snell::render::radiosity
