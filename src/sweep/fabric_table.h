// A laboratory's table of fabrics, the input of `drape fabrics` (docs/reference.md, "Fabrics"): a
// CSV file, one row per fabric, each column one of FabricColumns(). The material columns are the
// scene's own keys below material.finite_volume (SI: `D_warp`; KES-FB: `kes.B_warp`; SiroFAST:
// `fast.B_warp`; Peirce: `bending_length.warp`), with their units and checks, so that a row gives
// the same SI parameters as a scene that names the same keys. Lines that start with '#' are
// comments (a table's sources and licences), blank lines are skipped, a cell may be quoted.
// Every error is located as FABRICS.csv:LINE:COLUMN (1-based; COLUMN the cell's position in its
// row): a column drape does not know, with the nearest it does; a cell that is not a number; a
// row with too many or too few cells; a name given twice.
#ifndef DRAPE_SRC_SWEEP_FABRIC_TABLE_H_
#define DRAPE_SRC_SWEEP_FABRIC_TABLE_H_

#include <optional>
#include <string>
#include <vector>

namespace drape {

struct FabricColumn {
  enum class Kind {
    kName,              // the fabric's name: required, unique
    kText,              // carried to the outputs as it is (source, description)
    kMaterial,          // a material key: the row's scene gives it
    kSpecimenDiameter,  // drape_test.specimen_diameter
    kMeasuredDc,        // the measured drape coefficient, a fraction in [0, 1]
    kMeasuredDcSd,      // its standard deviation over the lab's drops, ≥ 0
    kMeasuredFolds,     // the fold (node) count the lab saw, a whole number ≥ 1
  };
  std::string name;  // as the header writes it
  Kind kind = Kind::kText;
  std::string scene_key;  // the scene key it sets (material and specimen columns), else ""
  std::string unit;       // "" for none
  std::string doc;        // one line, for the reference
};

// Every column a table may have: name, source, description, the material keys (from the scene
// schema), specimen_diameter, measured_dc, measured_dc_sd.
const std::vector<FabricColumn>& FabricColumns();

// docs/reference.md's table of the columns (between `<!-- fabric-columns -->` and
// `<!-- /fabric-columns -->`): column, unit, meaning, one row per FabricColumns() entry.
std::string FabricColumnsMarkdown();

// The most fabrics one table may hold.
constexpr int kMostFabrics = 10000;

// One given cell: its text and where it stands.
struct FabricCell {
  const FabricColumn* column = nullptr;
  std::string text;
  int line = 0;
  int position = 0;  // 1-based column number
};

struct FabricRow {
  int line = 0;  // in the file
  std::string name;
  std::vector<FabricCell> cells;  // every non-empty cell but the name, in column order
  std::optional<double> measured_dc, measured_dc_sd, specimen_diameter;
  std::optional<int> measured_folds;

  // The cell of `column` (by its name), or null.
  const FabricCell* Cell(const std::string& column) const;
};

struct FabricTable {
  std::string file;
  std::vector<std::string> header;  // the column names as written
  std::vector<FabricRow> rows;
};

// Reads and checks `path`. Throws InputError, located, on any bad input; a missing or empty file
// too.
FabricTable ReadFabricTable(const std::string& path);

// The `--set` overrides that make row `row`'s fabric of a base scene: its material replaced by
// {model: finite_volume, the row's keys}, then its specimen diameter where given. The cell of each
// override (null for the material's replacement) is in `cells` when given.
std::vector<std::string> FabricOverrides(const FabricRow& row,
                                         std::vector<const FabricCell*>* cells = nullptr);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_FABRIC_TABLE_H_
