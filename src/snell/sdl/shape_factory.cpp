#include "snell/sdl/shape_factory.hpp"

#include <stdexcept>

#include "snell/geometry/box.hpp"
#include "snell/geometry/cone.hpp"
#include "snell/geometry/cylinder.hpp"
#include "snell/geometry/disc.hpp"
#include "snell/geometry/plane.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/geometry/torus.hpp"
#include "snell/geometry/triangle.hpp"

// Temporary seam while the geometry engineers land their files: __has_include on the implementation
// tells whether the constructor will link. Remove the guards once every shape is on main (a stale
// ccache/ninja object may need `touch` of this file after the shapes arrive).
#if __has_include("snell/geometry/box.cpp")
#define SNELL_HAS_BOX 1
#endif
#if __has_include("snell/geometry/cylinder.cpp")
#define SNELL_HAS_CYLINDER 1
#endif
#if __has_include("snell/geometry/cone.cpp")
#define SNELL_HAS_CONE 1
#endif
#if __has_include("snell/geometry/disc.cpp")
#define SNELL_HAS_DISC 1
#endif
#if __has_include("snell/geometry/torus.cpp")
#define SNELL_HAS_TORUS 1
#endif
#if __has_include("snell/geometry/triangle.cpp")
#define SNELL_HAS_TRIANGLE 1
#endif
#if __has_include("snell/geometry/mesh.cpp")
#define SNELL_HAS_MESH 1
#endif
#if __has_include("snell/geometry/blob.cpp")
#define SNELL_HAS_BLOB 1
#endif

namespace snell::sdl::shapes {

namespace {
[[noreturn]] void unavailable(const char* name) {
  throw std::runtime_error(std::string(name) + " is not available in this build yet");
}
}  // namespace

ShapePtr sphere(const Vec3& center, double radius) {
  return std::make_shared<geometry::Sphere>(center, radius);
}
ShapePtr plane(const Vec3& normal, double distance) {
  return std::make_shared<geometry::Plane>(normal, distance);
}

ShapePtr box([[maybe_unused]] const Vec3& a, [[maybe_unused]] const Vec3& b) {
#ifdef SNELL_HAS_BOX
  return std::make_shared<geometry::Box>(a, b);
#else
  unavailable("box");
#endif
}

ShapePtr cylinder([[maybe_unused]] const Vec3& base, [[maybe_unused]] const Vec3& cap,
                  [[maybe_unused]] double radius, [[maybe_unused]] bool open) {
#ifdef SNELL_HAS_CYLINDER
  return std::make_shared<geometry::Cylinder>(base, cap, radius, open);
#else
  unavailable("cylinder");
#endif
}

ShapePtr cone([[maybe_unused]] const Vec3& base, [[maybe_unused]] double base_radius,
              [[maybe_unused]] const Vec3& cap, [[maybe_unused]] double cap_radius,
              [[maybe_unused]] bool open) {
#ifdef SNELL_HAS_CONE
  return std::make_shared<geometry::Cone>(base, base_radius, cap, cap_radius, open);
#else
  unavailable("cone");
#endif
}

ShapePtr disc([[maybe_unused]] const Vec3& center, [[maybe_unused]] const Vec3& normal,
              [[maybe_unused]] double radius, [[maybe_unused]] double hole_radius) {
#ifdef SNELL_HAS_DISC
  return std::make_shared<geometry::Disc>(center, normal, radius, hole_radius);
#else
  unavailable("disc");
#endif
}

ShapePtr torus([[maybe_unused]] double major, [[maybe_unused]] double minor) {
#ifdef SNELL_HAS_TORUS
  return std::make_shared<geometry::Torus>(major, minor);
#else
  unavailable("torus");
#endif
}

ShapePtr triangle([[maybe_unused]] const Vec3& a, [[maybe_unused]] const Vec3& b,
                  [[maybe_unused]] const Vec3& c) {
#ifdef SNELL_HAS_TRIANGLE
  return std::make_shared<geometry::Triangle>(a, b, c);
#else
  unavailable("triangle");
#endif
}

ShapePtr smooth_triangle([[maybe_unused]] const Vec3& a, [[maybe_unused]] const Vec3& na,
                         [[maybe_unused]] const Vec3& b, [[maybe_unused]] const Vec3& nb,
                         [[maybe_unused]] const Vec3& c, [[maybe_unused]] const Vec3& nc) {
#ifdef SNELL_HAS_TRIANGLE
  return std::make_shared<geometry::Triangle>(a, na, b, nb, c, nc);
#else
  unavailable("smooth_triangle");
#endif
}

ShapePtr mesh([[maybe_unused]] geometry::MeshData data) {
#ifdef SNELL_HAS_MESH
  return std::make_shared<geometry::Mesh>(std::move(data));
#else
  unavailable("mesh");
#endif
}

ShapePtr blob([[maybe_unused]] double threshold,
              [[maybe_unused]] std::vector<geometry::BlobComponent> components) {
#ifdef SNELL_HAS_BLOB
  return std::make_shared<geometry::Blob>(threshold, std::move(components));
#else
  unavailable("blob");
#endif
}

}  // namespace snell::sdl::shapes
