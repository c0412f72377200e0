#include "src/output/json.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstdio>

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

std::string RoundedNumber(double value, int digits) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

std::string JsonNumber(double value) { return std::isfinite(value) ? FormatNumber(value) : "null"; }

std::string JsonString(const std::string& text) {
  std::string quoted = "\"";
  for (unsigned char c : text) {
    switch (c) {
      case '"':
        quoted += "\\\"";
        break;
      case '\\':
        quoted += "\\\\";
        break;
      case '\n':
        quoted += "\\n";
        break;
      case '\r':
        quoted += "\\r";
        break;
      case '\t':
        quoted += "\\t";
        break;
      default:
        if (c < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
          quoted += escaped;
        } else {
          quoted += static_cast<char>(c);
        }
    }
  }
  return quoted + "\"";
}

std::string JsonBool(bool value) { return value ? "true" : "false"; }

std::string JsonObject(const std::vector<std::pair<std::string, std::string>>& members, int depth) {
  if (members.empty()) return "{}";
  const std::string inner(2 * (depth + 1), ' ');
  std::string text = "{\n";
  for (size_t k = 0; k < members.size(); ++k) {
    text += inner + JsonString(members[k].first) + ": " + members[k].second;
    text += k + 1 < members.size() ? ",\n" : "\n";
  }
  return text + std::string(2 * depth, ' ') + "}";
}

}  // namespace drape
