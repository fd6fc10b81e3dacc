// Anti-aliasing's two passes (first_sample_grid.hpp, two_pass_queue.hpp): each first sample a tile reads is
// traced once, the work order respects what each second pass reads, and the image equals that of tiles that
// trace their own borders.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "scene_builder.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/render/first_sample_grid.hpp"
#include "snell/render/renderer.hpp"
#include "snell/render/tiles.hpp"
#include "snell/render/two_pass_queue.hpp"

namespace snell::render {
namespace {

/// The tiles of the whole 100 x 70 image whose index has `parity`.
std::vector<Tile> tiles_of_parity(int parity) {
  std::vector<Tile> tiles;
  for (const Tile& t : make_tiles(100, 70, {0, 0, 100, 70}))
    if (t.index % 2 == parity) tiles.push_back(t);
  return tiles;
}

TEST(FirstSampleGridTest, EverySampleATileReadsIsTracedOnceByATileItNeeds) {
  // A checkerboard of a 4 x 3 tiling: no tile's left or top neighbour is in the batch, and the corner of a
  // missing tile is the border of two tiles of the batch (the one below it and the one to its right).
  std::vector<Tile> batch;
  for (const Tile& t : make_tiles(100, 70, {0, 0, 100, 70}))
    if ((t.index % 4 + t.index / 4) % 2 == 0) batch.push_back(t);
  const FirstSampleGrid grid(batch, 100, 70);
  std::map<std::pair<int, int>, size_t> tracer;
  for (size_t i = 0; i < batch.size(); ++i)
    grid.for_each_owned(i, [&](int x, int y) { EXPECT_TRUE(tracer.emplace(std::pair{x, y}, i).second); });
  std::set<std::pair<int, int>> read;
  for (size_t i = 0; i < batch.size(); ++i) {
    const PixelRect b = full_tile_rect(batch[i].index, 100, 70);
    const std::vector<size_t> needs = grid.needs(i);
    EXPECT_EQ(needs.front(), i);
    auto check = [&](int x, int y) {
      read.insert({x, y});
      const auto it = tracer.find({x, y});
      ASSERT_NE(it, tracer.end()) << x << "," << y;
      EXPECT_NE(std::find(needs.begin(), needs.end(), it->second), needs.end()) << x << "," << y;
    };
    for (int x = b.x0; x < b.x1; ++x) check(x, b.y0 - 1);
    for (int y = b.y0; y < b.y1; ++y)
      for (int x = b.x0 - 1; x < b.x1; ++x) check(x, y);
  }
  EXPECT_EQ(tracer.size(), read.size());  // nothing traced that no tile reads
}

TEST(FirstSampleGridTest, NeighboursInTheBatchLendTheirSamples) {
  const std::vector<Tile> all = make_tiles(100, 70, {0, 0, 100, 70});
  const FirstSampleGrid grid(all, 100, 70);
  size_t traced = 0;
  for (size_t i = 0; i < all.size(); ++i) grid.for_each_owned(i, [&](int, int) { ++traced; });
  EXPECT_EQ(traced, 100u * 70u + 100u + 70u);
  // Tile 5 (second row, second column) reads tile 1 above it and tile 4 to its left.
  EXPECT_EQ(grid.needs(5), (std::vector<size_t>{5, 1, 4}));
}

TEST(FirstSampleGridTest, BatchesAreWholeRowsOfTilesWithinThePixelBudget) {
  const std::vector<Tile> all = make_tiles(100, 70, {0, 0, 100, 70});  // rows of 3200, 3200, 600 pixels
  EXPECT_EQ(tile_batches(all, 100, 70, 1 << 20).size(), 1u);
  const auto two = tile_batches(all, 100, 70, 6400);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].size(), 8u);
  EXPECT_EQ(two[1].size(), 4u);
  EXPECT_EQ(tile_batches(all, 100, 70, 1000).size(), 3u);  // a row over the budget is a batch alone
}

TEST(TwoPassQueueTest, SecondPassesComeInOrderOnceTheirFirstPassesAreDone) {
  const std::vector<Tile> all = make_tiles(100, 70, {0, 0, 100, 70});
  const FirstSampleGrid grid(all, 100, 70);
  std::vector<std::vector<size_t>> needs;
  for (size_t i = 0; i < all.size(); ++i) needs.push_back(grid.needs(i));
  TwoPassQueue queue(needs);
  std::set<size_t> first_done;
  std::vector<size_t> seconds;
  for (;;) {
    const TwoPassQueue::Work work = queue.next();
    if (work.pass == TwoPassQueue::Work::Pass::none) break;
    if (work.pass == TwoPassQueue::Work::Pass::first) {
      EXPECT_TRUE(first_done.insert(work.tile).second);
      queue.first_done(work.tile);
    } else {
      for (const size_t j : needs[work.tile]) EXPECT_TRUE(first_done.count(j)) << work.tile << " needs " << j;
      seconds.push_back(work.tile);
    }
  }
  EXPECT_EQ(first_done.size(), all.size());
  ASSERT_EQ(seconds.size(), all.size());
  for (size_t i = 0; i < seconds.size(); ++i) EXPECT_EQ(seconds[i], i);
}

TEST(TwoPassQueueTest, AnAbandonedQueueHandsOutNothing) {
  TwoPassQueue queue({{0}, {1, 0}});
  EXPECT_EQ(queue.next().pass, TwoPassQueue::Work::Pass::first);
  queue.abandon();  // tile 0's first pass will never be done: no thread may wait for it
  EXPECT_EQ(queue.next().pass, TwoPassQueue::Work::Pass::none);
}

RenderOptions options(int threads) {
  RenderOptions o;
  o.width = 100;
  o.height = 70;
  o.antialias = true;
  o.jitter = true;
  o.seed = 5;
  o.threads = threads;
  return o;
}

TEST(TwoPassRenderTest, ImageEqualsTilesThatTraceTheirOwnBorders) {
  scene::Scene s = test::two_spheres();
  scene::Light& l = s.lights.front();
  l.area = l.jitter = true;  // random numbers in every sample
  l.axis1 = {2, 0, 0};
  l.axis2 = {0, 0, 2};
  l.size1 = l.size2 = 3;
  const auto accel = accel::make_accelerator("none", s);
  const RenderResult two_passes = Renderer(s, *accel, options(2)).render();
  // A tile source hands tiles out one by one: each traces its own border (distributed renders).
  const std::vector<Tile> all = make_tiles(100, 70, {0, 0, 100, 70});
  std::atomic<size_t> next{0};
  RenderOptions o = options(2);
  o.tile_source = [&]() -> std::optional<Tile> {
    const size_t i = next++;
    return i < all.size() ? std::optional<Tile>(all[i]) : std::nullopt;
  };
  const RenderResult self_contained = Renderer(s, *accel, o).render();
  EXPECT_EQ(two_passes.image.rgb, self_contained.image.rgb);
  EXPECT_LT(two_passes.rays.camera, self_contained.rays.camera);
  EXPECT_EQ(Renderer(s, *accel, options(1)).render().image.rgb, two_passes.image.rgb);
}

TEST(TwoPassRenderTest, AListOfTilesCompletesAnImageBegunByAnotherRun) {
  const scene::Scene s = test::two_spheres();
  const auto accel = accel::make_accelerator("none", s);
  const RenderResult whole = Renderer(s, *accel, options(2)).render();
  RenderOptions first = options(2), second = options(2);
  first.tiles = tiles_of_parity(0);
  second.tiles = tiles_of_parity(1);
  const Renderer a(s, *accel, first);
  io::Image image = a.blank_target();
  EXPECT_EQ(a.render_into(image).tiles_rendered, 6u);
  EXPECT_FALSE(image.fully_covered());
  EXPECT_EQ(Renderer(s, *accel, second).render_into(image).tiles_rendered, 6u);
  EXPECT_EQ(image.rgb, whole.image.rgb);
  EXPECT_TRUE(image.fully_covered());
  // An empty list (a resume file holding every tile) renders nothing.
  RenderOptions none = options(2);
  none.tiles = std::vector<Tile>{};
  const Renderer c(s, *accel, none);
  io::Image untouched = c.blank_target();
  const RenderStats stats = c.render_into(untouched);
  EXPECT_EQ(stats.tiles_rendered, 0u);
  EXPECT_EQ(stats.rays.total(), 0u);
}

}  // namespace
}  // namespace snell::render
