#include "snell/accel/box_lanes.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "accel_test_support.hpp"

namespace snell::accel_test {
namespace {

// The lane test must pass exactly the boxes the scalar slab test passes (the list's culling is then the
// scalar one), for rays along axes (zero direction components), rays starting on a box face, and windows
// that end inside boxes; the padding of the last chunk is never entered.
TEST(BoxLanesTest, EnteredMatchesScalarSlabTest) {
  math::Pcg32 rng(17);
  std::vector<math::Bounds3> boxes;
  for (int i = 0; i < 23; ++i) {  // not a multiple of the chunk: the last one is padded
    const Vec3 c = uniform_vec(rng, -5, 5), h = uniform_vec(rng, 0.1, 2);
    boxes.push_back({c - h, c + h});
  }
  const accel::BoxLanes lanes(boxes);
  ASSERT_EQ(lanes.chunks(), 6u);
  int entered_total = 0;
  for (int i = 0; i < 20000; ++i) {
    Vec3 d = uniform_vec(rng, -1, 1);
    if (i % 7 == 0) d[i % 3] = 0;
    if (i % 11 == 0) d = Vec3(0, 0, i % 2 ? 1.0 : -1.0);
    Vec3 o = uniform_vec(rng, -8, 8);
    if (i % 13 == 0) o.x = boxes[static_cast<size_t>(i) % boxes.size()].lo.x;  // on a face
    const math::Ray ray{o, d, 0};
    const double t0 = i % 3 ? 0.0 : uniform(rng, 0, 4);
    const double t1 = i % 5 ? math::kInfinity : t0 + uniform(rng, 0, 6);
    const geometry::RayBox box_ray(ray);
    for (size_t chunk = 0; chunk < lanes.chunks(); ++chunk) {
      const std::uint32_t bits = lanes.entered(box_ray, chunk, t0, t1);
      for (size_t k = 0; k < accel::BoxLanes::kChunk; ++k) {
        const size_t b = chunk * accel::BoxLanes::kChunk + k;
        const bool lane = (bits >> k) & 1;
        if (b >= boxes.size()) {
          EXPECT_FALSE(lane) << "padding box " << b << " entered by ray " << i;
          continue;
        }
        EXPECT_EQ(lane, box_ray.hits(boxes[b], t0, t1)) << "box " << b << " ray " << i;
        entered_total += lane;
      }
    }
  }
  EXPECT_GT(entered_total, 2000);  // the test sees both outcomes often (4,030 entered of 460,000)
}

}  // namespace
}  // namespace snell::accel_test
