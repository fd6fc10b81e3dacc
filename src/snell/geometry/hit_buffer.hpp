#pragma once
// A few candidate crossings of one ray with a convex-ish shape (box, cylinder, cone, torus), filtered to
// (t_min, t_max) and kept sorted, so that `intersect` and `all_hits` share one code path; NearestBuffer is
// the same interface for `intersect` alone.
#include <array>
#include <utility>

#include "snell/geometry/shape.hpp"

namespace snell::geometry {

template <int N>
class HitBuffer {
 public:
  HitBuffer(double t_min, double t_max) : t_min_(t_min), t_max_(t_max) {}

  /// Whether a crossing at t would be kept (lets callers skip computing the normal).
  bool accepts(double t) const { return t > t_min_ && t < t_max_ && size_ < N; }
  void add(const LocalHit& hit) {
    if (accepts(hit.t)) hits_[size_++].hit = hit;
  }
  void sort() {
    // Insertion sort: at most N elements (std::sort trips GCC's -Warray-bounds on tiny arrays).
    for (int i = 1; i < size_; ++i) {
      for (int j = i; j > 0 && hits_[j].hit.t < hits_[j - 1].hit.t; --j)
        std::swap(hits_[j].hit, hits_[j - 1].hit);
    }
  }
  double t_min() const { return t_min_; }
  double t_max() const { return t_max_; }
  int size() const { return size_; }
  const LocalHit& operator[](int i) const { return hits_[i].hit; }

  /// Sorts, then the nearest kept crossing.
  bool nearest(LocalHit& hit) {
    if (size_ == 0) return false;
    sort();
    hit = hits_[0].hit;
    return true;
  }
  void append_sorted(HitList& out) {
    sort();
    for (int i = 0; i < size_; ++i) out.push_back(hits_[i].hit);
  }

 private:
  double t_min_, t_max_;
  // A slot holds a hit only once add writes it: the buffer clears nothing when made (four default hits
  // were a 320-byte `rep stos` per call, 84% of Cylinder::all_hits in wood_1.pov's profile).
  union Slot {
    Slot() {}
    LocalHit hit;
  };
  std::array<Slot, N> hits_;
  int size_ = 0;
};

/// HitBuffer's interface for a nearest-hit query: the window closes to the nearest crossing so far, so a
/// shape's gather builds the normal and uv of a crossing only when it is nearer than all before it (and
/// clears no array of candidates: HitBuffer<4> zeroes four hits per call).
class NearestBuffer {
 public:
  NearestBuffer(double t_min, double t_max) : t_min_(t_min), t_max_(t_max) {}

  bool accepts(double t) const { return t > t_min_ && t < t_max_; }
  void add(const LocalHit& hit) {
    if (!accepts(hit.t)) return;
    best_ = hit;
    t_max_ = hit.t;
    found_ = true;
  }
  double t_min() const { return t_min_; }
  double t_max() const { return t_max_; }

  bool nearest(LocalHit& hit) const {
    if (found_) hit = best_;
    return found_;
  }

 private:
  double t_min_, t_max_;
  LocalHit best_;
  bool found_ = false;
};

/// Whether any crossing lies in (t_min, t_max), for Shape::crosses: accepts nothing once one is found, so a
/// shape's gather stops building hits, and the hits' normals and uvs, never read, compile away.
class AnyBuffer {
 public:
  AnyBuffer(double t_min, double t_max) : t_min_(t_min), t_max_(t_max) {}

  bool accepts(double t) const { return !found_ && t > t_min_ && t < t_max_; }
  void add(const LocalHit& hit) { found_ = found_ || (hit.t > t_min_ && hit.t < t_max_); }
  bool found() const { return found_; }

 private:
  double t_min_, t_max_;
  bool found_ = false;
};

}  // namespace snell::geometry
