#pragma once
// 8-bit file values of linear pixels without two pow() calls per channel: Encoding::encode is monotonic,
// so the 255 points where the rounded byte steps up are found once (by bisection over the float bit
// patterns, exact for every float) and each channel costs a binary search over them. Writing a 320x240
// PNG spent most of its time in those pow() calls. A table indexed by the top bits of the float then starts
// that search at most a step or two below the answer, instead of bisecting all 255 steps.
#include <array>
#include <cstdint>

#include "snell/io/encoding.hpp"

namespace snell::io {

class ByteEncoding {
 public:
  explicit ByteEncoding(const Encoding& encoding);
  /// The same byte as lround(encoding.encode(value) * 255), for every float value (NaN gives 0).
  std::uint8_t operator()(float value) const;

 private:
  /// The byte by bisecting steps_ (what the table is filled from).
  std::uint8_t by_search(float value) const;

  /// Float bit patterns of [0, 1] shifted right by this many bits index `start_`.
  static constexpr int kBucketShift = 16;
  static constexpr std::uint32_t kBuckets = (0x3F800000u >> kBucketShift) + 1;

  /// steps_[k - 1]: the least float whose byte is at least k (k = 1..255); steps_[255] is +infinity, so a
  /// step search ends there.
  std::array<float, 256> steps_{};
  /// start_[i]: the byte of the least float of bucket i (floats are ordered like their patterns, so no
  /// float of the bucket has a lower byte).
  std::array<std::uint8_t, kBuckets> start_{};
};

}  // namespace snell::io
