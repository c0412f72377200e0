// A whole text read as a number, in strtod's syntax: the one reader of a number that stands alone
// in a table cell or a token of a mesh file ("1e-8", "0.5"; not "1 m", not ""); and the text of a
// number in the schema's rows and the loader's messages.
#ifndef DRAPE_SRC_SCENE_NUMBER_TEXT_H_
#define DRAPE_SRC_SCENE_NUMBER_TEXT_H_

#include <charconv>
#include <cmath>
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

// The shortest text that reads back as `value`, in %g's notation ("0.0007", "1e-08"); a whole
// number below 1e15 in full ("100000000", not "1e+08").
inline std::string NumberText(double value) {
  if (value == std::floor(value) && std::abs(value) < 1e15) {
    return std::to_string(static_cast<long long>(value));
  }
  char text[32];
  const auto written = std::to_chars(text, text + sizeof text, value, std::chars_format::general);
  return std::string(text, written.ptr);
}

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_NUMBER_TEXT_H_
