#pragma once
// The resume file of an interrupted or checkpointed render (issue 12): which tiles are finished and their
// linear pixels, tied to one scene and set of flags by a fingerprint. `+C` / `--continue` reads it and
// renders only the other tiles; tiles are self-contained (renderer.cpp), so the result equals an
// uninterrupted render.
//
// Layout (little-endian): "SNELLRSM", u32 format version, u64 fingerprint, i32 width, i32 height, u32 tile
// count, then per tile: i32 index, i32 x0 y0 x1 y1, and (x1-x0)*(y1-y0)*3 float RGB values, row by row.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "snell/io/image.hpp"
#include "snell/render/tiles.hpp"

namespace snell::render {

class ResumeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ResumeData {
  uint64_t fingerprint = 0;
  /// Full-size image whose coverage channel marks the finished tiles' pixels.
  io::Image image;
  std::vector<Tile> tiles;
};

/// Writes the given finished tiles of `image` (temporary file, then rename). Throws ResumeError.
void write_resume_file(const std::filesystem::path& path, uint64_t fingerprint, const io::Image& image,
                       const std::vector<Tile>& tiles);

/// Reads and checks a resume file: well formed, the same fingerprint and image size, tiles inside the
/// image and in its tiling. Throws ResumeError with the reason.
ResumeData read_resume_file(const std::filesystem::path& path, uint64_t fingerprint, int width, int height);

/// FNV-1a, 64 bits: the fingerprint's hash. Not cryptographic; it tells a changed scene or flag from
/// the one a resume file was made for.
class Fnv1a {
 public:
  void add(const void* data, size_t size);
  void add(const std::string& text);
  template <typename T>
  void add_value(const T& value) {
    add(&value, sizeof value);
  }
  uint64_t value() const { return hash_; }

 private:
  uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace snell::render
