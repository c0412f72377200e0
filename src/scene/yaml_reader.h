// Strict, located reading of a YAML document (yaml-cpp 0.7): every value carries the place it came
// from (the scene file or a `--set` override), maps are checked for unknown and duplicate keys,
// numbers are parsed in full (no NaN, infinity, octal look-alikes or trailing text). Nodes are only
// ever read through const access: yaml-cpp's non-const operator[] inserts keys.
#ifndef DRAPE_SRC_SCENE_YAML_READER_H_
#define DRAPE_SRC_SCENE_YAML_READER_H_

#include <yaml-cpp/anchor.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "src/scene/scene.h"

namespace drape {

// Where the nodes of a document came from: the file, or one of the `--set` overrides grafted in.
// An override's nodes are located as file "--set", line = the override's 1-based number, column =
// the 1-based position in the "key.path=value" text.
class YamlOrigins {
 public:
  explicit YamlOrigins(std::string file) : file_(std::move(file)) {}

  // `node` (and everything below it) came from override number `index` (0-based); its text starts
  // at 0-based `value_offset` of the override, and `key_offset` is where its key is named.
  void AddOverride(const YAML::Node& node, int index, int key_offset, int value_offset);

  // The override that `node` is, or -1 if it came from the file.
  int OverrideOf(const YAML::Node& node) const;

  // The location of `mark` in the file (override == -1) or in an override; a null mark (a node
  // made by an override) falls back to the override's key.
  Location Locate(const YAML::Mark& mark, int override, const std::string& key) const;

  const std::string& file() const { return file_; }

 private:
  struct Override {
    YAML::Node node;
    int index = 0;
    int key_offset = 0;
    int value_offset = 0;
  };
  std::string file_;
  std::vector<Override> overrides_;
};

// A node with its location and dotted key path. (Its implicit move assignment copies the
// YAML::Node, which has no move assignment in yaml-cpp 0.7 and may throw: bugprone-exception-escape
// expects moves not to throw.)
struct YamlValue {  // NOLINT(bugprone-exception-escape)
  YAML::Node node;  // read through const access only
  Location where;
  const YamlOrigins* origins = nullptr;
  int override = -1;  // the `--set` it came from, -1 for the file

  const YAML::Node& get() const { return node; }
};

// The root of a document.
YamlValue YamlRoot(const YAML::Node& root, const YamlOrigins& origins);

// Throws InputError at `value`.
[[noreturn]] void Fail(const YamlValue& value, const std::string& what);

// How a node is described in "expected X, got Y" messages: "a list", "a map", "nothing", "'abc'".
std::string Describe(const YAML::Node& node);

// The candidate nearest to `name` by edit distance (transpositions count one), if it is close
// enough to be a plausible typo.
std::optional<std::string> NearestName(const std::string& name,
                                       const std::vector<std::string>& candidates);

// "; did you mean 'x'?" or " (expected one of: a, b, c)".
std::string SuggestionText(const std::string& name, const std::vector<std::string>& candidates);

// A map whose keys are checked on construction: it must be a map (or empty, if allowed), keys
// must be plain scalars, unique, and in `allowed`.
class YamlMap {
 public:
  YamlMap(const YamlValue& value, const std::vector<std::string>& allowed);
  // Any plain, unique key is accepted.
  explicit YamlMap(const YamlValue& value);

  bool Has(const std::string& key) const { return Find(key).has_value(); }
  std::optional<YamlValue> Find(const std::string& key) const;
  // A required key: if missing, fails at this map's location with the missing key's path.
  YamlValue Get(const std::string& key) const;
  // Where `key` itself is written (for "given twice"-style errors).
  Location KeyLocation(const std::string& key) const;
  // Keys in document order.
  std::vector<std::string> Keys() const;
  const YamlValue& value() const { return value_; }

 private:
  struct Entry {
    std::string key;
    Location key_where;
    YamlValue value;
  };
  void Read(const std::vector<std::string>* allowed);
  const Entry* FindEntry(const std::string& key) const;
  YamlValue value_;
  std::vector<Entry> entries_;
};

// The path of a child: "a.b" (or "b" at the root) and "a[3]".
std::string ChildKey(const std::string& parent, const std::string& key);
std::string ItemKey(const std::string& parent, int index);

// The items of a list, each located ("fixed[2]").
std::vector<YamlValue> ReadList(const YamlValue& value);

// Scalars. Numbers are plain decimal scalars, fully parsed and finite.
// The one YAML document of the file at `path` (a `what`, e.g. "scene file", for the messages),
// or a null node if the file is empty. Throws InputError, located, for an unreadable file, a
// syntax error or a second document. (yaml-cpp 0.7's LoadAll never returns on some inputs, e.g. a
// lone ',': this reader counts the documents itself and stops where the parser stops advancing.)
YAML::Node ReadYamlFile(const std::string& path, const std::string& what);
// The text of that file, unparsed (the same errors for a folder or an unreadable file).
std::string ReadYamlFileText(const std::string& path, const std::string& what);
// The same for YAML text already read, its errors located in `label` (a file name, or "<string>").
YAML::Node ParseYamlText(const std::string& text, const std::string& label,
                         const std::string& what);

// Every number read lies in [1e-30, 1e15] in magnitude, or is 0: within that range the
// products the model forms (mass × gravity × height, stiffness × length², ...) stay finite, and
// no stiffness is subnormal (tests/bad_input_test.cc; density 1e308 or a stiffness of 1e-320 are
// refused where they are written).
constexpr double kLargestInputMagnitude = 1e15;
constexpr double kSmallestInputMagnitude = 1e-30;
double ReadNumber(const YamlValue& value);
double ReadPositive(const YamlValue& value);     // > 0
double ReadNonNegative(const YamlValue& value);  // >= 0
int ReadInt(const YamlValue& value);             // a whole number
int ReadIntAtLeast(const YamlValue& value, int minimum);
bool ReadBool(const YamlValue& value);  // true | false
std::string ReadString(const YamlValue& value);
// One of `choices`; otherwise fails with the nearest choice suggested.
std::string ReadChoice(const YamlValue& value, const std::vector<std::string>& choices);

// A list of numbers; `size` >= 0 demands exactly that many.
std::vector<double> ReadNumbers(const YamlValue& value, int size = -1);
Eigen::Vector3d ReadVector3(const YamlValue& value);

// The number in `text` if it is a plain, fully parsed, finite decimal number; otherwise the reason
// it is not (for messages), in `error`.
std::optional<double> ParseNumber(const std::string& text, std::string* error);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_YAML_READER_H_
