// Normals that set the bent normal themselves (texture/facets.hpp, texture/bump_map.hpp; behaviour of
// POV-Ray's normal.cpp facets() and imageutil.cpp bump_map()).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "pattern_point.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/texture/bump_map.hpp"
#include "snell/texture/facets.hpp"
#include "snell/texture/pattern_normal.hpp"
#include "snell/texture/povray_noise.hpp"

using namespace snell::texture;
using snell::math::Vec3;
using snell::texture::test::at;

namespace {

NormalSpec spec_of(std::shared_ptr<const ValuePattern> pattern, double bump_size = 0.5) {
  NormalSpec spec;
  spec.pattern = std::move(pattern);
  spec.bump_size = bump_size;
  return spec;
}

/// A 4x1 grey image with heights 0, 0.25, 0.5, 0.75 from left to right, repeated.
std::shared_ptr<const ImageMapPigment> ramp_image() {
  auto image = std::make_shared<snell::io::Image>(4, 1);
  for (int x = 0; x < 4; ++x)
    for (int c = 0; c < 3; ++c) image->rgb[image->index(x, 0) + c] = 0.25f * x;
  ImageMapSpec spec;
  spec.image = image;
  return std::make_shared<ImageMapPigment>(spec);
}

}  // namespace

TEST(FacetsTest, NormalsStayUnitLengthAndQuantised) {
  snell::math::Pcg32 rng(5);
  const PatternNormal facets(spec_of(std::make_shared<FacetsPattern>()));
  for (int i = 0; i < 200; ++i) {
    const Vec3 n = normalize(Vec3{rng.next_double() - 0.5, rng.next_double() - 0.5, rng.next_double() - 0.5});
    const Vec3 bent = facets.perturb(n, at({rng.next_double(), rng.next_double(), rng.next_double()}));
    EXPECT_NEAR(length(bent), 1.0, 1e-12);
    // Size 0.1 snaps n*10 to a random point within about two cells: the facet stays near n.
    EXPECT_GT(dot(bent, n), 0.9);
  }
}

TEST(FacetsTest, NearbyNormalsShareAFacet) {
  // Without coords the bent normal depends only on the normal: a small change keeps the same facet.
  const PatternNormal facets(spec_of(std::make_shared<FacetsPattern>()));
  const Vec3 n = normalize(Vec3{0.3, 0.8, -0.2});
  const Vec3 a = facets.perturb(n, at({0, 0, 0}));
  const Vec3 b = facets.perturb(n, at({5, -3, 2}));
  EXPECT_NEAR(length(a - b), 0, 1e-12);
}

TEST(FacetsTest, CoordsTiltsByATangentNoiseVector) {
  FacetsParams params;
  params.coords = 0.5;
  params.size = 1;
  const PatternNormal facets(spec_of(std::make_shared<FacetsPattern>(params)));
  snell::math::Pcg32 rng(8);
  for (int i = 0; i < 100; ++i) {
    const Vec3 p{rng.next_double() * 5, rng.next_double() * 5, rng.next_double() * 5};
    const Vec3 bent = facets.perturb({0, 1, 0}, at(p));
    EXPECT_NEAR(length(bent), 1.0, 1e-12);
    EXPECT_GT(bent.y, 0.5);  // a tangent tilt of at most |coords| * |noise| keeps the normal up
  }
}

TEST(FacetsTest, NearestPointIsTheNearestOfTheNeighbourCells) {
  const FacetsPattern facets;
  snell::math::Pcg32 rng(3);
  for (int i = 0; i < 30; ++i) {
    const Vec3 q{rng.next_double() * 10, rng.next_double() * 10, rng.next_double() * 10};
    const Vec3 found = facets.nearest_point(q);
    // Brute force over a 7x7x7 block of cells.
    double best = 1e9;
    for (int dx = -3; dx <= 3; ++dx)
      for (int dy = -3; dy <= 3; ++dy)
        for (int dz = -3; dz <= 3; ++dz) {
          const Vec3 c = povray_point_in_cube(static_cast<int>(std::floor(q.x)) + dx,
                                              static_cast<int>(std::floor(q.y)) + dy,
                                              static_cast<int>(std::floor(q.z)) + dz);
          best = std::min(best, length(c - q));
        }
    EXPECT_NEAR(length(found - q), best, 1e-12);
  }
}

TEST(BumpMapTest, FlatImageKeepsTheNormal) {
  auto image = std::make_shared<snell::io::Image>(2, 2);
  ImageMapSpec spec;
  spec.image = image;
  const PatternNormal bumps(
      spec_of(std::make_shared<BumpMapPattern>(std::make_shared<ImageMapPigment>(spec)), 3));
  const Vec3 n = bumps.perturb({0, 0, -1}, at({0.3, 0.6, 0}));
  EXPECT_NEAR(n.x, 0, 1e-12);
  EXPECT_NEAR(n.y, 0, 1e-12);
  EXPECT_NEAR(n.z, -1, 1e-12);
}

TEST(BumpMapTest, RampTiltsByThePixelStep) {
  // Heights rise by bump_size * 0.25 per pixel to the right; the triangle (0,h,0), (-1,h-s,1), (1,h+s,1)
  // has normal (-s, 1, 0)/|.| in POV-Ray's frame, whose x axis for the normal -z is n x y = +x.
  const double bump_size = 2, step = bump_size * 0.25;
  const PatternNormal bumps(spec_of(std::make_shared<BumpMapPattern>(ramp_image()), bump_size));
  const Vec3 n = bumps.perturb({0, 0, -1}, at({0.375, 0.5, 0}));  // pixel 1 of 4
  const Vec3 expected = normalize(Vec3{-step, 0, -1});
  EXPECT_NEAR(n.x, expected.x, 1e-6);
  EXPECT_NEAR(n.y, expected.y, 1e-6);
  EXPECT_NEAR(n.z, expected.z, 1e-6);
  EXPECT_NEAR(length(n), 1.0, 1e-12);
}
