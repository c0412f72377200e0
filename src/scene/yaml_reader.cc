#include "src/scene/yaml_reader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "src/scene/number_text.h"

namespace drape {

// ---------------------------------------------------------------------------------- origins

void YamlOrigins::AddOverride(const YAML::Node& node, int index, int key_offset, int value_offset) {
  overrides_.push_back({node, index, key_offset, value_offset});
}

int YamlOrigins::OverrideOf(const YAML::Node& node) const {
  for (int k = static_cast<int>(overrides_.size()) - 1; k >= 0; --k) {
    if (overrides_[k].node.is(node)) return k;
  }
  return -1;
}

Location YamlOrigins::Locate(const YAML::Mark& mark, int override, const std::string& key) const {
  if (override < 0) {
    return {file_, std::max(1, mark.line + 1), std::max(1, mark.column + 1), key};
  }
  const Override& source = overrides_[override];
  const int column = mark.is_null() ? source.key_offset + 1 : source.value_offset + mark.column + 1;
  return {"--set", source.index + 1, column, key};
}

// ------------------------------------------------------------------------------- basics

YamlValue YamlRoot(const YAML::Node& root, const YamlOrigins& origins) {
  return {root, Location{origins.file(), 1, 1, ""}, &origins, -1};
}

void Fail(const YamlValue& value, const std::string& what) { throw InputError(value.where, what); }

std::string Describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined:
      return "nothing";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    case YAML::NodeType::Scalar:
      break;
  }
  return "'" + node.Scalar() + "'";
}

std::string ChildKey(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string ItemKey(const std::string& parent, int index) {
  return parent + "[" + std::to_string(index) + "]";
}

// The value below `parent` (a map entry or a list item): from an override if it is one, else from
// wherever its parent came from.
static YamlValue Child(const YamlValue& parent, const YAML::Node& node, const YAML::Mark& mark,
                       const std::string& key) {
  int origin = parent.origins->OverrideOf(node);
  if (origin < 0) origin = parent.override;
  return {node, parent.origins->Locate(mark, origin, key), parent.origins, origin};
}

// ------------------------------------------------------------------------------ suggestions

static int EditDistance(const std::string& a, const std::string& b) {
  // Optimal string alignment: insertions, deletions, substitutions and adjacent transpositions.
  const size_t n = a.size(), m = b.size();
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1, 0));
  for (size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
  for (size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
  for (size_t i = 1; i <= n; ++i) {
    for (size_t j = 1; j <= m; ++j) {
      const int cost = std::tolower(a[i - 1]) == std::tolower(b[j - 1]) ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

std::optional<std::string> NearestName(const std::string& name,
                                       const std::vector<std::string>& candidates) {
  const int allowed = name.size() <= 3 ? 1 : name.size() <= 6 ? 2 : 3;
  std::optional<std::string> best;
  int best_distance = allowed + 1;
  for (const auto& candidate : candidates) {
    const int distance = EditDistance(name, candidate);
    if (distance < best_distance && distance < static_cast<int>(name.size())) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

std::string SuggestionText(const std::string& name, const std::vector<std::string>& candidates) {
  if (candidates.empty()) return " (nothing is accepted here)";
  if (auto nearest = NearestName(name, candidates)) return "; did you mean '" + *nearest + "'?";
  std::string list;
  for (const auto& candidate : candidates) list += (list.empty() ? "" : ", ") + candidate;
  return " (expected one of: " + list + ")";
}

// ------------------------------------------------------------------------------------ maps

YamlMap::YamlMap(const YamlValue& value, const std::vector<std::string>& allowed) : value_(value) {
  Read(&allowed);
}

YamlMap::YamlMap(const YamlValue& value) : value_(value) { Read(nullptr); }

void YamlMap::Read(const std::vector<std::string>* allowed) {
  const YamlValue& value = value_;
  const YAML::Node& node = value.get();
  if (node.IsNull()) return;  // `key:` with nothing under it: an empty map
  if (!node.IsMap()) Fail(value, "expected a map of keys, got " + Describe(node));
  for (const auto& pair : node) {
    const YAML::Node key_node = pair.first;
    const YAML::Node child = pair.second;
    int origin = value.origins->OverrideOf(child);
    if (origin < 0) origin = value.override;
    // A key named by an override has no mark: locate it where that override names it.
    const int key_origin = key_node.Mark().is_null() ? origin : value.override;
    if (!key_node.IsScalar()) {
      throw InputError(value.origins->Locate(key_node.Mark(), key_origin, value.where.key),
                       "a key must be a plain name, got " + Describe(key_node));
    }
    const std::string& key = key_node.Scalar();
    const std::string path = ChildKey(value.where.key, key);
    const Location key_where = value.origins->Locate(key_node.Mark(), key_origin, path);
    if (allowed && std::find(allowed->begin(), allowed->end(), key) == allowed->end()) {
      throw InputError(key_where, "unknown key '" + key + "'" + SuggestionText(key, *allowed));
    }
    if (const Entry* first = FindEntry(key)) {
      throw InputError(key_where, "duplicate key '" + key + "' (first given at line " +
                                      std::to_string(first->key_where.line) + ")");
    }
    YamlValue entry{child, value.origins->Locate(child.Mark(), origin, path), value.origins,
                    origin};
    // A block collection or an empty value is best pointed at by its key.
    const bool at_key =
        child.IsNull() || (!child.IsScalar() && child.Style() == YAML::EmitterStyle::Block);
    if (at_key) entry.where = key_where;
    entries_.push_back({key, key_where, entry});
  }
}

const YamlMap::Entry* YamlMap::FindEntry(const std::string& key) const {
  for (const auto& entry : entries_) {
    if (entry.key == key) return &entry;
  }
  return nullptr;
}

std::optional<YamlValue> YamlMap::Find(const std::string& key) const {
  if (const Entry* entry = FindEntry(key)) return entry->value;
  return std::nullopt;
}

YamlValue YamlMap::Get(const std::string& key) const {
  if (const Entry* entry = FindEntry(key)) return entry->value;
  Location where = value_.where;
  where.key = ChildKey(value_.where.key, key);
  throw InputError(where, "required key '" + key + "' is missing");
}

Location YamlMap::KeyLocation(const std::string& key) const {
  const Entry* entry = FindEntry(key);
  return entry ? entry->key_where : value_.where;
}

std::vector<std::string> YamlMap::Keys() const {
  std::vector<std::string> keys;
  for (const auto& entry : entries_) keys.push_back(entry.key);
  return keys;
}

// ----------------------------------------------------------------------------------- lists

std::vector<YamlValue> ReadList(const YamlValue& value) {
  const YAML::Node& node = value.get();
  std::vector<YamlValue> items;
  if (node.IsNull()) return items;
  if (!node.IsSequence()) Fail(value, "expected a list, got " + Describe(node));
  int index = 0;
  for (const auto& element : node) {
    const YAML::Node item = element;
    YamlValue child = Child(value, item, item.Mark(), ItemKey(value.where.key, index++));
    if (item.IsNull()) {  // an empty item's mark is past it: point at the list instead
      child.where.file = value.where.file;
      child.where.line = value.where.line;
      child.where.column = value.where.column;
    }
    items.push_back(child);
  }
  return items;
}

// --------------------------------------------------------------------------------- numbers

static std::string Lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// "010" → "write 10 or 8 explicitly"; "01.5" → "write 1.5 explicitly".
static std::string OctalAdvice(const std::string& sign, const std::string& body) {
  size_t first = body.find_first_not_of('0');
  std::string decimal;
  if (first == std::string::npos) {
    decimal = "0";
  } else {
    decimal = body.substr(first);
    if (!std::isdigit(static_cast<unsigned char>(decimal[0]))) decimal = "0" + decimal;
  }
  std::string advice = "write " + sign + decimal;
  const bool all_octal = body.find_first_not_of("01234567") == std::string::npos;
  if (all_octal) {
    const std::string octal = std::to_string(std::strtoll(body.c_str(), nullptr, 8));
    if (octal != decimal) advice += " or " + sign + octal;
  }
  return advice + " explicitly";
}

std::optional<double> ParseNumber(const std::string& text, std::string* error) {
  const std::string quoted = "'" + text + "'";
  if (text.empty()) {
    *error = "expected a number, got nothing";
    return std::nullopt;
  }
  const bool has_sign = text[0] == '-' || text[0] == '+';
  const std::string sign = text[0] == '-' ? "-" : "";
  const std::string body = text.substr(has_sign ? 1 : 0);
  const std::string lower = Lower(body);
  if (lower == ".nan" || lower == "nan" || lower == ".inf" || lower == "inf" ||
      lower == "infinity" || lower == ".infinity") {
    *error = quoted + " is not a finite number (NaN and infinity are not allowed)";
    return std::nullopt;
  }
  if (body.empty() || body.find_first_not_of("0123456789.eE+-") != std::string::npos) {
    *error = "expected a number, got " + quoted;
    return std::nullopt;
  }
  if (body.size() > 1 && body[0] == '0' && std::isdigit(static_cast<unsigned char>(body[1]))) {
    *error = quoted + " looks like an octal number: " + OctalAdvice(sign, body);
    return std::nullopt;
  }
  errno = 0;
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) {
    *error = quoted + " is not a number";
    return std::nullopt;
  }
  if (errno == ERANGE && !std::isfinite(number)) {
    *error = quoted + " is out of range";
    return std::nullopt;
  }
  if (!std::isfinite(number)) {
    *error = quoted + " is not a finite number";
    return std::nullopt;
  }
  if (std::abs(number) > kLargestInputMagnitude ||
      (number != 0.0 && std::abs(number) < kSmallestInputMagnitude)) {
    std::ostringstream message;
    message << quoted << " is out of range: numbers in a scene lie between "
            << kSmallestInputMagnitude << " and " << kLargestInputMagnitude
            << " in magnitude (or are 0), so that their products stay finite";
    *error = message.str();
    return std::nullopt;
  }
  return number;
}

namespace {

// Where each document of a stream starts, and where its content (its first node) starts.
class DocumentStarts : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override {
    starts.push_back(mark);
    contents.push_back(mark);
    awaiting_content_ = true;
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { Content(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { Content(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                const std::string&) override {
    Content(mark);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    Content(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    Content(mark);
  }
  void OnMapEnd() override {}

  std::vector<YAML::Mark> starts, contents;

 private:
  void Content(const YAML::Mark& mark) {
    if (awaiting_content_) contents.back() = mark;
    awaiting_content_ = false;
  }
  bool awaiting_content_ = false;
};

// Throws InputError for a second document, or for text the parser does not advance over (it
// would otherwise yield empty documents for ever). Throws YAML::Exception for a syntax error.
void CheckSingleDocument(const std::string& text, const std::string& path,
                         const std::string& what) {
  std::istringstream stream(text);
  YAML::Parser parser(stream);
  DocumentStarts documents;
  while (documents.starts.size() < 2 && parser.HandleNextDocument(documents)) {
  }
  if (documents.starts.size() < 2) return;
  const YAML::Mark& first = documents.starts[0];
  const YAML::Mark& second = documents.starts[1];
  const YAML::Mark& content = documents.contents[1];
  const Location where{path, content.line + 1, content.column + 1, ""};
  if (second.pos == first.pos) {
    throw InputError(where, "YAML syntax error: unexpected text here (a stray ',', ']' or '}'?)");
  }
  throw InputError(where, "a " + what + " holds one YAML document; this is a second one");
}

}  // namespace

YAML::Node ReadYamlFile(const std::string& path, const std::string& what) {
  return ParseYamlText(ReadYamlFileText(path, what), path, what);
}

std::string ReadYamlFileText(const std::string& path, const std::string& what) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw InputError(path + ": cannot read the " + what + ": it is a folder");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the " + what + ": " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read the " + what + ": read error");
  return text.str();
}

YAML::Node ParseYamlText(const std::string& text, const std::string& label,
                         const std::string& what) {
  try {
    CheckSingleDocument(text, label, what);
    return YAML::Load(text);
  } catch (const YAML::Exception& exception) {  // a ParserException, with its mark
    const YAML::Mark mark = exception.mark;
    throw InputError(Location{label, std::max(1, mark.line + 1), std::max(1, mark.column + 1), ""},
                     "YAML syntax error: " + exception.msg);
  }
}

double ReadNumber(const YamlValue& value) {
  const YAML::Node& node = value.get();
  if (!node.IsScalar()) Fail(value, "expected a number, got " + Describe(node));
  if (node.Tag() == "!") Fail(value, "expected a number, got the quoted text " + Describe(node));
  std::string error;
  const auto number = ParseNumber(node.Scalar(), &error);
  if (!number) Fail(value, error);
  return *number;
}

double ReadPositive(const YamlValue& value) {
  const double number = ReadNumber(value);
  if (!(number > 0.0)) Fail(value, "must be positive, got " + FormatNumber(number));
  return number;
}

double ReadNonNegative(const YamlValue& value) {
  const double number = ReadNumber(value);
  if (number < 0.0) Fail(value, "must not be negative, got " + FormatNumber(number));
  return number;
}

int ReadInt(const YamlValue& value) {
  const double number = ReadNumber(value);
  if (number != std::floor(number) || number < INT_MIN || number > INT_MAX) {
    Fail(value, "expected a whole number, got " + Describe(value.get()));
  }
  return static_cast<int>(number);
}

int ReadIntAtLeast(const YamlValue& value, int minimum) {
  const int number = ReadInt(value);
  if (number < minimum) {
    Fail(value, "must be at least " + std::to_string(minimum) + ", got " + std::to_string(number));
  }
  return number;
}

bool ReadBool(const YamlValue& value) {
  const YAML::Node& node = value.get();
  if (node.IsScalar() && node.Tag() != "!") {
    const std::string text = Lower(node.Scalar());
    if (text == "true") return true;
    if (text == "false") return false;
  }
  Fail(value, "expected true or false, got " + Describe(node));
}

std::string ReadString(const YamlValue& value) {
  const YAML::Node& node = value.get();
  if (!node.IsScalar()) Fail(value, "expected a text value, got " + Describe(node));
  return node.Scalar();
}

std::string ReadChoice(const YamlValue& value, const std::vector<std::string>& choices) {
  const std::string text = ReadString(value);
  if (std::find(choices.begin(), choices.end(), text) == choices.end()) {
    Fail(value, "unknown value '" + text + "'" + SuggestionText(text, choices));
  }
  return text;
}

std::vector<double> ReadNumbers(const YamlValue& value, int size) {
  const std::string wanted =
      size >= 0 ? "a list of " + std::to_string(size) + " numbers" : "a list of numbers";
  if (!value.get().IsSequence())
    Fail(value, "expected " + wanted + ", got " + Describe(value.get()));
  std::vector<double> numbers;
  for (const auto& item : ReadList(value)) numbers.push_back(ReadNumber(item));
  if (size >= 0 && static_cast<int>(numbers.size()) != size) {
    Fail(value, "expected " + wanted + ", got " + std::to_string(numbers.size()));
  }
  return numbers;
}

Eigen::Vector3d ReadVector3(const YamlValue& value) {
  const auto numbers = ReadNumbers(value, 3);
  return {numbers[0], numbers[1], numbers[2]};
}

}  // namespace drape
