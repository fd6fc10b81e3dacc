#include "snell/sdl/shape_factory.hpp"

#include "snell/geometry/box.hpp"
#include "snell/geometry/cone.hpp"
#include "snell/geometry/cylinder.hpp"
#include "snell/geometry/disc.hpp"
#include "snell/geometry/lathe.hpp"
#include "snell/geometry/plane.hpp"
#include "snell/geometry/poly.hpp"
#include "snell/geometry/polygon.hpp"
#include "snell/geometry/quadric.hpp"
#include "snell/geometry/sor.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/geometry/superellipsoid.hpp"
#include "snell/geometry/text_outline.hpp"
#include "snell/geometry/torus.hpp"
#include "snell/geometry/triangle.hpp"

namespace snell::sdl::shapes {

ShapePtr sphere(const Vec3& center, double radius) {
  return std::make_shared<geometry::Sphere>(center, radius);
}
ShapePtr plane(const Vec3& normal, double distance) {
  return std::make_shared<geometry::Plane>(normal, distance);
}

ShapePtr box(const Vec3& a, const Vec3& b) {
  return std::make_shared<geometry::Box>(a, b);
}

ShapePtr cylinder(const Vec3& base, const Vec3& cap, double radius, bool open) {
  return std::make_shared<geometry::Cylinder>(base, cap, radius, open);
}

ShapePtr cone(const Vec3& base, double base_radius, const Vec3& cap, double cap_radius, bool open) {
  return std::make_shared<geometry::Cone>(base, base_radius, cap, cap_radius, open);
}

ShapePtr disc(const Vec3& center, const Vec3& normal, double radius, double hole_radius) {
  return std::make_shared<geometry::Disc>(center, normal, radius, hole_radius);
}

ShapePtr torus(double major, double minor) {
  return std::make_shared<geometry::Torus>(major, minor);
}

ShapePtr poly(int order, const std::vector<double>& coefficients) {
  return std::make_shared<geometry::Poly>(order, coefficients);
}

ShapePtr polygon(const std::vector<Vec3>& points) {
  return std::make_shared<geometry::Polygon>(points);
}

ShapePtr prism(geometry::SplineKind kind, const std::vector<math::Vec2>& points, double height1,
               double height2, geometry::Sweep sweep, bool open) {
  return std::make_shared<geometry::Prism>(geometry::Outline(geometry::prism_pieces(kind, points)), height1,
                                           height2, sweep, open);
}

ShapePtr lathe(geometry::SplineKind kind, const std::vector<math::Vec2>& points) {
  return std::make_shared<geometry::Lathe>(geometry::Outline(geometry::lathe_pieces(kind, points)));
}

ShapePtr sor(const std::vector<math::Vec2>& points, bool open) {
  return std::make_shared<geometry::Sor>(points, open);
}

ShapePtr sphere_sweep(geometry::SweepSpline spline, const std::vector<geometry::SweepSphere>& points) {
  return std::make_shared<geometry::SphereSweep>(geometry::sweep_path(spline, points));
}

ShapePtr text(const std::filesystem::path& font, const std::string& string, double thickness,
              const Vec3& offset) {
  return std::make_shared<geometry::Prism>(geometry::text_outline(font, string, {offset.x, offset.y}), 0,
                                           thickness, geometry::Sweep::linear, false, true);
}

ShapePtr triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  return std::make_shared<geometry::Triangle>(a, b, c);
}

ShapePtr smooth_triangle(const Vec3& a, const Vec3& na, const Vec3& b, const Vec3& nb, const Vec3& c,
                         const Vec3& nc) {
  return std::make_shared<geometry::Triangle>(a, na, b, nb, c, nc);
}

ShapePtr mesh(geometry::MeshData data) {
  return std::make_shared<geometry::Mesh>(std::move(data));
}

ShapePtr blob(double threshold, std::vector<geometry::BlobComponent> components) {
  return std::make_shared<geometry::Blob>(threshold, std::move(components));
}

ShapePtr quadric(const Vec3& squares, const Vec3& mixed, const Vec3& linear, double constant) {
  return std::make_shared<geometry::Quadric>(squares, mixed, linear, constant);
}

std::shared_ptr<const geometry::Isosurface> isosurface(geometry::IsosurfaceSettings settings) {
  return std::make_shared<geometry::Isosurface>(std::move(settings));
}

ShapePtr superellipsoid(double east_west, double north_south) {
  return std::make_shared<geometry::Superellipsoid>(east_west, north_south);
}

ShapePtr branch_set(std::span<const geometry::BranchInput> branches) {
  return std::make_shared<geometry::BranchSet>(branches);
}

ShapePtr height_field(geometry::HeightGrid grid, bool smooth, double water_level) {
  return std::make_shared<geometry::HeightField>(std::move(grid), smooth, water_level);
}

ShapePtr julia_fractal(const geometry::JuliaFractal::Settings& settings) {
  return std::make_shared<geometry::JuliaFractal>(settings);
}

}  // namespace snell::sdl::shapes
