// The 8-bit table encoder must give exactly the byte of the direct formula for every float it can meet.
#include "snell/io/byte_encoding.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "snell/math/pcg32.hpp"

namespace snell::io {
namespace {

long direct_byte(const Encoding& encoding, float value) {
  return std::lround(encoding.encode(value) * 255.0);
}

TEST(ByteEncodingTest, MatchesTheDirectFormulaForEveryGammaAndValue) {
  for (const Encoding encoding : {Encoding{1.0, false}, Encoding{2.2, false}, Encoding{1.8, false},
                                  Encoding{2.2, true}, Encoding{0.45, false}}) {
    const ByteEncoding byte(encoding);
    math::Pcg32 rng(7, 11);
    for (int i = 0; i < 200000; ++i) {
      // Uniform in [0, 1.2] and, to reach the dark end's steps, log-uniform down to 1e-6.
      const float v = i % 2 ? static_cast<float>(rng.next_double() * 1.2)
                            : static_cast<float>(std::pow(10.0, -6.0 * rng.next_double()));
      ASSERT_EQ(byte(v), direct_byte(encoding, v)) << "value " << v << " gamma " << encoding.assumed_gamma;
    }
  }
}

TEST(ByteEncodingTest, StepsFallOnTheExactFloat) {
  // Either side of each step, one float apart, the bytes differ as the formula says; the walk is fine
  // enough to pass every step of the table's buckets.
  for (const Encoding encoding : {Encoding{1.0, false}, Encoding{2.2, true}, Encoding{0.45, false}}) {
    const ByteEncoding byte(encoding);
    for (float v = 1e-7f; v < 1.0f; v *= 1.001f) {
      const float next = std::nextafter(v, 2.0f);
      ASSERT_EQ(byte(v), direct_byte(encoding, v)) << v;
      ASSERT_EQ(byte(next), direct_byte(encoding, next)) << next;
    }
  }
  const ByteEncoding byte(Encoding{1.0, false});
  EXPECT_EQ(byte(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(byte(-1.0f), 0);
  EXPECT_EQ(byte(0.0f), 0);
  EXPECT_EQ(byte(1.0f), 255);
  EXPECT_EQ(byte(1e30f), 255);
  EXPECT_EQ(byte(std::numeric_limits<float>::infinity()), 255);
}

}  // namespace
}  // namespace snell::io
