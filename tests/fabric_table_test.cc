// The fabric table of `drape fabrics` (src/sweep/fabric_table.h): its columns are the scene's
// keys, a row in KES, FAST or Peirce units gives the same SI material as a scene naming the same
// keys, and every bad table is refused at its row and column before anything is solved.
#include "src/sweep/fabric_table.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "src/scene/scene_loader.h"
#include "src/scene/scene_schema.h"
#include "src/sweep/fabrics.h"
#include "tests/reference_block.h"
#include "tests/scratch_folder.h"
#include "tests/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

class FabricTableTest : public ::testing::Test {
 protected:
  std::string Write(const std::string& text, const std::string& name = "fabrics.csv") const {
    const fs::path path = scratch_.path() / name;
    std::ofstream(path) << text;
    return path.string();
  }
  FabricsSpec Load(const std::string& text, std::vector<std::string> overrides = {}) const {
    FabricsOptions options;
    options.table = Write(text);
    options.overrides = std::move(overrides);
    options.out = (scratch_.path() / "out").string();
    return LoadFabrics(options);
  }
  testing::ScratchFolder scratch_{"fabric_table"};
};

// Every material key of the scene schema is a column, named below material.finite_volume.
TEST_F(FabricTableTest, TheMaterialColumnsAreTheSchemasKeys) {
  std::vector<std::string> names;
  for (const FabricColumn& column : FabricColumns()) names.push_back(column.name);
  for (const char* expected :
       {"density", "D_warp", "D_66", "kes.W", "kes.B_warp", "kes.2HB_warp", "fast.W", "fast.EB5",
        "fast.E100_weft", "bending_length.bias", "bending_friction_warp"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
  for (const FabricColumn& column : FabricColumns()) {
    if (column.kind != FabricColumn::Kind::kMaterial) continue;
    bool in_schema = false;
    for (const SchemaRow& row : SceneSchema()) in_schema |= row.Path() == column.scene_key;
    EXPECT_TRUE(in_schema) << column.scene_key;
  }
}

// The same fabric as a scene names it and as a row gives it: the loader's SI values, bit for bit,
// for KES, FAST and Peirce's bending lengths.
TEST_F(FabricTableTest, KesFastAndBendingLengthRowsGiveTheScenesSiParameters) {
  const std::string table =
      "# a comment line\n"
      "name,kes.W,kes.B_warp,kes.B_weft,kes.G,kes.EMT_warp,kes.EMT_weft,kes.LT_warp,"
      "fast.W,fast.B_warp,fast.B_weft,fast.EB5,fast.E100_warp,fast.E100_weft,"
      "bending_length.warp,bending_length.weft,bending_length.bias,density,G,E_warp,E_weft\n"
      "kes,12,0.12,0.08,0.9,4,7,0.65,,,,,,,,,,,,,\n"
      "fast,,,,,,,,150,7.5,5.2,2.5,2,3,,,,,,,\n"
      "peirce,,,,,,,,,,,,,,2.2,1.9,1.7,0.12,50,8000,5000\n";
  const std::vector<std::string> scenes = {
      "kes: {W: 12, B_warp: 0.12, B_weft: 0.08, G: 0.9, EMT_warp: 4, EMT_weft: 7, LT_warp: 0.65}",
      "fast: {W: 150, B_warp: 7.5, B_weft: 5.2, EB5: 2.5, E100_warp: 2, E100_weft: 3}",
      "bending_length: {warp: 2.2, weft: 1.9, bias: 1.7}, G: 50, E_warp: 8000, E_weft: 5000"};
  const FabricsSpec spec = Load(table);
  ASSERT_EQ(spec.fabrics.size(), 3u);
  for (size_t k = 0; k < scenes.size(); ++k) {
    const std::string text = StandardTesterScene() + "material: {model: finite_volume" +
                             (k == 2 ? ", density: 0.12" : "") + ", finite_volume: {" + scenes[k] +
                             "}}\n";
    const Scene expected = LoadSceneText(text, "<scene>", ".");
    const MaterialSpec& got = spec.fabrics[k].scene.material;
    const FiniteVolumeSpec& a = got.finite_volume;
    const FiniteVolumeSpec& b = expected.material.finite_volume;
    EXPECT_EQ(got.mass_value, expected.material.mass_value) << k;
    EXPECT_EQ(a.D_warp, b.D_warp) << k;
    EXPECT_EQ(a.D_weft, b.D_weft) << k;
    EXPECT_EQ(a.D_66, b.D_66) << k;
    EXPECT_EQ(a.G, b.G) << k;
    EXPECT_EQ(a.E_warp, b.E_warp) << k;
    EXPECT_EQ(a.E_weft, b.E_weft) << k;
    EXPECT_EQ(a.measured.size(), b.measured.size()) << k;
    EXPECT_EQ(spec.fabrics[k].scene.drape_test->specimen_diameter, 0.30);
  }
  EXPECT_EQ(spec.fabrics[1].row.name, "fast");
  EXPECT_EQ(spec.fabrics[1].folder, "fabrics/002-fast");
}

// Every shipped table (configs/fabrics/*.csv) loads: its columns, its values and every row's scene.
TEST_F(FabricTableTest, TheShippedTablesLoad) {
  int tables = 0;
  for (const auto& entry :
       fs::directory_iterator(fs::path(drape_tests::kSourceDir) / "configs/fabrics")) {
    if (entry.path().extension() != ".csv") continue;
    FabricsOptions options;
    options.table = entry.path().string();
    options.out = (scratch_.path() / "out").string();
    const FabricsSpec spec = LoadFabrics(options);
    EXPECT_FALSE(spec.fabrics.empty()) << entry.path();
    ++tables;
  }
  EXPECT_GE(tables, 1);
}

// --set applies to every fabric after its material; the row's specimen_diameter to its own.
TEST_F(FabricTableTest, SetAndTheSpecimenDiameterApply) {
  const FabricsSpec spec = Load(
      "name,density,D_warp,D_weft,G,E_warp,E_weft,specimen_diameter,measured_dc,measured_dc_sd\n"
      "a,0.1,1e-5,1e-5,50,1000,1000,0.24,0.5,0.02\n"
      "b,0.1,1e-5,1e-5,50,1000,1000,,,\n",
      {"material.finite_volume.D_66=0", "mesh.spacing=0.02"});
  EXPECT_EQ(spec.fabrics[0].scene.drape_test->specimen_diameter, 0.24);
  EXPECT_EQ(spec.fabrics[1].scene.drape_test->specimen_diameter, 0.30);
  EXPECT_EQ(spec.fabrics[0].scene.material.finite_volume.D_66, 0.0);
  EXPECT_EQ(spec.fabrics[1].scene.mesh.spacing, 0.02);
  EXPECT_EQ(*spec.fabrics[0].row.measured_dc, 0.5);
  EXPECT_EQ(*spec.fabrics[0].row.measured_dc_sd, 0.02);
  EXPECT_FALSE(spec.fabrics[1].row.measured_dc);
}

// docs/reference.md lists the columns as FabricColumns() has them (DRAPE_WRITE_SCHEMA_DOCS=1
// writes the block instead of comparing it).
TEST(FabricColumns, TheReferenceListsThem) {
  testing::ExpectReferenceBlock("fabric-columns", FabricColumnsMarkdown(), "FabricColumns()");
}

struct BadTable {
  const char* name;
  std::string text;
  std::string where;  // "LINE:COLUMN: key"
  std::string what;
};

class BadFabricTable : public FabricTableTest, public ::testing::WithParamInterface<BadTable> {};

const char kGood[] = "name,kes.W,kes.B_warp,kes.B_weft,kes.G,kes.EMT_warp,kes.EMT_weft\n";

std::vector<BadTable> BadTables() {
  const std::string good = kGood;
  return {
      {"UnitInTheName", "name,B_warp_gf,kes.W\na,1,12\n", "1:2: B_warp_gf",
       "did you mean 'kes.B_warp' (gf·cm²/cm) or 'fast.B_warp' (µN·m)?"},
      {"UnknownColumn", "name,kes.EMT_wrap\na,1\n", "1:2: kes.EMT_wrap",
       "did you mean 'kes.EMT_warp'?"},
      {"NoNameColumn", "kes.W\n12\n", "1:1: name", "the table has no 'name' column"},
      {"ColumnTwice", "name,kes.W,kes.W\na,1,2\n", "1:3: kes.W", "the column is given twice"},
      {"NegativeWeight", good + "a,12,0.1,0.08,0.9,4,7\nb,-3,0.1,0.08,0.9,4,7\n", "3:2: kes.W",
       "must be positive, got -3"},
      {"TextInANumber", good + "a,12,abc,0.08,0.9,4,7\n", "2:3: kes.B_warp",
       "expected a number (gf·cm²/cm), got 'abc'"},
      {"NotFinite", good + "a,12,nan,0.08,0.9,4,7\n", "2:3: kes.B_warp", "expected a number"},
      {"TwoWays",
       "name,kes.W,D_warp,kes.B_warp,kes.B_weft,kes.G,kes.EMT_warp,kes.EMT_weft\n"
       "a,12,1e-5,0.1,0.08,0.9,4,7\n",
       "2:4: kes.B_warp", "give D_warp in one way only"},
      {"MissingParameter", "name,kes.W,kes.B_warp,kes.G\na,12,0.1,0.9\n",
       "2:1:", "fabric 'a': required key 'E_warp' is missing"},
      {"TooManyCells", good + "a,12,0.1,0.08,0.9,4,7,9\n", "2:8:", "the row has 8 cells"},
      {"TooFewCells", good + "a,12,0.1\n", "2:4:", "the row has 3 cells, the header 7"},
      {"NameTwice", good + "a,12,0.1,0.08,0.9,4,7\na,12,0.1,0.08,0.9,4,7\n", "3:1: name",
       "the fabric 'a' is named twice"},
      {"NoName", good + ",12,0.1,0.08,0.9,4,7\n", "2:1: name", "every fabric needs a name"},
      {"Empty", "", "1:1:", "the table is empty"},
      {"HeaderOnly", "# only a header\n" + good, "2:1:", "no fabric"},
      {"DcOutOfRange", "name,measured_dc\na,1.2\n", "2:2: measured_dc", "a fraction in [0, 1]"},
      {"SdWithoutDc", "name,measured_dc_sd\na,0.1\n", "2:2: measured_dc_sd",
       "a standard deviation without measured_dc"},
      {"BadSpecimen",
       good.substr(0, good.size() - 1) + ",specimen_diameter\na,12,0.1,0.08,0.9,4,7,-1\n",
       "2:8: specimen_diameter", "must be positive"},
  };
}

TEST_P(BadFabricTable, IsRefusedAtItsRowAndColumn) {
  const BadTable& bad = GetParam();
  try {
    Load(bad.text);
    FAIL() << "accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("fabrics.csv:" + bad.where), std::string::npos) << message;
    EXPECT_NE(message.find(bad.what), std::string::npos) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(FabricTable, BadFabricTable, ::testing::ValuesIn(BadTables()),
                         [](const auto& test) { return std::string(test.param.name); });

// More rows than kMostFabrics: refused at the first one over.
TEST_F(FabricTableTest, ARowCountOverTheLimitIsRefused) {
  std::string text = "name,measured_dc\n";
  for (int k = 0; k <= kMostFabrics; ++k) text += "f" + std::to_string(k) + ",0.5\n";
  try {
    ReadFabricTable(Write(text));
    FAIL() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, kMostFabrics + 2);
    EXPECT_NE(std::string(error.what()).find("more than 10000 fabrics"), std::string::npos);
  }
}

// A user's --set that the loader refuses is located in --set, numbered as the user gave it.
TEST_F(FabricTableTest, ABadSetIsTheUsersOwn) {
  try {
    Load("name,density,D_warp,D_weft,G,E_warp,E_weft\na,0.1,1e-5,1e-5,50,1000,1000\n",
         {"mesh.spacing=-1"});
    FAIL() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, "--set");
    EXPECT_EQ(error.where().line, 1);
  }
}

}  // namespace
}  // namespace drape
