#pragma once
// Keeps the list of finished tiles of a render and writes the resume file (render/resume_file.hpp): every
// `interval` seconds while rendering (`--checkpoint`), and once more when the render is interrupted.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <vector>

#include "snell/io/image.hpp"
#include "snell/render/tiles.hpp"

namespace snell::cli {

/// The resume file of the render writing `output`: `out.png.snell-resume`.
std::filesystem::path resume_path(const std::filesystem::path& output);

class Checkpoint {
 public:
  /// `image` is the render target; `done` the tiles it already holds (from a resume file).
  Checkpoint(std::filesystem::path path, uint64_t fingerprint, const io::Image& image,
             std::vector<render::Tile> done, double interval_seconds);

  /// Called by the renderer as each tile finishes (from any worker thread).
  void tile_done(const render::Tile& tile);
  /// Writes the resume file now. Throws render::ResumeError.
  void save();
  /// Removes the resume file (the render finished).
  void remove() const;
  const std::filesystem::path& path() const { return path_; }

 private:
  void save_locked();

  std::filesystem::path path_;
  uint64_t fingerprint_;
  const io::Image& image_;
  std::vector<render::Tile> done_;
  double interval_;
  std::chrono::steady_clock::time_point last_save_;
  std::mutex mutex_;
};

}  // namespace snell::cli
