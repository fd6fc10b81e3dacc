#include "snell/render/radiosity/record_grid.hpp"

#include "snell/math/constants.hpp"

#include <algorithm>
#include <cmath>

namespace snell::render::radiosity {

using math::Vec3;

namespace {

/// Records a hair's breadth from the query count as at it (no direction to test).
constexpr double kSamePoint = 1e-9;
/// A record this far in front of the point (cosine towards the mean normal) is dropped; between it and 0
/// its weight fades (POV-Ray's IN_FRONT_LIMIT).
constexpr double kInFrontLimit = -0.05;
/// Weights below this are dropped as noise.
constexpr double kLeastWeight = 1e-5;

/// The record's radius for the query, shrunk towards its nearest surface as POV-Ray does: a blend of the
/// harmonic mean and the nearest distance by the cosine between the query's offset and that direction.
double shrunk_radius(const Record& r, const Vec3& delta_unit) {
  const double towards_nearest = dot(r.to_nearest, delta_unit);
  if (towards_nearest <= 0) return r.harmonic_mean;
  return towards_nearest * r.nearest_distance + (1 - towards_nearest) * r.harmonic_mean;
}

}  // namespace

double reuse_error(const Record& r, const ReuseQuery& q) {
  const Vec3 delta = q.point - r.point;
  const double dist = length(delta);
  const double radius = dist > kSamePoint ? shrunk_radius(r, delta / dist) : r.harmonic_mean;
  const double translation = radius > 0 ? dist / radius : (dist > kSamePoint ? math::kInfinity : 0.0);
  const double rotation = 2 * std::sqrt(std::fabs(1 - dot(q.normal, r.normal)));
  return translation + rotation;
}

double reuse_weight(const Record& r, const ReuseQuery& q) {
  const double error = reuse_error(r, q);
  if (!(error < q.error_bound)) return 0;
  const Vec3 delta = q.point - r.point;
  const double dist = length(delta);
  // Is the record's point in front of the query's surface (Ward 1988's test, POV-Ray's tolerance)?
  double in_front = 1;
  if (dist > kSamePoint) {
    const Vec3 half = q.normal + r.normal;
    const double half_length = length(half);
    in_front = half_length > 0 ? dot(delta / dist, half) / half_length : 0;
  }
  if (in_front <= kInFrontLimit) return 0;
  const double t = error / q.error_bound;  // 0..1
  double weight;
  if (q.smooth)
    weight = t < 0.5 ? 1 - 2 * t * t : 2 * (1 - t) * (1 - t);  // POV-Ray's pseudo-sigmoid
  else
    weight = 1 - t;
  if (in_front <= 0) weight *= 1 - in_front / kInFrontLimit;
  return weight > kLeastWeight ? weight : 0;
}

uint64_t RecordGrid::cell_key(int level, int64_t x, int64_t y, int64_t z) {
  // A mix of the four numbers (splitmix64's finaliser); two cells sharing a key only cost a few more
  // weight tests, as every record is weighed by its true distance.
  uint64_t h = static_cast<uint64_t>(level + 64);
  for (const int64_t v : {x, y, z}) {
    h ^= static_cast<uint64_t>(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
    h ^= h >> 31;
  }
  return h;
}

void RecordGrid::insert(const Record& r) {
  const uint32_t index = static_cast<uint32_t>(records_.size());
  records_.push_back(r);
  probes_.push_back(
      Probe{static_cast<float>(r.point.x), static_cast<float>(r.point.y), static_cast<float>(r.point.z),
            static_cast<float>(r.harmonic_mean * r.harmonic_mean), static_cast<float>(r.normal.x),
            static_cast<float>(r.normal.y), static_cast<float>(r.normal.z)});
  const double reach = std::max(r.harmonic_mean * reach_factor_, 1e-12);
  // Cells at least as wide as the reach: a record lands in at most 3 x 3 x 3 cells, and a query weighs few
  // records whose reach misses it.
  const int level = std::clamp(static_cast<int>(std::ceil(std::log2(reach))), -60, 60);
  const double side = std::ldexp(1.0, level);
  if (!std::binary_search(levels_.begin(), levels_.end(), level))
    levels_.insert(std::upper_bound(levels_.begin(), levels_.end(), level), level);
  auto range = [&](double c) {
    return std::pair{static_cast<int64_t>(std::floor((c - reach) / side)),
                     static_cast<int64_t>(std::floor((c + reach) / side))};
  };
  const auto [x0, x1] = range(r.point.x);
  const auto [y0, y1] = range(r.point.y);
  const auto [z0, z1] = range(r.point.z);
  for (int64_t x = x0; x <= x1; ++x)
    for (int64_t y = y0; y <= y1; ++y)
      for (int64_t z = z0; z <= z1; ++z) {
        std::vector<uint32_t>& cell = cells_[cell_key(level, x, y, z)];
        if (cell.empty() || cell.back() != index) {  // two cells of one record may share a key
          cell.push_back(index);
          ++index_entries_;
        }
      }
}

void RecordGrid::clear() {
  records_.clear();
  probes_.clear();
  cells_.clear();
  levels_.clear();
  index_entries_ = 0;
}

uint64_t RecordGrid::bytes_per_record() {
  return sizeof(Record) + 8 * (sizeof(uint32_t) + 16);
}

uint64_t RecordGrid::bytes() const {
  return records_.capacity() * (sizeof(Record) + sizeof(Probe)) + index_entries_ * sizeof(uint32_t) +
         cells_.size() * (sizeof(uint64_t) + sizeof(std::vector<uint32_t>) + 16);
}

void RecordGrid::gather(const ReuseQuery& q, Blend& blend) const {
  // 2 sqrt(1 - cos) < bound needs cos > 1 - bound^2 / 4; float slack keeps the prefilter conservative.
  const float least_cos = static_cast<float>(1 - q.error_bound * q.error_bound / 4) - 1e-4f;
  const float bound_squared = static_cast<float>(q.error_bound * q.error_bound) * 1.001f;
  const float nx = static_cast<float>(q.normal.x), ny = static_cast<float>(q.normal.y),
              nz = static_cast<float>(q.normal.z);
  const float px = static_cast<float>(q.point.x), py = static_cast<float>(q.point.y),
              pz = static_cast<float>(q.point.z);
  for (const int level : levels_) {
    const double side = std::ldexp(1.0, level);
    const auto cell = cells_.find(cell_key(level, static_cast<int64_t>(std::floor(q.point.x / side)),
                                           static_cast<int64_t>(std::floor(q.point.y / side)),
                                           static_cast<int64_t>(std::floor(q.point.z / side))));
    if (cell == cells_.end()) continue;
    for (const uint32_t i : cell->second) {
      // Cheap rejections on the compact copy first (conservative, so the exact rule decides): normals
      // too far apart for the bound on their own, then POV-Ray's quick distance test (the shrunk radius
      // never exceeds the harmonic mean).
      const Probe& p = probes_[i];
      if (p.nx * nx + p.ny * ny + p.nz * nz < least_cos) continue;
      const float dx = p.x - px, dy = p.y - py, dz = p.z - pz;
      if (dx * dx + dy * dy + dz * dz > p.radius_squared * bound_squared) continue;
      const Record& r = records_[i];
      const double reach = r.harmonic_mean * q.error_bound;
      if (length_squared(q.point - r.point) >= reach * reach) continue;
      if (const double w = reuse_weight(r, q); w > 0) blend.add(r, w);
    }
  }
}

}  // namespace snell::render::radiosity
