#pragma once
// POV-Ray `isosurface` (POV-Ray 3.7 reference, "Isosurface Object"): the surface where a user function
// equals `threshold`, inside where it is below, cut out of a box or sphere container.
#include <atomic>
#include <cstdint>
#include <memory>

#include "snell/function/function.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

struct IsosurfaceSettings {
  /// f(x, y, z); must take exactly three arguments.
  std::shared_ptr<const function::Function> function;
  /// `contained_by { box | sphere }` (a geometry::Box or geometry::Sphere); POV-Ray's default is box{-1, 1}.
  std::shared_ptr<const Shape> container;
  double threshold = 0;
  /// Roots are refined until their bracket is shorter than this (in ray parameter units, as POV-Ray).
  double accuracy = 0.001;
  /// Lipschitz bound of f: |f(p) - f(q)| <= max_gradient |p - q|.
  double max_gradient = 1.1;
  /// `open`: where the container cuts the inside, show nothing instead of the container's surface.
  bool open = false;
  /// How many surface crossings one ray collects for CSG (`max_trace`; `all_intersections` = unlimited).
  int max_trace = 1;
  /// Keep the counts evaluations(), rays() and hits() (three shared atomic additions per ray, which two
  /// threads contend for, so only when asked: SNELL_ISOSURFACE_STATS).
  bool count_work = false;
};

/// Ray-casting by Lipschitz sphere tracing (Hart 1996, "Sphere tracing", The Visual Computer 12(10)):
/// with |grad f| <= L, no root lies closer than |f - threshold| / L, so the march takes that step (at
/// least `accuracy`), and a sign change is refined by the Illinois variant of regula falsi. POV-Ray
/// instead bisects recursively (R. Suzuki's method); both miss features thinner than `accuracy`.
class Isosurface final : public Shape {
 public:
  explicit Isosurface(IsosurfaceSettings settings);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool crosses(const Ray& ray, double t_min, double t_max) const override;
  bool inside(const Vec3& p) const override;
  bool inside_within_bounds() const override { return true; }
  std::string_view kind() const override { return "isosurface"; }

  /// f(p) - threshold: negative inside.
  double field(const Vec3& p) const;
  /// The steepest slope |grad f| seen between samples along rays so far (POV-Ray compares it with
  /// max_gradient after rendering: steeper means holes, much gentler means wasted time).
  double steepest_slope() const { return steepest_.load(std::memory_order_relaxed); }
  /// How many times f was evaluated so far (march, refinement and normals), for measuring the march;
  /// 0 unless settings().count_work.
  std::uint64_t evaluations() const { return evaluations_.load(std::memory_order_relaxed); }
  /// How many rays were traced and how many surface points (each with a 4-sample normal) found so far.
  std::uint64_t rays() const { return rays_.load(std::memory_order_relaxed); }
  std::uint64_t hits() const { return hits_.load(std::memory_order_relaxed); }
  const IsosurfaceSettings& settings() const { return settings_; }

 private:
  /// Crossings of the ray with t in (t_min, t_max), at most `limit` of them, in increasing t; without
  /// kNormals the hits of the surface carry only t (the container's walls keep theirs).
  template <bool kNormals, typename Sink>
  void trace(const Ray& ray, double t_min, double t_max, int limit, Sink&& sink) const;
  /// The hit at t with its normal; `batch`, where given, evaluates the normal's samples.
  LocalHit surface_hit(const Ray& ray, double t, function::Function::LaneBatch* batch) const;
  void note_slope(double slope) const;

  IsosurfaceSettings settings_;
  std::uint64_t id_;  // unique to this isosurface: the key of what its marches proved (isosurface.cpp)
  mutable std::atomic<double> steepest_{0};
  mutable std::atomic<std::uint64_t> evaluations_{0};
  mutable std::atomic<std::uint64_t> rays_{0};
  mutable std::atomic<std::uint64_t> hits_{0};
};

/// POV-Ray's `evaluate P0, P1, P2` asks for an adaptive max_gradient. snell stays deterministic by
/// measuring instead: the largest finite-difference slope of f on a grid over the container, times
/// `factor` (P1), and at least `floor` (P0).
double estimate_max_gradient(const function::Function& f, const Bounds3& box, double floor, double factor);

}  // namespace snell::geometry
