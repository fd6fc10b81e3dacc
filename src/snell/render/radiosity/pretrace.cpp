// The pretrace (POV-Ray 3.7 reference, "pretrace_start, pretrace_end"; behaviour of
// source/backend/render/radiositytask.cpp): passes over the image at a spacing of pretrace_start x the
// larger image side, halved each pass down to pretrace_end (at least one pixel), tracing one jittered
// camera ray per cell so that the cache fills from coarse to fine before the final pass.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include "snell/math/pcg32.hpp"
#include "snell/render/radiosity/solver.hpp"

namespace snell::render::radiosity {

void Solver::pretrace(int width, int height, const PixelRect& region, const CameraPoint& trace_point) {
  const double larger = std::max(width, height);
  const double end = std::max(1.0, larger * settings_.pretrace_end);
  const double start = std::max(end, larger * settings_.pretrace_start);
  const std::vector<Tile> tiles = make_tiles(width, height, region);
  for (int pass = 0;; ++pass) {
    const double spacing = std::max(start * std::ldexp(1.0, -pass), end);
    std::vector<TileRecords> found(tiles.size());
    std::vector<uint64_t> rays(tiles.size(), 0);
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
          for (size_t i = r.begin(); i != r.end(); ++i) {
            const PixelRect& t = tiles[i].rect;
            TraceContext context;
            context.radiosity_tile = empty_tile(false);
            // Cells start on multiples of the spacing, so a cell belongs to the tile its corner lies in.
            const double jitter = std::min(1.0, spacing / 2);
            for (double y = std::ceil((t.y0 - 0.5) / spacing) * spacing; y < t.y1; y += spacing)
              for (double x = std::ceil((t.x0 - 0.5) / spacing) * spacing; x < t.x1; x += spacing) {
                // Jitter seeded by pass and cell, the same in every run.
                context.rng.seed(math::mix_seed(static_cast<uint64_t>(pass), std::bit_cast<uint64_t>(x),
                                                std::bit_cast<uint64_t>(y), 0x7ad105e7ULL),
                                 0x3c6ef372fe94f82bULL);
                const double jx = jitter * (2 * context.rng.next_double() - 1);
                const double jy = jitter * (2 * context.rng.next_double() - 1);
                const double px = std::clamp(x + spacing / 2 + jx, 0.0, width - 1e-9);
                const double py = std::clamp(y + spacing / 2 + jy, 0.0, height - 1e-9);
                trace_point(px / width, py / height, context);
              }
            found[i] = std::move(context.radiosity_tile);
            rays[i] = context.counters.total();
          }
        });
    merge(found);
    ++pretrace_passes_;
    for (const uint64_t n : rays) pretrace_rays_ += n;
    if (spacing <= end) break;
  }
}

}  // namespace snell::render::radiosity
