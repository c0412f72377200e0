// A record's CSV layout as one list of columns: each column's name, how it writes its field of a
// record and how it reads the field back. The header, the rows and the reading of a record type
// all come from its list (drops.csv's rows, a fabric task's record), so a column is added, renamed
// or moved in one place, and a test can hold the documentation's column list against it.
#ifndef DRAPE_SRC_OUTPUT_CSV_RECORD_H_
#define DRAPE_SRC_OUTPUT_CSV_RECORD_H_

#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "src/output/csv_field.h"

namespace drape {

template <typename Record>
struct CsvColumn {
  std::string name;
  std::function<std::string(const Record&)> write;  // the cell's text, before CsvField's quoting
  // Sets the record's field from the cell; throws std::exception where the cell does not read.
  std::function<void(const std::string& cell, Record& record)> read;
};

template <typename Record>
using CsvColumns = std::vector<CsvColumn<Record>>;

// A cell's text for a field: an integer, a number (CsvNumber: empty where not finite), a boolean
// (`true`/`false`) or a text.
inline std::string CsvCellText(int value) { return std::to_string(value); }
inline std::string CsvCellText(double value) { return CsvNumber(value); }
inline std::string CsvCellText(bool value) { return value ? "true" : "false"; }
inline std::string CsvCellText(const std::string& value) { return value; }

// A field from its cell, the whole cell or an exception (std::invalid_argument, std::out_of_range).
void ReadCsvCell(const std::string& cell, int* value);
void ReadCsvCell(const std::string& cell, double* value);
void ReadCsvCell(const std::string& cell, bool* value);
void ReadCsvCell(const std::string& cell, std::string* value);

// The column `name` for the member `member` of the record (an int, double, bool or string).
template <typename Record, typename Field>
CsvColumn<Record> MemberColumn(std::string name, Field Record::*member) {
  return {std::move(name), [member](const Record& r) { return CsvCellText(r.*member); },
          [member](const std::string& cell, Record& r) { ReadCsvCell(cell, &(r.*member)); }};
}

template <typename Record>
std::string CsvHeader(const CsvColumns<Record>& columns) {
  std::vector<std::string> names;
  names.reserve(columns.size());
  for (const CsvColumn<Record>& column : columns) names.push_back(column.name);
  return CsvLine(names);
}

template <typename Record>
std::string CsvRow(const CsvColumns<Record>& columns, const Record& record) {
  std::vector<std::string> cells;
  cells.reserve(columns.size());
  for (const CsvColumn<Record>& column : columns) cells.push_back(column.write(record));
  return CsvLine(cells);
}

// The record a row holds; nothing where the row has another number of cells than there are
// columns, or a cell does not read as its column's field.
template <typename Record>
std::optional<Record> ParseCsvRow(const CsvColumns<Record>& columns, const std::string& line) {
  const std::vector<std::string> cells = SplitCsvLine(line);
  if (cells.size() != columns.size()) return std::nullopt;
  Record record;
  try {
    for (size_t k = 0; k < columns.size(); ++k) columns[k].read(cells[k], record);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  return record;
}

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_CSV_RECORD_H_
