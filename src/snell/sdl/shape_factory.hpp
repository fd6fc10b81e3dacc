#pragma once
// The one place where the language constructs geometry: a new shape is one function here plus its
// keyword in objects.cpp.
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "snell/geometry/blob.hpp"
#include "snell/geometry/branch_set.hpp"
#include "snell/geometry/height_field.hpp"
#include "snell/geometry/isosurface.hpp"
#include "snell/geometry/julia_fractal.hpp"
#include "snell/geometry/mesh.hpp"
#include "snell/geometry/prism.hpp"
#include "snell/geometry/shape.hpp"
#include "snell/geometry/sphere_sweep.hpp"

namespace snell::sdl::shapes {

using ShapePtr = std::shared_ptr<const geometry::Shape>;
using math::Vec3;

/// Shapes may throw std::invalid_argument / std::runtime_error on degenerate input; the parser reports it.
ShapePtr sphere(const Vec3& center, double radius);
ShapePtr plane(const Vec3& normal, double distance);
ShapePtr box(const Vec3& a, const Vec3& b);
ShapePtr cylinder(const Vec3& base, const Vec3& cap, double radius, bool open);
ShapePtr cone(const Vec3& base, double base_radius, const Vec3& cap, double cap_radius, bool open);
ShapePtr disc(const Vec3& center, const Vec3& normal, double radius, double hole_radius);
ShapePtr torus(double major, double minor);
/// poly/cubic/quartic with POV-Ray's coefficient order.
ShapePtr poly(int order, const std::vector<double>& coefficients);
ShapePtr polygon(const std::vector<Vec3>& points);
ShapePtr prism(geometry::SplineKind kind, const std::vector<math::Vec2>& points, double height1,
               double height2, geometry::Sweep sweep, bool open);
ShapePtr lathe(geometry::SplineKind kind, const std::vector<math::Vec2>& points);
ShapePtr sor(const std::vector<math::Vec2>& points, bool open);
ShapePtr sphere_sweep(geometry::SweepSpline spline, const std::vector<geometry::SweepSphere>& points);
/// `text { ttf font string thickness, offset }`: the string's outline swept along z from 0 to thickness.
ShapePtr text(const std::filesystem::path& font, const std::string& string, double thickness,
              const Vec3& offset);
ShapePtr triangle(const Vec3& a, const Vec3& b, const Vec3& c);
ShapePtr smooth_triangle(const Vec3& a, const Vec3& na, const Vec3& b, const Vec3& nb, const Vec3& c,
                         const Vec3& nc);
ShapePtr mesh(geometry::MeshData data);
ShapePtr blob(double threshold, std::vector<geometry::BlobComponent> components);
/// POV-Ray quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }.
ShapePtr quadric(const Vec3& squares, const Vec3& mixed, const Vec3& linear, double constant);

/// Returned as an Isosurface so the caller can read its gradient statistics after rendering.
std::shared_ptr<const geometry::Isosurface> isosurface(geometry::IsosurfaceSettings settings);
ShapePtr superellipsoid(double east_west, double north_south);
ShapePtr height_field(geometry::HeightGrid grid, bool smooth, double water_level);
/// Round cones under one BVH (an L-system's branches).
ShapePtr branch_set(std::span<const geometry::BranchInput> branches);
ShapePtr julia_fractal(const geometry::JuliaFractal::Settings& settings);

}  // namespace snell::sdl::shapes
