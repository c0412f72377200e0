#include "src/output/csv_field.h"

#include <cmath>

#include "src/output/json.h"

namespace drape {

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  }
  return quoted + "\"";
}

std::string CsvNumber(double value) { return std::isfinite(value) ? FormatNumber(value) : ""; }

}  // namespace drape
