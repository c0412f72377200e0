// Numbers and strings as written into result files: the one number format and the one JSON
// writer (strings, objects, lists) of every output (summary.json, nodes.csv, mesh.vtk, scene.yaml,
// fit.json, the comparison and sweep tables, ...) and of the values substituted into scenes by
// `--set`.
#ifndef DRAPE_SRC_OUTPUT_JSON_H_
#define DRAPE_SRC_OUTPUT_JSON_H_

#include <string>
#include <utility>
#include <vector>

#include "src/scene/number_text.h"  // FormatNumber, the number format of every data file

namespace drape {

// `value` rounded to `digits` significant digits (%.*g): for text people read (captions, HTML and
// Markdown tables, log lines), never for a data file.
std::string RoundedNumber(double value, int digits);

// A JSON number: FormatNumber, or null for NaN and infinities (JSON has neither).
std::string JsonNumber(double value);

// A JSON string literal: quotes, backslashes and control characters escaped.
std::string JsonString(const std::string& text);

std::string JsonBool(bool value);

// A JSON object of `"key": value` members (each value JSON text already), one per line with the
// indentation of `depth` (0: the file's top level).
std::string JsonObject(const std::vector<std::pair<std::string, std::string>>& members, int depth);

// The same object on one line: {"seed": 1, "placement_m": 0.002}; {} when empty.
std::string JsonInlineObject(const std::vector<std::pair<std::string, std::string>>& members);

// A JSON list of `items` (each JSON text already) on one line: [1, "a", null]; [] when empty.
std::string JsonList(const std::vector<std::string>& items);

// A JSON list one item a line, with the indentation of `depth` (as JsonObject): for lists of
// objects. [] when empty.
std::string JsonListLines(const std::vector<std::string>& items, int depth);

// `values` as JSON strings (JsonString), each: for JsonList and JsonObject.
std::vector<std::string> JsonStrings(const std::vector<std::string>& values);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_JSON_H_
