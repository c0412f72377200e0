// Numbers and strings as written into result files: the one number formatter and the one JSON
// string writer used by summary.json (src/output/writers.cc), fit.json (src/fit/fit_writer.cc),
// the comparison tables (src/compare/compare_report.cc) and the values substituted into scenes by
// `--set` (src/fit/).
#ifndef DRAPE_SRC_OUTPUT_JSON_H_
#define DRAPE_SRC_OUTPUT_JSON_H_

#include <string>

namespace drape {

// `value` with `digits` significant digits (%.*g); the default 17 reads back exactly.
// Non-finite values are written as printf writes them (nan, inf).
std::string FormatNumber(double value, int digits = 17);

// A JSON number: FormatNumber, or null for NaN and infinities (JSON has neither).
std::string JsonNumber(double value, int digits = 17);

// A JSON string literal: quotes, backslashes and control characters escaped.
std::string JsonString(const std::string& text);

std::string JsonBool(bool value);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_JSON_H_
