#pragma once
// POV-Ray `prism`: an outline in the xz plane swept along y from height1 to height2, either straight
// (linear_sweep) or towards the origin (conic_sweep: the outline scaled by y). `text` reuses it with the
// outline in the xy plane swept along z. Walls are found exactly: the ray and the sweep direction span a
// plane that meets the outline's plane in a line, whose crossings with each cubic piece are polynomial
// roots (as in POV-Ray's prism.cpp).
#include "snell/geometry/outline.hpp"
#include "snell/geometry/shape.hpp"

namespace snell::geometry {

enum class Sweep { linear, conic };

class Prism final : public Shape {
 public:
  /// `outline_in_xy`: the outline lies in the xy plane and the sweep runs along z (text); else xz and y.
  Prism(Outline outline, double height1, double height2, Sweep sweep, bool open, bool outline_in_xy = false);

  Bounds3 bounds() const override;
  bool intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const override;
  /// Stops at the first crossing and builds no hit (shadow rays).
  bool crosses(const Ray& ray, double t_min, double t_max) const override;
  void all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const override;
  bool inside(const Vec3& p) const override;
  std::string_view kind() const override { return outline_in_xy_ ? "text" : "prism"; }

 private:
  /// A crossing found before its normal is worked out: piece >= 0 is a wall, -1 the bottom, -2 the top.
  struct Crossing {
    double t;
    int piece;
    double s;
  };
  /// Emits the crossings in (t_min, t_max), walls before caps; `emit` may lower t_max as it goes.
  template <typename F>
  void crossings(const Ray& local, double t_min, const double& t_max, F&& emit) const;
  template <typename F>
  void wall_crossings(const Ray& local, double t_min, const double& t_max, F&& emit) const;
  LocalHit make_hit(const Ray& local, const Crossing& c) const;
  bool inside_local(const Vec3& p) const;
  /// Swaps y and z for text; the identity for prisms. Its own inverse.
  Vec3 to_local(const Vec3& v) const { return outline_in_xy_ ? Vec3(v.x, v.z, v.y) : v; }

  Outline outline_;
  double h1_, h2_;
  Sweep sweep_;
  bool open_, outline_in_xy_;
};

}  // namespace snell::geometry
