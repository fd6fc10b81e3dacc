#include "snell/io/byte_encoding.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace snell::io {

namespace {

long byte_of(const Encoding& encoding, float value) {
  return std::lround(encoding.encode(value) * 255.0);
}

}  // namespace

ByteEncoding::ByteEncoding(const Encoding& encoding) {
  // Non-negative floats order like their bit patterns, so bisecting the patterns of [0, 1] finds, for each
  // byte k, the first float that reaches it.
  const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
  for (int k = 1; k <= 255; ++k) {
    std::uint32_t lo = 0, hi = one;  // byte(lo) < k <= byte(hi): byte(0) is 0, byte(1) is 255
    while (hi > lo + 1) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      (byte_of(encoding, std::bit_cast<float>(mid)) >= k ? hi : lo) = mid;
    }
    steps_[static_cast<size_t>(k - 1)] = std::bit_cast<float>(hi);
  }
  steps_[255] = std::numeric_limits<float>::infinity();
  for (std::uint32_t i = 0; i < kBuckets; ++i) start_[i] = by_search(std::bit_cast<float>(i << kBucketShift));
}

std::uint8_t ByteEncoding::by_search(float value) const {
  if (!(value > 0)) return 0;
  return static_cast<std::uint8_t>(std::upper_bound(steps_.begin(), steps_.end() - 1, value) -
                                   steps_.begin());
}

std::uint8_t ByteEncoding::operator()(float value) const {
  if (!(value > 0)) return 0;  // also NaN, as Encoding::encode
  if (!(value < 1)) return 255;
  unsigned byte = start_[std::bit_cast<std::uint32_t>(value) >> kBucketShift];
  while (value >= steps_[byte]) ++byte;  // steps_[255] is infinite: ends by 255
  return static_cast<std::uint8_t>(byte);
}

}  // namespace snell::io
