// The tiles this process renders itself: the whole job in a single process, rank 0's share in a distributed
// render (distributed.hpp). Built with and without MPI.
#include <atomic>

#include "cli/distributed.hpp"

namespace snell::cli::distributed {

render::RenderStats render_local(const Job& job, io::Image& image, const TileSource& next_tile) {
  render::RenderOptions options = job.options;
  options.tile_source = next_tile;
  options.tile_done = [&job](const render::Tile& t, const io::Image&) { job.tile_done(t); };
  return render::Renderer(job.scene, job.accelerator, options).render_into(image);
}

render::RenderStats render_alone(const Job& job, io::Image& image) {
  std::atomic<size_t> next{0};
  return render_local(job, image, [&job, &next]() -> std::optional<render::Tile> {
    const size_t i = next++;
    if (i >= job.tiles.size()) return std::nullopt;
    return job.tiles[i];
  });
}

}  // namespace snell::cli::distributed
