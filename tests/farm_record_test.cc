// The one encoding of a farm task's results (src/parallel/farm_record.h): records come back as
// they went, numbers bit for bit, rows with any bytes (commas, quotes, newlines, NUL).
#include "src/parallel/farm_record.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace drape {
namespace {

TEST(FarmRecord, RecordsComeBackAsTheyWent) {
  const char kWithNul[] = "a\nrow with a NUL \0 inside";
  const std::vector<FarmRecord> records = {
      {"solved", 3, "3,0.5,\"a, \"\"quoted\"\" state\",true", {0.1, -0.0, 1.0 / 3.0}},
      {"skipped", 0, std::string(kWithNul, sizeof kWithNul - 1), {}},
      {"interrupted", 12, "", {std::numeric_limits<double>::denorm_min(), 1e300}}};
  const std::vector<FarmRecord> back = DecodeFarmRecords(EncodeFarmRecords(records));
  ASSERT_EQ(back.size(), records.size());
  for (size_t k = 0; k < records.size(); ++k) EXPECT_TRUE(back[k] == records[k]) << k;
  EXPECT_TRUE(std::signbit(back[0].numbers[1]));  // -0.0 stays negative
  EXPECT_TRUE(DecodeFarmRecords(EncodeFarmRecords({})).empty());
}

TEST(FarmRecord, TextItDidNotWriteIsRefused) {
  const std::string text = EncodeFarmRecords({{"solved", 1, "row", {1.0}}});
  EXPECT_THROW(DecodeFarmRecords(text.substr(0, text.size() - 1)), std::logic_error);
  EXPECT_THROW(DecodeFarmRecords(text + "x"), std::logic_error);
}

}  // namespace
}  // namespace drape
