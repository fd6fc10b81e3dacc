// Tiles are the unit of partial, resumed and distributed renders: a region's pixels and a resumed render's
// pixels must equal those of one uninterrupted render of the whole image.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <optional>
#include <set>
#include <vector>

#include "scene_builder.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/render/renderer.hpp"
#include "snell/render/resume_file.hpp"
#include "snell/render/tiles.hpp"

namespace snell::render {
namespace {

RenderOptions options() {
  RenderOptions o;
  o.width = 100;  // not a multiple of the tile size: edge tiles are narrower
  o.height = 70;
  o.antialias = true;
  o.jitter = true;
  o.seed = 3;
  o.threads = 2;
  return o;
}

TEST(TilesTest, TilingCoversTheRegionOnceWithFullImageIndices) {
  const auto tiles = make_tiles(100, 70, {10, 20, 90, 50});
  int64_t area = 0;
  std::set<int> indices;
  for (const Tile& t : tiles) {
    area += t.rect.area();
    indices.insert(t.index);
    EXPECT_EQ(t.index, (t.rect.y0 / kTileSize) * tiles_across(100) + t.rect.x0 / kTileSize);
  }
  EXPECT_EQ(area, 80 * 30);
  EXPECT_EQ(indices.size(), tiles.size());
  EXPECT_EQ(tiles_across(100), 4);
  EXPECT_EQ(tiles_down(70), 3);
}

TEST(TilesTest, RegionPixelsEqualTheWholeRenderAndTheRestStaysUnrendered) {
  const scene::Scene s = test::two_spheres();
  const auto accel = accel::make_accelerator("none", s);
  const RenderResult whole = Renderer(s, *accel, options()).render();
  RenderOptions o = options();
  o.region = {13, 7, 61, 44};
  const RenderResult part = Renderer(s, *accel, o).render();
  for (int y = 0; y < 70; ++y)
    for (int x = 0; x < 100; ++x) {
      const bool inside = x >= 13 && x < 61 && y >= 7 && y < 44;
      ASSERT_EQ(part.image.alpha_at(x, y), inside ? 1.0f : 0.0f) << x << "," << y;
      if (inside) {
        ASSERT_EQ(part.image.at(x, y), whole.image.at(x, y)) << x << "," << y;
      }
    }
}

/// A tile source handing out, in order, the tiles of the whole 100 x 70 image whose index has `parity`.
std::function<std::optional<Tile>()> tiles_of_parity(int parity, std::vector<Tile>& storage,
                                                     std::atomic<size_t>& next) {
  for (const Tile& t : make_tiles(100, 70, {0, 0, 100, 70}))
    if (t.index % 2 == parity) storage.push_back(t);
  return [&storage, &next]() -> std::optional<Tile> {
    const size_t i = next++;
    if (i >= storage.size()) return std::nullopt;
    return storage[i];
  };
}

TEST(TilesTest, TilesFromASourceCompleteAnImageBegunByAnotherRun) {
  const scene::Scene s = test::two_spheres();
  const auto accel = accel::make_accelerator("none", s);
  const RenderResult whole = Renderer(s, *accel, options()).render();
  // First run: even tiles only; the second run renders the rest, as a resumed render does.
  std::vector<Tile> evens, odds;
  std::atomic<size_t> next_even{0}, next_odd{0};
  RenderOptions first = options();
  first.tile_source = tiles_of_parity(0, evens, next_even);
  const Renderer a(s, *accel, first);
  io::Image image = a.blank_target();
  a.render_into(image);
  RenderOptions second = options();
  second.tile_source = tiles_of_parity(1, odds, next_odd);
  std::mutex m;
  std::set<int> reported;
  second.tile_done = [&](const Tile& t, const io::Image&) {
    std::lock_guard lock(m);
    EXPECT_TRUE(reported.insert(t.index).second);
  };
  const RenderStats stats = Renderer(s, *accel, second).render_into(image);
  EXPECT_EQ(stats.tiles_rendered, reported.size());
  EXPECT_EQ(reported.size(), 6u);  // 12 tiles, the odd ones
  EXPECT_EQ(image.rgb, whole.image.rgb);
  EXPECT_TRUE(image.fully_covered());
}

TEST(TilesTest, CancelledRenderReportsItAndKeepsFinishedTiles) {
  const scene::Scene s = test::two_spheres();
  const auto accel = accel::make_accelerator("none", s);
  std::atomic<bool> cancel{false};
  RenderOptions o = options();
  o.threads = 1;
  o.cancel = &cancel;
  int done = 0;
  o.tile_done = [&](const Tile&, const io::Image&) {
    if (++done == 3) cancel = true;
  };
  const RenderResult r = Renderer(s, *accel, o).render();
  EXPECT_TRUE(r.cancelled);
  EXPECT_EQ(r.tiles_rendered, 3u);
  EXPECT_FALSE(r.image.fully_covered());
}

TEST(ResumeFileTest, RoundTripsTilesAndRejectsOtherFingerprints) {
  const scene::Scene s = test::two_spheres();
  const auto accel = accel::make_accelerator("none", s);
  const RenderResult whole = Renderer(s, *accel, options()).render();
  const auto path = std::filesystem::temp_directory_path() / "snell_resume_test.snell-resume";
  const auto tiles = make_tiles(100, 70, {0, 0, 100, 70});
  const std::vector<Tile> some(tiles.begin(), tiles.begin() + 5);
  write_resume_file(path, 42, whole.image, some);
  const ResumeData data = read_resume_file(path, 42, 100, 70);
  ASSERT_EQ(data.tiles.size(), 5u);
  for (const Tile& t : some)
    for (int y = t.rect.y0; y < t.rect.y1; ++y)
      for (int x = t.rect.x0; x < t.rect.x1; ++x) {
        ASSERT_EQ(data.image.at(x, y), whole.image.at(x, y));
        ASSERT_EQ(data.image.alpha_at(x, y), 1.0f);
      }
  EXPECT_EQ(data.image.alpha_at(99, 69), 0.0f);
  EXPECT_THROW(read_resume_file(path, 43, 100, 70), ResumeError);
  EXPECT_THROW(read_resume_file(path, 42, 101, 70), ResumeError);
  // Truncated and foreign files are clear errors, never a crash.
  std::filesystem::resize_file(path, 60);
  EXPECT_THROW(read_resume_file(path, 42, 100, 70), ResumeError);
  std::ofstream(path, std::ios::trunc) << "not a resume file";
  EXPECT_THROW(read_resume_file(path, 42, 100, 70), ResumeError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace snell::render
