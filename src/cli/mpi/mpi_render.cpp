// The tile queue over MPI ranks (distributed.hpp). Messages, all on MPI_COMM_WORLD:
//   worker -> 0  kRequest  (no data)               asks for a tile
//   0 -> worker  kAssign   int tile index, or -1    the tile, or "no more"
//   worker -> 0  kHeader   int index x0 y0 x1 y1    a finished tile ...
//   worker -> 0  kPixels   float RGB, row by row    ... and its pixels (same sender: MPI keeps their order)
//   worker -> 0  kDone     uint64 ray counters[5]   the worker has stopped; its statistics
// Rank 0 polls with MPI_Iprobe and short sleeps rather than a blocking receive, which in Open MPI spins and
// would take a core from rank 0's own render thread.
#include <array>
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include "cli/distributed.hpp"
#include "cli/mpi/mpi_transport.hpp"

namespace snell::cli::distributed {

namespace {

enum Tag : int { kRequest = 1, kAssign = 2, kHeader = 3, kPixels = 4, kDone = 5 };
constexpr int kNoMoreTiles = -1;

using Counters = std::array<uint64_t, 5>;

Counters pack(const render::RenderStats& s) {
  return {s.rays.camera, s.rays.reflected, s.rays.refracted, s.rays.shadow, s.supersampled_pixels};
}

void add(render::RenderStats& s, const Counters& c) {
  s.rays.camera += c[0];
  s.rays.reflected += c[1];
  s.rays.refracted += c[2];
  s.rays.shadow += c[3];
  s.supersampled_pixels += c[4];
}

std::vector<float> tile_pixels(const io::Image& image, const render::PixelRect& r) {
  std::vector<float> pixels;
  pixels.reserve(static_cast<size_t>(r.area()) * 3);
  for (int y = r.y0; y < r.y1; ++y)
    pixels.insert(pixels.end(), image.rgb.begin() + static_cast<std::ptrdiff_t>(image.index(r.x0, y)),
                  image.rgb.begin() + static_cast<std::ptrdiff_t>(image.index(r.x1 - 1, y) + 3));
  return pixels;
}

/// Ranks 1..N-1: ask rank 0 for tiles until it has none, send each finished one back.
render::RenderStats work(const Job& job, io::Image& image) {
  std::map<int, render::Tile> by_index;
  for (const render::Tile& t : job.tiles) by_index[t.index] = t;
  std::mutex mpi_lock;  // MPI_THREAD_SERIALIZED: one MPI call at a time
  bool exhausted = false;
  render::RenderOptions options = job.options;
  options.tile_source = [&]() -> std::optional<render::Tile> {
    std::lock_guard lock(mpi_lock);
    if (exhausted) return std::nullopt;
    mpi::send_empty(0, kRequest);
    int index = kNoMoreTiles;
    mpi::recv(&index, 1, 0, kAssign);
    const auto it = by_index.find(index);
    if (index == kNoMoreTiles || it == by_index.end()) {
      exhausted = true;
      return std::nullopt;
    }
    return it->second;
  };
  options.tile_done = [&](const render::Tile& t, const io::Image& img) {
    const std::vector<float> pixels = tile_pixels(img, t.rect);
    const int header[5] = {t.index, t.rect.x0, t.rect.y0, t.rect.x1, t.rect.y1};
    std::lock_guard lock(mpi_lock);
    mpi::send(header, 5, 0, kHeader);
    mpi::send(pixels.data(), static_cast<int>(pixels.size()), 0, kPixels);
  };
  render::RenderStats stats = render::Renderer(job.scene, job.accelerator, options).render_into(image);
  const Counters counters = pack(stats);
  mpi::send(counters.data(), static_cast<int>(counters.size()), 0, kDone);
  return stats;
}

/// Rank 0: serve the queue to the other ranks and to its own render thread, gather the pixels.
render::RenderStats lead(const Job& job, io::Image& image) {
  std::mutex queue_mutex;
  size_t next = 0;
  bool closed = false;  // no tile is handed out after an interruption
  auto take = [&]() -> std::optional<render::Tile> {
    std::lock_guard lock(queue_mutex);
    if (closed || next >= job.tiles.size()) return std::nullopt;
    return job.tiles[next++];
  };

  render::RenderStats local;
  std::thread local_render([&] { local = render_local(job, image, take); });

  render::RenderStats total;
  const int workers = size() - 1;
  int done = 0;
  while (done < workers) {
    if (job.options.cancel && job.options.cancel->load()) {
      std::lock_guard lock(queue_mutex);
      closed = true;
    }
    const mpi::Waiting message = mpi::probe_any();
    if (!message.ready) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      continue;
    }
    const int from = message.from;
    if (message.tag == kRequest) {
      mpi::recv_empty(from, kRequest);
      const std::optional<render::Tile> tile = take();
      const int index = tile ? tile->index : kNoMoreTiles;
      mpi::send(&index, 1, from, kAssign);
    } else if (message.tag == kHeader) {
      int h[5];
      mpi::recv(h, 5, from, kHeader);
      const render::Tile tile{h[0], {h[1], h[2], h[3], h[4]}};
      std::vector<float> pixels(static_cast<size_t>(tile.rect.area()) * 3);
      mpi::recv(pixels.data(), static_cast<int>(pixels.size()), from, kPixels);
      size_t k = 0;
      for (int y = tile.rect.y0; y < tile.rect.y1; ++y)
        for (int x = tile.rect.x0; x < tile.rect.x1; ++x, k += 3) {
          image.set(x, y, {pixels[k], pixels[k + 1], pixels[k + 2]});
          image.set_alpha(x, y, 1.0f);
        }
      ++total.tiles_rendered;
      job.tile_done(tile);
    } else if (message.tag == kDone) {
      Counters c{};
      mpi::recv(c.data(), static_cast<int>(c.size()), from, kDone);
      add(total, c);
      ++done;
    } else {
      mpi::recv_empty(from, message.tag);
    }
  }
  local_render.join();
  add(total, pack(local));
  total.tiles_rendered += local.tiles_rendered;
  total.cancelled = job.options.cancel && job.options.cancel->load();
  return total;
}

}  // namespace

render::RenderStats render(const Job& job, io::Image& image) {
  if (size() == 1) return render_alone(job, image);  // no mpirun: no queue, no second thread
  return rank() == 0 ? lead(job, image) : work(job, image);
}

}  // namespace snell::cli::distributed
