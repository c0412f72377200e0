#include "src/output/json.h"

#include <cmath>
#include <cstdio>

namespace drape {

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

namespace {

// `items` between `open` and `close`: on one line, or one a line indented for `depth` (< 0: one
// line).
std::string Joined(const std::vector<std::string>& items, const char* open, const char* close,
                   int depth) {
  if (items.empty()) return std::string(open) + close;
  if (depth < 0) {
    std::string text = open;
    for (size_t k = 0; k < items.size(); ++k) text += (k ? ", " : "") + items[k];
    return text + close;
  }
  const std::string inner(2 * (depth + 1), ' ');
  std::string text = std::string(open) + "\n";
  for (size_t k = 0; k < items.size(); ++k) {
    text += inner + items[k] + (k + 1 < items.size() ? ",\n" : "\n");
  }
  return text + std::string(2 * depth, ' ') + close;
}

std::vector<std::string> MemberTexts(
    const std::vector<std::pair<std::string, std::string>>& members) {
  std::vector<std::string> items;
  items.reserve(members.size());
  for (const auto& [key, value] : members) items.push_back(JsonString(key) + ": " + value);
  return items;
}

}  // namespace

std::string JsonObject(const std::vector<std::pair<std::string, std::string>>& members, int depth) {
  return Joined(MemberTexts(members), "{", "}", depth);
}

std::string JsonInlineObject(const std::vector<std::pair<std::string, std::string>>& members) {
  return Joined(MemberTexts(members), "{", "}", -1);
}

std::string JsonList(const std::vector<std::string>& items) { return Joined(items, "[", "]", -1); }

std::string JsonListLines(const std::vector<std::string>& items, int depth) {
  return Joined(items, "[", "]", depth);
}

std::vector<std::string> JsonStrings(const std::vector<std::string>& values) {
  std::vector<std::string> items;
  items.reserve(values.size());
  for (const std::string& value : values) items.push_back(JsonString(value));
  return items;
}

}  // namespace drape
