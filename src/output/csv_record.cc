#include "src/output/csv_record.h"

#include <stdexcept>

namespace drape {
namespace {

// Throws where std::stoi/std::stod read less than the whole cell ("12abc", "0.5 m").
void RequireWhole(const std::string& cell, size_t used) {
  if (used != cell.size()) throw std::invalid_argument("not a number: " + cell);
}

}  // namespace

void ReadCsvCell(const std::string& cell, int* value) {
  size_t used = 0;
  *value = std::stoi(cell, &used);
  RequireWhole(cell, used);
}

void ReadCsvCell(const std::string& cell, double* value) {
  size_t used = 0;
  *value = std::stod(cell, &used);
  RequireWhole(cell, used);
}

void ReadCsvCell(const std::string& cell, bool* value) {
  if (cell != "true" && cell != "false") throw std::invalid_argument("not true or false: " + cell);
  *value = cell == "true";
}

void ReadCsvCell(const std::string& cell, std::string* value) { *value = cell; }

}  // namespace drape
