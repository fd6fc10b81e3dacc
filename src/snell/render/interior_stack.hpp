#pragma once
// The solids a ray is inside, innermost last, as POV-Ray's Ray::GetInteriors() tracks them for refraction
// (POV-Ray 3.7 trace.cpp, ComputeRefraction: entering pushes, leaving removes). Fixed capacity: deeper
// nesting than kCapacity is treated as not entering, which only affects the ior of absurd scenes.
#include <algorithm>
#include <array>
#include <cstddef>

#include "snell/scene/object.hpp"

namespace snell::render {

class InteriorStack {
 public:
  static constexpr size_t kCapacity = 16;

  // Only the first size_ slots are ever read, so a new stack clears none and a copy copies only those:
  // every camera ray starts with an empty stack, whose 136 bytes were cleared by a `rep stos` (60% of
  // trace_camera_ray in pigmap.pov's profile).
  InteriorStack() {}
  InteriorStack(const InteriorStack& other) : size_(other.size_) {
    std::copy_n(other.items_.begin(), size_, items_.begin());
  }
  InteriorStack& operator=(const InteriorStack& other) {
    size_ = other.size_;
    std::copy_n(other.items_.begin(), size_, items_.begin());
    return *this;
  }

  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }
  const scene::Object* back() const { return items_[size_ - 1]; }
  const scene::Object* at(size_t i) const { return items_[i]; }
  bool contains(const scene::Object* o) const {
    for (size_t i = 0; i < size_; ++i)
      if (items_[i] == o) return true;
    return false;
  }
  void push(const scene::Object* o) {
    if (size_ < kCapacity) items_[size_++] = o;
  }
  /// Removes `o`; false when it was not there.
  bool remove(const scene::Object* o) {
    for (size_t i = 0; i < size_; ++i) {
      if (items_[i] != o) continue;
      for (size_t j = i + 1; j < size_; ++j) items_[j - 1] = items_[j];
      --size_;
      return true;
    }
    return false;
  }

 private:
  std::array<const scene::Object*, kCapacity> items_;
  size_t size_ = 0;
};

/// The index of refraction of an object's interior (1 for objects without one).
inline double ior_of(const scene::Object* o) {
  return o && o->interior ? o->interior->ior : 1.0;
}

}  // namespace snell::render
