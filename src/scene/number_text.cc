#include "src/scene/number_text.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>

namespace drape {

std::string FormatNumber(double value) {
  char text[40];
  char* const end = text + sizeof text;
  std::to_chars_result written = std::to_chars(text, end, value, std::chars_format::scientific);
  assert(written.ec == std::errc() && "40 characters hold any double");
  if (!std::isfinite(value)) return std::string(text, written.ptr);
  // Fixed notation where %g would use it (decimal exponents -4 to 16 with 17 digits), else the
  // scientific text: the same notation as %.17g, with only the digits that are needed.
  const char* sign = std::find(text, written.ptr, 'e') + 1;
  int exponent = 0;
  std::from_chars(sign + (*sign == '+'), written.ptr, exponent);
  if (exponent < -4 || exponent >= 17) return std::string(text, written.ptr);
  written = std::to_chars(text, end, value, std::chars_format::fixed);
  assert(written.ec == std::errc() && "40 characters hold a double below 1e17");
  return std::string(text, written.ptr);
}

}  // namespace drape
