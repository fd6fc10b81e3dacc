#include "snell/render/radiosity/record_grid.hpp"

#include "snell/math/constants.hpp"
#include "snell/math/float_lanes.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

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

/// The query point's offset from a record, its length and the error's rotation term: what reuse_error,
/// reuse_weight and the grid's own lower bound all need, computed once.
struct Offset {
  Offset(const Record& r, const ReuseQuery& q) : Offset(r, q, q.point - r.point) {}
  /// With the offset (and so its squared length) already at hand.
  Offset(const Record& r, const ReuseQuery& q, const Vec3& d, double distance_squared)
      : delta(d),
        dist(std::sqrt(distance_squared)),
        rotation(2 * std::sqrt(std::fabs(1 - dot(q.normal, r.normal)))) {}
  Offset(const Record& r, const ReuseQuery& q, const Vec3& d) : Offset(r, q, d, length_squared(d)) {}
  Vec3 delta;
  double dist;
  double rotation;
};

double error_at(const Record& r, const Offset& o) {
  const double radius = o.dist > kSamePoint ? shrunk_radius(r, o.delta / o.dist) : r.harmonic_mean;
  const double translation = radius > 0 ? o.dist / radius : (o.dist > kSamePoint ? math::kInfinity : 0.0);
  return translation + o.rotation;
}

double weight_at(const Record& r, const ReuseQuery& q, const Offset& o) {
  const double error = error_at(r, o);
  if (!(error < q.error_bound)) return 0;
  // Is the record's point in front of the query's surface (Ward 1988's test, POV-Ray's tolerance)?
  double in_front = 1;
  if (o.dist > kSamePoint) {
    const Vec3 half = q.normal + r.normal;
    const double half_length = length(half);
    in_front = half_length > 0 ? dot(o.delta / o.dist, half) / half_length : 0;
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

}  // namespace

double reuse_error(const Record& r, const ReuseQuery& q) {
  return error_at(r, Offset(r, q));
}

double reuse_weight(const Record& r, const ReuseQuery& q) {
  return weight_at(r, q, Offset(r, q));
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

void RecordGrid::Cell::add(uint32_t record, const Record& r) {
  if (size % kGroup == 0) {
    // A new group, padded with entries of negative radius, which no distance test keeps.
    for (std::vector<float>* v : {&x, &y, &z, &nx, &ny, &nz}) v->resize(v->size() + kGroup, 0.0f);
    radius_squared.resize(radius_squared.size() + kGroup, -1.0f);
    index.resize(index.size() + kGroup, 0);
  }
  x[size] = static_cast<float>(r.point.x);
  y[size] = static_cast<float>(r.point.y);
  z[size] = static_cast<float>(r.point.z);
  radius_squared[size] = static_cast<float>(r.harmonic_mean * r.harmonic_mean);
  nx[size] = static_cast<float>(r.normal.x);
  ny[size] = static_cast<float>(r.normal.y);
  nz[size] = static_cast<float>(r.normal.z);
  index[size] = record;
  ++size;
}

void RecordGrid::insert(const Record& r) {
  const uint32_t index = static_cast<uint32_t>(records_.size());
  records_.push_back(r);
  const double reach = std::max(r.harmonic_mean * reach_factor_, 1e-12);
  // Cells at least as wide as the reach: a record lands in at most 3 x 3 x 3 cells, and a query weighs few
  // records whose reach misses it.
  const int level = std::clamp(static_cast<int>(std::ceil(std::log2(reach))), -60, 60);
  const double side = std::ldexp(1.0, level);
  const auto at_or_above = std::lower_bound(levels_.begin(), levels_.end(), level,
                                            [](const Level& l, int v) { return l.level < v; });
  if (at_or_above == levels_.end() || at_or_above->level != level)
    levels_.insert(at_or_above, Level{level, 1 / side});
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
        Cell& cell = cells_[cell_key(level, x, y, z)];
        if (cell.size == 0 ||
            cell.index[cell.size - 1] != index) {  // two cells of one record may share a key
          cell.add(index, r);
          ++index_entries_;
        }
      }
}

void RecordGrid::clear() {
  records_.clear();
  cells_.clear();
  levels_.clear();
  index_entries_ = 0;
}

uint64_t RecordGrid::bytes_per_record() {
  return sizeof(Record) + 8 * (8 * sizeof(float) + 16);
}

uint64_t RecordGrid::bytes() const {
  return records_.capacity() * sizeof(Record) + index_entries_ * 8 * sizeof(float) +
         cells_.size() * (sizeof(uint64_t) + sizeof(Cell) + 16);
}

void RecordGrid::gather(const ReuseQuery& q, Blend& blend) const {
  using F = math::lanes::Lanes<Cell::kGroup>::F;
  using M = math::lanes::Lanes<Cell::kGroup>::M;
  const auto load = [](const std::vector<float>& v, uint32_t at) {
    F f;
    std::memcpy(&f, v.data() + at, sizeof f);
    return f;
  };
  // 2 sqrt(1 - cos) < bound needs cos > 1 - bound^2 / 4; float slack keeps the prefilter conservative.
  const F least_cos = static_cast<float>(1 - q.error_bound * q.error_bound / 4) - 1e-4f + F{};
  const F bound_squared = static_cast<float>(q.error_bound * q.error_bound) * 1.001f + F{};
  const F nx = static_cast<float>(q.normal.x) + F{}, ny = static_cast<float>(q.normal.y) + F{},
          nz = static_cast<float>(q.normal.z) + F{};
  const F px = static_cast<float>(q.point.x) + F{}, py = static_cast<float>(q.point.y) + F{},
          pz = static_cast<float>(q.point.z) + F{};
  for (const Level& level : levels_) {
    const auto found =
        cells_.find(cell_key(level.level, static_cast<int64_t>(std::floor(q.point.x * level.inverse_side)),
                             static_cast<int64_t>(std::floor(q.point.y * level.inverse_side)),
                             static_cast<int64_t>(std::floor(q.point.z * level.inverse_side))));
    if (found == cells_.end()) continue;
    const Cell& cell = found->second;
    for (uint32_t group = 0; group < cell.size; group += Cell::kGroup) {
      // Cheap rejections, a group at a time (conservative, so the exact rule decides): normals too far
      // apart for the bound on their own, and POV-Ray's quick distance test (the shrunk radius never
      // exceeds the harmonic mean).
      const F cosine = load(cell.nx, group) * nx + load(cell.ny, group) * ny + load(cell.nz, group) * nz;
      const F dx = load(cell.x, group) - px, dy = load(cell.y, group) - py, dz = load(cell.z, group) - pz;
      const F distance_squared = dx * dx + dy * dy + dz * dz;
      const M dropped =
          (cosine < least_cos) | (distance_squared > load(cell.radius_squared, group) * bound_squared);
      for (unsigned kept = ~math::lanes::bits(dropped) & ((1u << Cell::kGroup) - 1); kept != 0;
           kept &= kept - 1) {
        const Record& r = records_[cell.index[group + static_cast<uint32_t>(std::countr_zero(kept))]];
        const double reach = r.harmonic_mean * q.error_bound;
        const Vec3 delta = q.point - r.point;
        const double distance_squared_exact = length_squared(delta);
        if (distance_squared_exact >= reach * reach) continue;
        const Offset offset(r, q, delta, distance_squared_exact);
        // A lower bound of reuse_error: the shrunk radius, a blend of the harmonic mean and the nearest
        // distance, is at most the larger of the two, and the rotation term is reuse_error's own. Most
        // records that get this far fail here (gamma_showcase: 6 of 10), before the weight's divisions and
        // square roots; the slack covers the blend's rounding.
        if (offset.dist / std::max(r.harmonic_mean, r.nearest_distance) + offset.rotation >=
            q.error_bound * (1 + 1e-12))
          continue;
        if (const double w = weight_at(r, q, offset); w > 0) blend.add(r, w);
      }
    }
  }
}

}  // namespace snell::render::radiosity
