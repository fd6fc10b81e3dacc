#pragma once
// POV-Ray `sor` (surface of revolution): the squared radius is a cubic in the height between consecutive
// points, the Hermite cubic through P[i+1], P[i+2] whose slopes come from the neighbours P[i], P[i+3]
// (POV-Ray 3.7 reference, "Surface of Revolution"). A ray then meets each piece where a cubic in the
// height vanishes. Unless `open`, discs close the bottom and the top.
#include <span>
#include <vector>

#include "snell/geometry/axial_ray.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

class Sor final : public Shape {
 public:
  /// `points` (r, y): at least 4, with y strictly increasing from the second to the next-to-last.
  Sor(std::span<const Vec2> points, bool open);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  /// Stops at the first crossing and builds no hit (shadow rays).
  bool crosses(const Ray& ray, double t_min, double t_max) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  bool inside_within_bounds() const override { return true; }
  std::string_view kind() const override { return "sor"; }

  /// Squared radius at height y (within the shape's height range).
  double radius_squared(double y) const;

 private:
  /// r^2 = ((c3 w + c2) w + c1) w + c0 with w = (y - y0) / (y1 - y0) in [0, 1].
  struct Piece {
    double y0, y1;
    std::array<double, 4> c;
    /// Radius range over the piece, for skipping it.
    double r_min = 0, r_max = 0;
  };
  const Piece& piece_at(double y) const;
  /// Emits the crossings in (t_min, t_max); `emit` may lower t_max as it goes. With kExistence, a side
  /// piece's crossing is only shown to exist (has_root) and emitted without its hit (shadow rays).
  template <bool kExistence = false, typename F>
  void crossings(const Ray& ray, double t_min, const double& t_max, F&& emit) const;

  std::vector<Piece> pieces_;
  double radius_ = 0;
  AxialReach reach_;  // for skipping the pieces a ray passes out of reach of
  bool open_;
};

}  // namespace snell::geometry
