// `drape fabrics --calibrate` (src/sweep/calibrate.h) end to end on the standard tester at 5 cm:
// given "measured" drape coefficients that drape itself predicts at a known bending scale, the
// calibration finds that scale, its leave-one-out predictions meet them, the file it writes is
// one `--calibration` reads back to the same solves; and a table too small to fit, an unknown
// constant or a calibration with --calibration is refused before anything is solved.
#include "src/sweep/calibrate.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "src/output/atomic_file.h"
#include "src/output/csv_field.h"
#include "tests/scratch_folder.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// Three fabrics of different stiffness; measured_dc is filled in by the test.
constexpr char kCalibrationHeader[] =
    "name,kes.W,kes.B_warp,kes.B_weft,kes.G,kes.EMT_warp,kes.EMT_weft";
const std::vector<std::string> kCalibrationRows = {
    "stiff,12,0.12,0.08,0.9,4,7", "middle,10,0.05,0.05,0.6,4,7", "limp,8,0.02,0.02,0.4,4,7"};

class CalibrateTest : public ::testing::Test {
 protected:
  FabricsOptions Options(const std::vector<std::string>& measured, const std::string& out) const {
    std::string table = kCalibrationHeader;
    table += measured.empty() ? "\n" : ",measured_dc\n";
    for (size_t k = 0; k < kCalibrationRows.size(); ++k) {
      table += kCalibrationRows[k] + (measured.empty() ? "" : "," + measured[k]) + "\n";
    }
    const fs::path path = scratch_.path() / (out + ".csv");
    std::ofstream(path) << table;
    FabricsOptions options;
    options.table = path.string();
    options.overrides = {"mesh.spacing=0.05"};
    options.out = (scratch_.path() / out).string();
    options.threads = 1;
    options.command_line = "drape fabrics " + out + ".csv";
    return options;
  }
  testing::ScratchFolder scratch_{"calibrate"};
};

TEST_F(CalibrateTest, FindsTheBendingScaleThatMadeTheMeasurements) {
  // The "measurements": drape's own DCs with every bending rigidity × 1.5, a point of the grid.
  FabricsOptions truth = Options({}, "truth");
  truth.calibration.values = {{"bending_scale", 1.5}};
  std::ostringstream log;
  const FabricsSummary measured = RunFabrics(LoadFabrics(truth), truth, log);
  std::vector<std::string> dcs;
  for (const FabricPrediction& p : measured.predictions) {
    ASSERT_TRUE(p.drape_coefficient) << p.state;
    dcs.push_back(CsvNumber(*p.drape_coefficient));
  }
  ASSERT_NE(dcs.front(), dcs.back());

  FabricsOptions options = Options(dcs, "calibration");
  options.calibrate = {"bending_scale"};
  const CalibrateSummary s = RunCalibrate(options, log);
  ASSERT_TRUE(s.problem.empty()) << s.problem;
  EXPECT_EQ(s.fitted_fabrics, 3);
  EXPECT_EQ(s.fitted.Value("bending_scale"), 1.5);
  EXPECT_NEAR(s.fit.rms, 0.0, 1e-12);
  EXPECT_NEAR(s.after.mean_abs_difference, 0.0, 1e-12);  // the same solves as the measurements
  EXPECT_GT(s.before.mean_abs_difference, 0.01);         // the scale matters at this lattice
  for (const auto& left : s.left_out) {
    ASSERT_TRUE(left);
    EXPECT_EQ(left->fit.values[0], 1.5);
    EXPECT_NEAR(left->difference, 0.0, 1e-12);
  }
  EXPECT_EQ(s.solves, 6 * 3 + 3);  // the grid's six points and the calibrated table

  // The file it wrote gives a later run the calibrated solves.
  const fs::path file = fs::path(s.directory) / "calibration.yaml";
  const Calibration read = ReadCalibration(file.string());
  EXPECT_EQ(read.Value("bending_scale"), 1.5);
  FabricsOptions later = Options(dcs, "later");
  later.calibration = read;
  const FabricsSummary again = RunFabrics(LoadFabrics(later), later, log);
  EXPECT_NEAR(again.statistics.mean_abs_difference, 0.0, 1e-12);
  const std::string json = ReadWholeFile(fs::path(later.out) / "fabrics.json");
  EXPECT_NE(json.find("\"calibration\": \"" + file.string() + " (bending_scale 1.5)\""),
            std::string::npos)
      << json;
  for (const char* name : {"calibration.csv", "calibration.json", "report.html"}) {
    EXPECT_TRUE(fs::exists(fs::path(s.directory) / name)) << name;
  }

  // A re-run keeps every solve.
  std::ostringstream rerun;
  EXPECT_EQ(RunCalibrate(options, rerun).solves, 0);
}

TEST_F(CalibrateTest, RefusesWhatItCannotFitBeforeSolving) {
  FabricsOptions small = Options({"0.5", "0.4", ""}, "small");
  small.calibrate = {"bending_scale"};
  std::ostringstream log;
  try {
    RunCalibrate(small, log);
    FAIL() << "a table of two measured fabrics was calibrated";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("needs at least 3 fabrics with a measured_dc"),
              std::string::npos)
        << error.what();
  }
  EXPECT_FALSE(fs::exists(small.out));

  FabricsOptions unknown = Options({"0.5", "0.4", "0.3"}, "unknown");
  unknown.calibrate = {"bending_scal"};
  try {
    RunCalibrate(unknown, log);
    FAIL() << "an unknown constant was calibrated";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("--calibrate:1:1: bending_scal: not a calibration "
                        "constant; did you mean 'bending_scale'?"),
              std::string::npos)
        << error.what();
  }
  unknown.calibrate = {"bending_scale", "bending_scale"};
  EXPECT_THROW(RunCalibrate(unknown, log), InputError);
  unknown.calibrate = {"bending_scale", "bending_power", "shear_scale"};
  EXPECT_THROW(RunCalibrate(unknown, log), InputError);
  unknown.calibrate = {"bending_scale"};
  unknown.calibration.values = {{"shear_scale", 2.0}};
  EXPECT_THROW(RunCalibrate(unknown, log), InputError);
  EXPECT_FALSE(fs::exists(unknown.out));
  EXPECT_TRUE(log.str().empty()) << log.str();
}

}  // namespace
}  // namespace drape
