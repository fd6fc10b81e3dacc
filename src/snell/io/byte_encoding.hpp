#pragma once
// 8-bit file values of linear pixels without two pow() calls per channel: Encoding::encode is monotonic,
// so the 255 points where the rounded byte steps up are found once (by bisection over the float bit
// patterns, exact for every float) and each channel costs a binary search over them. Writing a 320x240
// PNG spent most of its time in those pow() calls.
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
  /// steps_[k - 1]: the least float whose byte is at least k (k = 1..255).
  std::array<float, 255> steps_{};
};

}  // namespace snell::io
