#include "src/output/json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>

namespace drape {
namespace {

// Every data file's numbers read back as the very doubles written, in no more characters than
// the shortest such text: 0.1 is "0.1", not printf's 17-digit 0.10000000000000001.
TEST(FormatNumber, IsTheShortestTextThatReadsBackExactly) {
  EXPECT_EQ(FormatNumber(0.1), "0.1");
  EXPECT_EQ(FormatNumber(100000.0), "100000");
  EXPECT_EQ(FormatNumber(1e-5), "1e-05");
  EXPECT_EQ(FormatNumber(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(FormatNumber(-0.0), "-0");
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  for (int k = 0; k < 2000; ++k) {
    const double value = (k % 2 ? -1.0 : 1.0) * std::pow(10.0, exponent(random));
    const std::string text = FormatNumber(value);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), value) << text;
    char longest[40];
    std::snprintf(longest, sizeof longest, "%.17g", value);
    EXPECT_LE(text.size(), std::string(longest).size()) << text << " against " << longest;
  }
}

TEST(FormatNumber, WritesNonFiniteValuesAsWords) {
  EXPECT_EQ(FormatNumber(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(FormatNumber(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(JsonNumber(std::numeric_limits<double>::quiet_NaN()), "null");
}

TEST(RoundedNumber, KeepsTheDigitsAskedForPeopleToRead) {
  EXPECT_EQ(RoundedNumber(1.0 / 3.0, 3), "0.333");
  EXPECT_EQ(RoundedNumber(123456.0, 2), "1.2e+05");
}

// The one JSON writer: objects one member a line (at a depth) or on one line, lists likewise; each
// value is JSON text already, each key quoted.
TEST(JsonWriter, WritesObjectsAndListsOnOneLineOrOneItemALine) {
  EXPECT_EQ(JsonObject({{"a", "1"}, {"b\"", JsonList({"1", "null"})}}, 0),
            "{\n  \"a\": 1,\n  \"b\\\"\": [1, null]\n}");
  EXPECT_EQ(JsonObject({{"a", JsonObject({{"b", "true"}}, 1)}}, 0),
            "{\n  \"a\": {\n    \"b\": true\n  }\n}");
  EXPECT_EQ(JsonObject({}, 1), "{}");
  EXPECT_EQ(JsonInlineObject({{"seed", "1"}, {"unit", JsonString("m")}}),
            "{\"seed\": 1, \"unit\": \"m\"}");
  EXPECT_EQ(JsonInlineObject({}), "{}");
  EXPECT_EQ(JsonList({}), "[]");
  EXPECT_EQ(JsonListLines({"{}", "[]"}, 1), "[\n    {},\n    []\n  ]");
  EXPECT_EQ(JsonListLines({}, 1), "[]");
  EXPECT_EQ(JsonList(JsonStrings({"a", "b\n"})), "[\"a\", \"b\\n\"]");
}

}  // namespace
}  // namespace drape
