// Numbers as text: WholeNumber, the one reader of a number that stands alone in a table cell or a
// token of a mesh file, and FormatNumber, the one writer of a number (data files, the schema's
// rows, the loader's messages).
#ifndef DRAPE_SRC_SCENE_NUMBER_TEXT_H_
#define DRAPE_SRC_SCENE_NUMBER_TEXT_H_

#include <cstdlib>
#include <optional>
#include <string>

namespace drape {

// The number that is the whole of `text`; none when `text` is empty or has anything else.
inline std::optional<double> WholeNumber(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

// The shortest text that reads back as exactly `value` (std::to_chars), in the notation of %.17g
// (fixed for decimal exponents -4 to 16, else scientific): 0.1 (not 0.10000000000000001), 100000,
// 1e-05, 0.3333333333333333. The number format of every data file (src/output/json.h), of the
// schema's ranges and defaults, and of the loader's messages. Non-finite values are written as
// nan, inf and -inf.
std::string FormatNumber(double value);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_NUMBER_TEXT_H_
