#include "src/sweep/fabric_table.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <set>

#include "src/output/csv_field.h"
#include "src/scene/number_text.h"
#include "src/scene/scene.h"
#include "src/scene/scene_schema.h"
#include "src/scene/yaml_reader.h"
#include "src/sweep/sweep.h"

namespace drape {
namespace {

constexpr const char* kMaterial = "material.finite_volume";

using Kind = FabricColumn::Kind;

// The material columns: the numeric keys of material.finite_volume and of its kes, fast and
// bending_length blocks (named below material.finite_volume), and material.density.
void AddMaterialColumns(std::vector<FabricColumn>* columns) {
  const std::string prefix = std::string(kMaterial) + ".";
  for (const SchemaRow& row : SceneSchema()) {
    const bool numeric = row.value == ValueType::kNumber || row.value == ValueType::kInteger;
    if (!numeric) continue;
    if (row.table == "material" && row.key == "density") {
      columns->push_back({"density", Kind::kMaterial, "material.density", row.unit, row.doc});
    } else if (row.table == kMaterial || row.table.rfind(prefix, 0) == 0) {
      const std::string name =
          row.table == kMaterial ? row.key : row.table.substr(prefix.size()) + "." + row.key;
      columns->push_back({name, Kind::kMaterial, row.Path(), row.unit, row.doc});
    }
  }
}

std::string Trimmed(const std::string& text) {
  const size_t begin = text.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

[[noreturn]] void FailAt(const std::string& file, int line, int position, const std::string& key,
                         const std::string& what) {
  throw InputError(Location{file, line, position, key}, what);
}

// "did you mean 'kes.B_warp' (gf·cm²/cm) or 'fast.B_warp' (µN·m)?" for a header word that is not a
// column: the columns it is nearest to, or whose last part it starts with (a unit written into the
// name: B_warp_gf).
std::string ColumnSuggestion(const std::string& word) {
  std::vector<std::string> names, matches;
  for (const FabricColumn& column : FabricColumns()) names.push_back(column.name);
  for (const FabricColumn& column : FabricColumns()) {
    const std::string last = column.name.substr(column.name.rfind('.') + 1);
    if (word != column.name && (word == last || word.rfind(last + "_", 0) == 0)) {
      matches.push_back("'" + column.name + "'" +
                        (column.unit.empty() ? "" : " (" + column.unit + ")"));
    }
  }
  if (matches.empty()) {
    return SuggestionText(word, names) + " (the columns: docs/reference.md, \"drape fabrics\")";
  }
  std::string text = "; did you mean ";
  for (size_t k = 0; k < matches.size(); ++k) {
    text += (k == 0 ? "" : (k + 1 == matches.size() ? " or " : ", ")) + matches[k];
  }
  return text + "? A column's unit is the scene key's, never part of its name";
}

struct Header {
  std::vector<const FabricColumn*> columns;  // per position
  int line = 0;
};

Header ReadHeader(const std::string& file, int line, const std::vector<std::string>& words) {
  std::map<std::string, const FabricColumn*> known;
  for (const FabricColumn& column : FabricColumns()) known[column.name] = &column;
  Header header;
  header.line = line;
  std::set<std::string> seen;
  for (size_t k = 0; k < words.size(); ++k) {
    const int position = static_cast<int>(k) + 1;
    const std::string word = Trimmed(words[k]);
    const auto found = known.find(word);
    if (found == known.end()) {
      FailAt(file, line, position, word,
             word.empty() ? "an empty column name"
                          : "unknown column '" + word + "'" + ColumnSuggestion(word));
    }
    if (!seen.insert(word).second) FailAt(file, line, position, word, "the column is given twice");
    header.columns.push_back(found->second);
  }
  if (!seen.count("name")) FailAt(file, line, 1, "name", "the table has no 'name' column");
  return header;
}

double CellNumber(const FabricCell& cell, const std::string& file) {
  const std::optional<double> value = WholeNumber(cell.text);
  if (!value || !std::isfinite(*value)) {
    FailAt(file, cell.line, cell.position, cell.column->name,
           "expected a number" + (cell.column->unit.empty() ? "" : " (" + cell.column->unit + ")") +
               ", got '" + cell.text + "'");
  }
  return *value;
}

// The measured drape coefficient, its SD and the specimen's diameter: read and checked here (the
// material cells are checked by the scene loader, which knows their ranges).
void ReadRowNumbers(const std::string& file, FabricRow* row) {
  for (const FabricCell& cell : row->cells) {
    const Kind kind = cell.column->kind;
    if (kind == Kind::kText) continue;
    const double value = CellNumber(cell, file);
    const auto fail = [&](const std::string& what) {
      FailAt(file, cell.line, cell.position, cell.column->name, what);
    };
    if (kind == Kind::kMeasuredDc) {
      if (value < 0.0 || value > 1.0)
        fail("a drape coefficient is a fraction in [0, 1], got " + cell.text);
      row->measured_dc = value;
    } else if (kind == Kind::kMeasuredDcSd) {
      if (value < 0.0) fail("must not be negative, got " + cell.text);
      row->measured_dc_sd = value;
    } else if (kind == Kind::kMeasuredFolds) {
      if (value < 1.0 || value != std::floor(value) || value > 1000.0)
        fail("a fold count is a whole number from 1 to 1000, got " + cell.text);
      row->measured_folds = static_cast<int>(value);
    } else if (kind == Kind::kSpecimenDiameter) {
      row->specimen_diameter = value;  // checked by the loader (drape_test.specimen_diameter)
    }
  }
  if (row->measured_dc_sd && !row->measured_dc) {
    const FabricCell* sd = row->Cell("measured_dc_sd");
    FailAt(file, sd->line, sd->position, "measured_dc_sd",
           "a standard deviation without measured_dc");
  }
}

FabricRow ReadRow(const std::string& file, const Header& header, int line,
                  const std::vector<std::string>& cells) {
  if (cells.size() != header.columns.size()) {
    const int position = static_cast<int>(std::min(cells.size(), header.columns.size())) + 1;
    FailAt(file, line, position, "",
           "the row has " + std::to_string(cells.size()) + " cells, the header " +
               std::to_string(header.columns.size()) + " columns");
  }
  FabricRow row;
  row.line = line;
  for (size_t k = 0; k < cells.size(); ++k) {
    const FabricColumn* column = header.columns[k];
    const std::string text = Trimmed(cells[k]);
    const int position = static_cast<int>(k) + 1;
    if (column->kind == Kind::kName) {
      if (text.empty()) FailAt(file, line, position, "name", "every fabric needs a name");
      row.name = text;
    } else if (!text.empty()) {
      row.cells.push_back({column, text, line, position});
    }
  }
  ReadRowNumbers(file, &row);
  return row;
}

}  // namespace

const std::vector<FabricColumn>& FabricColumns() {
  static const std::vector<FabricColumn> columns = [] {
    std::vector<FabricColumn> list = {
        {"name", Kind::kName, "", "", "the fabric's name (required, unique): its folder and row"},
        {"source", Kind::kText, "", "", "where the numbers come from (carried to the outputs)"},
        {"description", Kind::kText, "", "", "the fabric in words (carried to the outputs)"},
    };
    AddMaterialColumns(&list);
    list.push_back({"specimen_diameter", Kind::kSpecimenDiameter, "drape_test.specimen_diameter",
                    "m", "the specimen's diameter (default: the base scene's, 0.30 m)"});
    list.push_back({"measured_dc", Kind::kMeasuredDc, "", "",
                    "the measured drape coefficient, a fraction (mean over the lab's drops)"});
    list.push_back({"measured_dc_sd", Kind::kMeasuredDcSd, "", "",
                    "its standard deviation over the lab's drops"});
    list.push_back({"measured_folds", Kind::kMeasuredFolds, "", "",
                    "the number of folds (nodes) the lab saw, where published"});
    return list;
  }();
  return columns;
}

std::string FabricColumnsMarkdown() {
  std::string text = "| column | unit | meaning |\n|---|---|---|\n";
  for (const FabricColumn& column : FabricColumns()) {
    std::string meaning = column.doc;
    if (column.kind == Kind::kMaterial) {
      meaning = "`" + column.scene_key + "`" + (meaning.empty() ? "" : ": " + meaning);
    }
    text += "| `" + column.name + "` | " + column.unit + " | " + meaning + " |\n";
  }
  return text;
}

const FabricCell* FabricRow::Cell(const std::string& column) const {
  for (const FabricCell& cell : cells) {
    if (cell.column->name == column) return &cell;
  }
  return nullptr;
}

FabricTable ReadFabricTable(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot read the fabric table: " + std::strerror(errno));
  FabricTable table;
  table.file = path;
  std::optional<Header> header;
  std::set<std::string> names;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (Trimmed(text).empty() || text[0] == '#') continue;
    const std::vector<std::string> cells = SplitCsvLine(text);
    if (!header) {
      header = ReadHeader(path, line, cells);
      for (const std::string& word : cells) table.header.push_back(Trimmed(word));
      continue;
    }
    if (static_cast<int>(table.rows.size()) == kMostFabrics) {
      FailAt(path, line, 1, "",
             "more than " + std::to_string(kMostFabrics) + " fabrics in one table: split it");
    }
    FabricRow row = ReadRow(path, *header, line, cells);
    if (!names.insert(row.name).second) {
      FailAt(path, line, 1, "name", "the fabric '" + row.name + "' is named twice");
    }
    table.rows.push_back(std::move(row));
  }
  if (!header) FailAt(path, 1, 1, "", "the table is empty: it needs a header row and a fabric");
  if (table.rows.empty()) FailAt(path, header->line, 1, "", "the table has a header but no fabric");
  return table;
}

std::vector<std::string> FabricOverrides(const FabricRow& row,
                                         std::vector<const FabricCell*>* cells) {
  std::vector<std::string> overrides = {"material={model: finite_volume, finite_volume: {}}"};
  if (cells) cells->assign(1, nullptr);
  for (const FabricCell& cell : row.cells) {
    if (cell.column->scene_key.empty()) continue;
    overrides.push_back(cell.column->scene_key + "=" + cell.text);
    if (cells) cells->push_back(&cell);
  }
  return overrides;
}

}  // namespace drape
