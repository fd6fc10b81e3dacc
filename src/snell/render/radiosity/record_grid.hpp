#pragma once
// The irradiance cache's records and their reuse rule (Ward, Rubinstein & Clear 1988, "A Ray Tracing
// Solution for Diffuse Interreflection"; Ward & Heckbert 1992, "Irradiance Gradients"), with POV-Ray 3.7's
// variant of the error measure and weights (behaviour of source/core/lighting/radiosity.cpp,
// AverageNearBlock), and a spatial index that finds the records whose reach covers a point.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "snell/math/color.hpp"
#include "snell/math/vec3.hpp"

namespace snell::render::radiosity {

/// One gathered sample of incoming indirect light.
struct Record {
  math::Vec3 point;
  /// The normal the hemisphere was gathered around.
  math::Vec3 normal;
  /// Unit direction of the nearest surface the gather rays hit, and its distance: the record reaches less
  /// far towards it (a wall next to a corner must not lend its light round the corner).
  math::Vec3 to_nearest;
  double nearest_distance = 0;
  /// Harmonic mean of the gather rays' hit distances, clamped to the reuse limits: the record's radius.
  double harmonic_mean = 0;
  /// Mean radiance over the cosine-weighted hemisphere (before brightness and gray_threshold).
  math::Color irradiance;
};

/// How a record is weighed for a query point.
struct ReuseQuery {
  math::Vec3 point;
  math::Vec3 normal;
  /// The error bound in force (error_bound, times low_error_factor in pretrace, doubled per bounce).
  double error_bound = 1.8;
  /// POV-Ray blends top-level records of the final pass with a smooth (pseudo-sigmoid) fall-off, all
  /// others linearly.
  bool smooth = false;
};

/// POV-Ray's error of reusing `r` at the query point: distance over the record's radius (shrunk towards its
/// nearest surface) plus 2 sqrt(1 - cos) of the normals' angle; `radius` receives that shrunk radius.
double reuse_error(const Record& r, const ReuseQuery& q);

/// The weight of record `r` at the query point: 0 when the error reaches the bound or the record lies well
/// in front of the point (it might shadow it), else falling from 1 at the record to 0 at the bound.
double reuse_weight(const Record& r, const ReuseQuery& q);

/// Sum of weights and of weight x irradiance over the reusable records.
struct Blend {
  math::Color weighted;
  double weight = 0;
  void add(const Record& r, double w) {
    weighted += r.irradiance * w;
    weight += w;
  }
  math::Color mean() const { return weight > 0 ? weighted * (1.0 / weight) : math::Color(0); }
};

/// Records indexed by a hierarchy of hashed grids: a record of reach r (harmonic mean x the largest error
/// bound any query will use) is filed in every cell of side >= r (the next power of two) its reach touches
/// (at most 27), so a query visits one cell per grid level in use. Iteration order is insertion order, so
/// sums over the records are the same in every run.
class RecordGrid {
 public:
  /// `reach_factor`: the largest error bound queries will use.
  explicit RecordGrid(double reach_factor = 1) : reach_factor_(reach_factor) {}

  double reach_factor() const { return reach_factor_; }
  void insert(const Record& r);
  void clear();
  size_t size() const { return records_.size(); }
  const std::vector<Record>& records() const { return records_; }
  /// Bytes held by the records and the index (approximate: hash-table nodes counted at their payload).
  uint64_t bytes() const;
  /// Bytes one more record costs, for charging the memory budget before adding it.
  static uint64_t bytes_per_record();

  /// Adds every reusable record's weight at the query point to `blend`.
  void gather(const ReuseQuery& q, Blend& blend) const;

 private:
  static uint64_t cell_key(int level, int64_t x, int64_t y, int64_t z);
  /// One cell's records: their positions, squared radii and normals in floats, in groups of kGroup
  /// (structure of arrays, the last group padded with entries no query keeps), for a quick conservative
  /// rejection of most of them a group at a time before the exact rule weighs the rest. A query weighs
  /// every record of its cell: with the reach sized for the largest error bound, most lie out of reach
  /// (gamma_showcase: about 220 entries looked at per lookup, 55 of them weighed: half of the render's time).
  struct Cell {
    static constexpr int kGroup = 4;
    std::vector<float> x, y, z, radius_squared, nx, ny, nz;
    std::vector<uint32_t> index;
    uint32_t size = 0;
    void add(uint32_t record, const Record& r);
  };
  /// A grid level: cell side 2^level, and the side's inverse (exact: a power of two).
  struct Level {
    int level;
    double inverse_side;
  };
  double reach_factor_;
  std::vector<Record> records_;
  std::unordered_map<uint64_t, Cell> cells_;
  /// Grid levels that hold records, ascending.
  std::vector<Level> levels_;
  uint64_t index_entries_ = 0;
};

}  // namespace snell::render::radiosity
