#pragma once
// The light each source sends to the surface point being shaded, after its shadow test, kept while that
// point is shaded: the layers of a layered texture, the two entries of a texture map between which the
// point falls and the entries of an averaged texture are all lit at the same point, and POV-Ray tests
// each light's shadow there once for all of them (trace.cpp: ComputeTextureColour opens a level of
// lightColorCache, ComputeOneDiffuseLight fills and reads it). wood_1.pov's two-layer woods traced twice
// the shadow rays of POV-Ray's render before this.
//
// Frames nest as shading does (a reflection shades another point before the first is done), so entries
// are addressed by frame and light index, never by reference: a nested frame may grow the storage.
#include <cstddef>
#include <vector>

#include "snell/math/color.hpp"

namespace snell::render {

class LitLights {
 public:
  /// Opens a frame of `lights` untested entries; returns its number for lookup() and close().
  int open(size_t lights) {
    const int frame = depth_++;
    const size_t need = static_cast<size_t>(depth_) * lights;
    if (entries_.size() < need) entries_.resize(need);
    for (size_t i = 0; i < lights; ++i) entries_[static_cast<size_t>(frame) * lights + i].tested = false;
    lights_ = lights;
    return frame;
  }
  void close() { --depth_; }
  /// The frame opened last and not closed; -1 when none is open.
  int innermost() const { return depth_ - 1; }

  struct Entry {
    bool tested = false;
    math::Color colour;
  };
  /// The entry of light `index` in `frame`; valid until the next open().
  Entry& lookup(int frame, size_t index) { return entries_[static_cast<size_t>(frame) * lights_ + index]; }

 private:
  std::vector<Entry> entries_;
  size_t lights_ = 0;
  int depth_ = 0;
};

/// Opens a frame for the lifetime of a shading call.
class LitLightsFrame {
 public:
  LitLightsFrame(LitLights& lit, size_t lights) : lit_(lit), frame_(lit.open(lights)) {}
  ~LitLightsFrame() { lit_.close(); }
  LitLightsFrame(const LitLightsFrame&) = delete;
  LitLightsFrame& operator=(const LitLightsFrame&) = delete;
  int frame() const { return frame_; }

 private:
  LitLights& lit_;
  int frame_;
};

}  // namespace snell::render
