// A whole text read as a number, in strtod's syntax: the one reader of a number that stands alone
// in a table cell, a token of a mesh file or a row of the schema ("1e-8", "0.5"; not "1 m", not
// "").
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

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_NUMBER_TEXT_H_
