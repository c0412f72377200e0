// `drape fit` end to end: the outputs fit.json, history.csv, sensitivity.csv, fit.png, report.md,
// the progress lines, and the sensitivity table against a closed-form reference.
#include "src/fit/fit_writer.h"

#include <cairo.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "src/cli/cli.h"
#include "src/output/json.h"
#include "src/output/png_text.h"
#include "src/output/version.h"
#include "tests/fit_test_support.h"
#include "tests/run_program.h"

namespace drape::testing {
namespace {

TEST(FitWriterTest, FitCommandWritesEveryOutput) {
  const std::string folder = FitTempDir("writer");
  const TrueSolve solved =
      SolveTruth("configs/fit/sheet_springs.yaml", {"material.springs.structural=35"});
  WriteNodePositions(solved.model, 0.0, 0, folder + "/nodes.csv");
  WriteTextFile(folder + "/fit_cli.yaml",
                "scene: " + SourcePath("configs/fit/sheet_springs.yaml") +
                    "\nparameters:\n  - {key: material.springs.structural, initial: 20, bounds: "
                    "[1, 1000], log: true}\n  - {key: material.springs.flexion, initial: 0.1, "
                    "bounds: [0.001, 10], log: true}\nmeasurements:\n  - positions: {file: "
                    "nodes.csv}\noutput: {directory: out}\n");
  const std::string out = folder + "/result";
  std::ostringstream stdout_text, stderr_text;
  const int status =
      RunCommand({"fit", folder + "/fit_cli.yaml", "--out", out, "--method", "implicit-lm"},
                 stdout_text, stderr_text);
  EXPECT_EQ(status, kExitConverged) << stderr_text.str();
  for (const char* name :
       {"fit.json", "history.csv", "sensitivity.csv", "fit.png", "report.md", "report.html"}) {
    EXPECT_TRUE(std::filesystem::exists(out + "/" + name)) << name;
  }
  const std::string json = ReadText(out + "/fit.json");
  for (const char* key : {"\"parameters\"", "\"standard_errors\"", "\"correlation\"",
                          "\"objective\"", "\"converged\": true", "\"evaluations\""}) {
    EXPECT_NE(json.find(key), std::string::npos) << key << "\n" << json;
  }
  // The fitted value exact, with its unit beside it, and how the fit was made.
  const YAML::Node table = YAML::Load(json);
  EXPECT_NEAR(table["parameters"]["material.springs.structural"].as<double>(), 35.0, 1e-6);
  EXPECT_EQ(table["units"]["material.springs.structural"].as<std::string>(), "N/m");
  EXPECT_EQ(table["drape_version"].as<std::string>(), DrapeVersion());
  EXPECT_NE(table["command_line"].as<std::string>().find("fit_cli.yaml"), std::string::npos);
  // One history row per evaluation, one progress line per evaluation.
  const std::string history = ReadText(out + "/history.csv");
  const int rows = static_cast<int>(std::count(history.begin(), history.end(), '\n')) - 1;
  const std::string progress = stderr_text.str();
  EXPECT_EQ(static_cast<int>(std::count(progress.begin(), progress.end(), '\n')), rows);
  EXPECT_NE(history.find("evaluation,time_s,objective"), std::string::npos);
  EXPECT_NE(ReadText(out + "/report.md").find("## Identifiability"), std::string::npos);
  // The same report as one page that stands alone: fit.png inside it, the provenance under its
  // title.
  const std::string html = ReadText(out + "/report.html");
  EXPECT_NE(html.find("<h2>Identifiability</h2>"), std::string::npos);
  EXPECT_NE(html.find("src=\"data:image/png;base64,iVBOR"), std::string::npos);
  EXPECT_NE(html.find("<p>drape " + DrapeVersion()), std::string::npos);
  EXPECT_EQ(PngTexts(ReadText(out + "/fit.png")).at("Software"), "drape " + DrapeVersion());
}

// A scalar measurement that is linear in a linear parameter: a drape coefficient-like residual is
// not available in closed form, so the table is checked on positions of a model whose Jacobian is
// given: ∂m/∂θ = J σ / (√w dθ/du).
TEST(FitWriterTest, SensitivityUndoesTheScalingOfTheResiduals) {
  const std::string folder = FitTempDir("sensitivity");
  WriteTextFile(folder + "/nodes.csv", "id,x,y,z\n1,0,0,0\n");
  WriteTextFile(folder + "/fit_s.yaml",
                "scene: " + SourcePath("configs/fit/sheet_springs.yaml") +
                    "\nparameters:\n  - {key: material.springs.structural, initial: 20, bounds: "
                    "[0, 100]}\nmeasurements:\n  - positions: {file: nodes.csv, sigma: 0.002, "
                    "weight: 4}\n");
  FitProblem problem(LoadFitFile(folder + "/fit_s.yaml"));
  FitResult result;
  result.parameters = {20.0};
  result.jacobian = Eigen::MatrixXd::Zero(3, 1);
  result.jacobian(2, 0) = 6.0;  // residual units per u, u = θ / 100
  const std::vector<Sensitivity> table = SensitivityTable(problem, result);
  ASSERT_EQ(table.size(), 1u);
  // RMS over 3 components: 6/√3; × σ/√w = 0.001; / (dθ/du = 100).
  EXPECT_NEAR(table[0].per_parameter, 6.0 / std::sqrt(3.0) * 0.001 / 100.0, 1e-15);
  EXPECT_NEAR(table[0].per_log_parameter, table[0].per_parameter * 20.0, 1e-15);
  EXPECT_EQ(table[0].unit, "m");
}

// fit.png says what was fitted: the caption holds each parameter's key, value and unit and the
// final residual; the picture is as tall as its caption needs.
TEST(FitWriterTest, FitPngShowsTheFittedValuesAndTheResidual) {
  const std::string folder = FitTempDir("png");
  const TrueSolve solved =
      SolveTruth("configs/fit/sheet_springs.yaml", {"material.springs.structural=35"});
  WriteNodePositions(solved.model, 0.0, 0, folder + "/nodes.csv");
  WriteTextFile(folder + "/fit_png.yaml",
                "scene: " + SourcePath("configs/fit/sheet_springs.yaml") +
                    "\nparameters:\n  - {key: material.springs.structural, initial: 20, bounds: "
                    "[1, 1000], log: true}\nmeasurements:\n  - positions: {file: nodes.csv}\n"
                    "method: implicit-lm\n");
  FitProblem problem(LoadFitFile(folder + "/fit_png.yaml"));
  const FitResult result = RunFit(problem);
  ASSERT_TRUE(result.converged) << result.termination;
  const FitPlotText text = FitPlotTextOf(problem, result);
  EXPECT_EQ(text.axis_labels[0], "x (m)");
  EXPECT_EQ(text.axis_labels[2], "z (m)");
  ASSERT_EQ(text.caption.size(), 3u);
  EXPECT_EQ(text.caption[0].rfind(
                "material.springs.structural = " + RoundedNumber(result.parameters[0], 6) +
                    " N/m (standard error ",
                0),
            0u)
      << text.caption[0];
  EXPECT_NEAR(result.parameters[0], 35.0, 1e-3);
  EXPECT_NE(text.caption[1].find("objective 1/2 sum r^2 = " + RoundedNumber(result.objective, 6)),
            std::string::npos)
      << text.caption[1];
  EXPECT_NE(text.caption[2].find("converged yes"), std::string::npos) << text.caption[2];

  WriteFitOutputs(problem, result, folder + "/out");
  cairo_surface_t* png = cairo_image_surface_create_from_png((folder + "/out/fit.png").c_str());
  ASSERT_EQ(cairo_surface_status(png), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_height(png), 40 + 460 + 50 + 18 * 3 + 10);
  cairo_surface_destroy(png);
}

}  // namespace
}  // namespace drape::testing
