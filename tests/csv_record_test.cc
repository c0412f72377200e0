// A record's CSV columns (src/output/csv_record.h): the header and rows come from one list, a row
// reads back to the record it was written from, and a row that is not of the columns' layout does
// not read.
#include "src/output/csv_record.h"

#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <string>

namespace drape {
namespace {

struct CsvSample {
  int count = 0;
  double value = 0.0;
  bool flag = false;
  std::string text;
};

const CsvColumns<CsvSample>& CsvSampleColumns() {
  static const CsvColumns<CsvSample> columns = {
      MemberColumn("count", &CsvSample::count), MemberColumn("value_m", &CsvSample::value),
      MemberColumn("flag", &CsvSample::flag), MemberColumn("text", &CsvSample::text)};
  return columns;
}

TEST(CsvRecord, TheHeaderIsTheColumnsNamesInOrder) {
  EXPECT_EQ(CsvHeader(CsvSampleColumns()), "count,value_m,flag,text");
}

TEST(CsvRecord, ARowReadsBackToItsRecordExactly) {
  CsvSample sample;
  sample.count = -7;
  sample.value = 1.0 / 3;
  sample.flag = true;
  sample.text = "a text, with \"quotes\"";
  const std::string row = CsvRow(CsvSampleColumns(), sample);
  EXPECT_EQ(row.substr(0, 3), "-7,");
  const std::optional<CsvSample> back = ParseCsvRow(CsvSampleColumns(), row);
  ASSERT_TRUE(back.has_value()) << row;
  EXPECT_EQ(back->count, sample.count);
  EXPECT_EQ(back->value, sample.value);
  EXPECT_EQ(back->flag, sample.flag);
  EXPECT_EQ(back->text, sample.text);
}

TEST(CsvRecord, ANumberThatIsNotFiniteIsAnEmptyCellThatDoesNotReadBack) {
  CsvSample sample;
  sample.value = std::numeric_limits<double>::quiet_NaN();
  const std::string row = CsvRow(CsvSampleColumns(), sample);
  EXPECT_EQ(row, "0,,false,");
  EXPECT_FALSE(ParseCsvRow(CsvSampleColumns(), row).has_value());
}

TEST(CsvRecord, ARowOfAnotherLayoutDoesNotRead) {
  EXPECT_TRUE(ParseCsvRow(CsvSampleColumns(), "1,2.5,false,x").has_value());
  EXPECT_FALSE(ParseCsvRow(CsvSampleColumns(), "1,2.5,false").has_value());      // a cell short
  EXPECT_FALSE(ParseCsvRow(CsvSampleColumns(), "1,2.5,false,x,y").has_value());  // one too many
  EXPECT_FALSE(ParseCsvRow(CsvSampleColumns(), "1.5,2.5,false,x").has_value());  // not an integer
  EXPECT_FALSE(ParseCsvRow(CsvSampleColumns(), "1,2.5 m,false,x").has_value());  // not a number
  EXPECT_FALSE(ParseCsvRow(CsvSampleColumns(), "1,2.5,yes,x").has_value());      // not a boolean
}

}  // namespace
}  // namespace drape
