#include "src/parallel/byte_codec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace drape {
namespace {

uint64_t BitsOf(double value) {
  uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

bool SameBits(double a, double b) { return BitsOf(a) == BitsOf(b); }

TEST(ByteCodec, NumbersComeBackBitForBitInTheirOrder) {
  const std::vector<double> values = {0.1,
                                      -0.0,
                                      1.0 / 3.0,
                                      std::numeric_limits<double>::denorm_min(),
                                      std::numeric_limits<double>::max(),
                                      std::nextafter(1.0, 2.0)};
  ByteWriter writer;
  writer.Int(-42);
  writer.Doubles(values);
  writer.Text(std::string("a\0b", 3));
  writer.Double(values[2]);
  writer.Doubles({});
  ByteReader reader(writer.bytes());
  EXPECT_EQ(reader.Int(), -42);
  const std::vector<double> read = reader.Doubles();
  ASSERT_EQ(read.size(), values.size());
  for (size_t k = 0; k < values.size(); ++k) EXPECT_TRUE(SameBits(read[k], values[k])) << k;
  EXPECT_EQ(reader.Text(), std::string("a\0b", 3));
  EXPECT_TRUE(SameBits(reader.Double(), values[2]));
  EXPECT_TRUE(reader.Doubles().empty());
  EXPECT_TRUE(reader.AtEnd());
}

TEST(ByteCodec, ReadingPastTheEndIsAProgrammerError) {
  ByteWriter writer;
  writer.Int(3);
  ByteReader reader(writer.bytes());
  reader.Int();
  EXPECT_THROW(reader.Double(), std::logic_error);
  ByteReader truncated(writer.bytes());  // a length of 3 doubles with no doubles behind it
  EXPECT_THROW(truncated.Doubles(), std::logic_error);
}

}  // namespace
}  // namespace drape
