// One field of a CSV line, quoted only where it must be: one rule for every CSV drape writes from
// free text (scene names, terminations, reasons).
#ifndef DRAPE_SRC_OUTPUT_CSV_FIELD_H_
#define DRAPE_SRC_OUTPUT_CSV_FIELD_H_

#include <string>
#include <vector>

namespace drape {

// `text` as it is when it holds no comma, quote or line break; else in double quotes, with each
// quote doubled and each line break turned into a space (one record per line).
std::string CsvField(const std::string& text);

// A number in a CSV cell: FormatNumber's text (the shortest that reads back exactly), or an empty
// cell when it is NaN or infinite (no NaN in any output).
std::string CsvNumber(double value);

// One CSV line of `cells`, each through CsvField.
std::string CsvLine(const std::vector<std::string>& cells);

// Splits one CSV line as CsvLine writes them (a quoted field may hold commas and doubled quotes).
std::vector<std::string> SplitCsvLine(const std::string& line);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_CSV_FIELD_H_
