// The irradiance cache (render/radiosity/record_grid.hpp, solver.hpp): POV-Ray's reuse rule (radiosity.cpp,
// AverageNearBlock) reuses a record exactly inside its validity radius, the grid finds every record a
// brute-force search finds, and cached renders converge to the gathered-everywhere answer and do not
// depend on the thread count.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_builder.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/memory/budget.hpp"
#include "snell/render/radiosity/record_grid.hpp"
#include "snell/render/renderer.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;
using radiosity::Record;
using radiosity::ReuseQuery;

Record flat_record(double harmonic_mean) {
  Record r;
  r.point = {0, 0, 0};
  r.normal = {0, 0, 1};
  r.to_nearest = {0, 0, 1};  // straight up: no shrinking along the surface
  r.nearest_distance = harmonic_mean;
  r.harmonic_mean = harmonic_mean;
  r.irradiance = Color(1);
  return r;
}

TEST(RadiosityCacheTest, RecordIsReusedExactlyInsideItsValidityRadius) {
  // Same normal: error = distance / R, reusable while below the error bound a, i.e. within R a.
  const Record r = flat_record(2);
  const double a = 0.5;  // validity radius 1
  EXPECT_GT(radiosity::reuse_weight(r, ReuseQuery{{0.999, 0, 0}, {0, 0, 1}, a, false}), 0);
  EXPECT_EQ(radiosity::reuse_weight(r, ReuseQuery{{1.001, 0, 0}, {0, 0, 1}, a, false}), 0);
  EXPECT_GT(radiosity::reuse_weight(r, ReuseQuery{{0, -0.7, 0.0}, {0, 0, 1}, a, false}), 0);
  EXPECT_EQ(radiosity::reuse_weight(r, ReuseQuery{{0.8, -0.7, 0.0}, {0, 0, 1}, a, false}), 0);
  // Linear fall-off 1 - error / a in the pretrace, POV-Ray's pseudo-sigmoid in the final pass.
  EXPECT_NEAR(radiosity::reuse_weight(r, ReuseQuery{{0.5, 0, 0}, {0, 0, 1}, a, false}), 0.5, 1e-12);
  EXPECT_NEAR(radiosity::reuse_weight(r, ReuseQuery{{0.25, 0, 0}, {0, 0, 1}, a, true}), 1 - 2 * 0.25 * 0.25,
              1e-12);
  EXPECT_NEAR(radiosity::reuse_weight(r, ReuseQuery{{0.75, 0, 0}, {0, 0, 1}, a, true}), 2 * 0.25 * 0.25,
              1e-12);
}

TEST(RadiosityCacheTest, NormalAngleCountsTwiceRootOneMinusCosine) {
  // At the record's point a tilted normal costs 2 sqrt(1 - cos(theta)): with a = 0.5 the limit is
  // cos(theta) = 1 - 1/16.
  const Record r = flat_record(1);
  auto tilted = [](double cos_theta) { return Vec3(std::sqrt(1 - cos_theta * cos_theta), 0, cos_theta); };
  EXPECT_GT(radiosity::reuse_weight(r, ReuseQuery{{0, 0, 0}, tilted(1 - 1.0 / 16 + 1e-4), 0.5, false}), 0);
  EXPECT_EQ(radiosity::reuse_weight(r, ReuseQuery{{0, 0, 0}, tilted(1 - 1.0 / 16 - 1e-4), 0.5, false}), 0);
}

TEST(RadiosityCacheTest, RecordInFrontOfThePointIsNotReused) {
  // A record 0.2 above the query's surface could be shadowing it (Ward 1988's "in front" test).
  const Record r = flat_record(2);
  EXPECT_EQ(radiosity::reuse_weight(r, ReuseQuery{{0.1, 0, -0.2}, {0, 0, 1}, 1.0, false}), 0);
  EXPECT_GT(radiosity::reuse_weight(r, ReuseQuery{{0.1, 0, 0.2}, {0, 0, 1}, 1.0, false}), 0);
}

TEST(RadiosityCacheTest, NearestSurfaceShrinksTheReachTowardsIt) {
  // Nearest hit 0.1 away along +x: towards it the radius blends to 0.1, away from it stays 2.
  Record r = flat_record(2);
  r.to_nearest = {1, 0, 0};
  r.nearest_distance = 0.1;
  EXPECT_EQ(radiosity::reuse_weight(r, ReuseQuery{{0.2, 0, 0}, {0, 0, 1}, 1.0, false}), 0);
  EXPECT_GT(radiosity::reuse_weight(r, ReuseQuery{{-0.2, 0, 0}, {0, 0, 1}, 1.0, false}), 0);
}

TEST(RadiosityCacheTest, GridFindsWhatABruteForceSearchFinds) {
  math::Pcg32 rng;
  rng.seed(12345, 1);
  const double bound = 1.5;
  radiosity::RecordGrid grid(bound);
  std::vector<Record> all;
  for (int i = 0; i < 400; ++i) {
    Record r = flat_record(std::exp(4 * rng.next_double() - 3));  // radii 0.05 .. 2.7
    r.point = {10 * rng.next_double() - 5, 10 * rng.next_double() - 5, 0.3 * rng.next_double()};
    r.irradiance = Color(rng.next_double());
    grid.insert(r);
    all.push_back(r);
  }
  for (int q = 0; q < 300; ++q) {
    const ReuseQuery query{
        {10 * rng.next_double() - 5, 10 * rng.next_double() - 5, 0.3}, {0, 0, 1}, bound, true};
    radiosity::Blend from_grid, brute;
    grid.gather(query, from_grid);
    for (const Record& r : all)
      if (const double w = radiosity::reuse_weight(r, query); w > 0) brute.add(r, w);
    EXPECT_NEAR(from_grid.weight, brute.weight, 1e-9);
    EXPECT_NEAR(from_grid.weighted.r, brute.weighted.r, 1e-9);
  }
}

/// A red sphere on a grey floor lit from above: colour bleeds onto the floor, shadows get indirect light.
scene::Scene sphere_on_floor(int count, double error_bound) {
  scene::Scene s;
  material::Finish f;
  f.diffuse = 0.7;
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(0, 1, 0), 1.0),
                                   test::texture({Color(1, 0.2, 0.1)}, f)));
  s.objects.push_back(
      test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), 0.0), test::texture({Color(0.8)}, f)));
  s.lights.push_back(test::point_light({3, 6, -3}));
  s.background.rgb = Color(0.4, 0.5, 0.7);
  s.camera.location = {0, 2.5, -5};
  s.camera.direction = {0, -0.35, 1};  // right x up = direction (left-handed)
  s.camera.right = {1.33, 0, 0};
  s.camera.up = {0, 1, 0.35};
  scene::RadiositySettings r;
  r.count = count;
  r.error_bound = error_bound;
  r.recursion_limit = 1;
  s.settings.radiosity = r;
  return s;
}

RenderResult render(const scene::Scene& s, int width, int height, int threads) {
  const auto accel = accel::make_accelerator("none", s);
  RenderOptions o;
  o.width = width;
  o.height = height;
  o.threads = threads;
  return Renderer(s, *accel, o).render();
}

double psnr(const io::Image& a, const io::Image& b) {
  double sum = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const Color d = a.at(x, y) - b.at(x, y);
      sum += d.r * d.r + d.g * d.g + d.b * d.b;
    }
  const double mse = sum / (3.0 * a.width * a.height);
  return 10 * std::log10(1 / mse);
}

TEST(RadiosityCacheTest, CachedImageConvergesToGatheringEverywhere) {
  // A vanishing error bound reuses nothing, so every point gathers: the reference. The cache at a tight
  // bound stays close to it, and closer than at a loose bound.
  const int w = 48, h = 36;
  const RenderResult reference = render(sphere_on_floor(200, 1e-6), w, h, 2);
  const RenderResult tight = render(sphere_on_floor(200, 0.3), w, h, 2);
  const RenderResult loose = render(sphere_on_floor(200, 3), w, h, 2);
  const double tight_psnr = psnr(tight.image, reference.image),
               loose_psnr = psnr(loose.image, reference.image);
  RecordProperty("tight_psnr", std::to_string(tight_psnr));
  RecordProperty("loose_psnr", std::to_string(loose_psnr));
  EXPECT_GT(tight_psnr, 42);
  EXPECT_GT(tight_psnr, loose_psnr);
  // The cache saves work: far fewer rays than gathering at every point.
  EXPECT_LT(tight.rays.total() * 2, reference.rays.total());
}

TEST(RadiosityCacheTest, SameImageForOneTwoAndThreeThreads) {
  scene::Scene s = sphere_on_floor(40, 1.8);
  s.settings.radiosity->recursion_limit = 2;
  const int w = 70, h = 50;  // several tiles
  const RenderResult one = render(s, w, h, 1);
  const RenderResult two = render(s, w, h, 2);
  const RenderResult three = render(s, w, h, 3);
  EXPECT_FALSE(one.integrator_summary.empty());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      ASSERT_EQ(one.image.at(x, y), two.image.at(x, y)) << x << "," << y;
      ASSERT_EQ(one.image.at(x, y), three.image.at(x, y)) << x << "," << y;
    }
}

TEST(RadiosityCacheTest, CacheStopsGrowingAtTheMemoryLimit) {
  // --max-memory: the cache is charged record by record; past the limit it stops growing (the render
  // goes on, gathering where records are missing) and gives everything back at the end.
  scene::Scene s = sphere_on_floor(20, 1.8);
  s.memory_budget = std::make_shared<memory::Budget>(8192);
  const RenderResult r = render(s, 40, 30, 2);
  EXPECT_NE(r.integrator_summary.find("stopped at --max-memory"), std::string::npos) << r.integrator_summary;
  EXPECT_LE(s.memory_budget->peak(), 8192u);
  EXPECT_GT(s.memory_budget->peak(), 0u);
  EXPECT_EQ(s.memory_budget->used(), 0u);
}

}  // namespace
}  // namespace snell::render
