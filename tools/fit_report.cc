// Regenerates docs/fitting.md: every fit method of `drape fit` on its validation cases
// (synthetic measurements from known parameters, with and without 0.5 mm Gaussian noise), with
// evaluations, wall time and accuracy.
//
//   build/fit_report [OUTPUT.md]      (default: docs/fitting.md in the source tree)
//
// Each case writes its synthetic data and fit file into a temporary folder, exactly as the tests
// in tests/fit_solver_test.cc do.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "src/fit/fit_file.h"
#include "src/fit/fit_measurements.h"
#include "src/fit/fit_methods.h"
#include "src/fit/fit_problem.h"
#include "src/fit/fit_solver.h"
#include "src/model/model.h"
#include "src/run/run.h"
#include "src/scene/scene_loader.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

std::string Source(const std::string& relative) {
  return std::string(DRAPE_SOURCE_DIR) + "/" + relative;
}

std::string Folder(const std::string& name) {
  const std::string path =
      (fs::temp_directory_path() / ("drape_fit_report_" + name + "_" + std::to_string(::getpid())))
          .string();
  fs::remove_all(path);
  fs::create_directories(path);
  return path;
}

Model SolveTruth(const std::string& scene_file, const std::vector<std::string>& overrides) {
  Scene scene = LoadScene(Source(scene_file), overrides);
  scene.solver.tolerance = 1e-10;
  Model model = BuildModel(scene);
  RunSolve(scene, model, "newton");
  return model;
}

// id,x,y,z of the free nodes, or (cloud) x,y,z of triangle centroids and edge midpoints; noise:
// N(0, noise²) per coordinate, std::mt19937(seed).
void WritePositions(const Model& model, bool cloud, double noise, unsigned seed,
                    const std::string& path) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> gaussian(0.0, noise);
  auto jitter = [&] { return noise > 0 ? gaussian(generator) : 0.0; };
  auto node = [&](int k) {
    return Eigen::Vector3d(model.positions[3 * k], model.positions[3 * k + 1],
                           model.positions[3 * k + 2]);
  };
  std::ofstream out(path);
  out.precision(17);
  if (!cloud) {
    out << "id,x,y,z\n";
    for (int k = 0; k < model.num_nodes; ++k) {
      if (model.fixed[3 * k]) continue;
      const Eigen::Vector3d p = node(k);
      out << k << "," << p.x() + jitter() << "," << p.y() + jitter() << "," << p.z() + jitter()
          << "\n";
    }
    return;
  }
  out << "x,y,z\n";
  for (const auto& t : model.triangles) {
    if (model.fixed[3 * t[0]] && model.fixed[3 * t[1]] && model.fixed[3 * t[2]]) continue;
    for (const Eigen::Vector3d& p : {Eigen::Vector3d((node(t[0]) + node(t[1]) + node(t[2])) / 3.0),
                                     Eigen::Vector3d(0.5 * (node(t[0]) + node(t[1])))}) {
      out << p.x() + jitter() << "," << p.y() + jitter() << "," << p.z() + jitter() << "\n";
    }
  }
}

double DrapeCoefficientOf(const Model& model) {
  FitMeasurement dc;
  dc.kind = FitMeasurement::Kind::kDrapeCoefficient;
  dc.sigma = 0.01;
  MeasurementContext context;
  context.disc_radius = 0.06;
  return EvaluateMeasurement(dc, model, model.positions.data(), context).model_value;
}

// The bending length that the virtual Peirce test of configs/fit/drape_fv.yaml reports for its
// own overhang (fixed point of c → Peirce(2c)).
double SelfConsistentBendingLength() {
  const Scene specimen = LoadScene(Source("configs/fit/drape_fv.yaml"));
  FitMeasurement measurement;
  measurement.kind = FitMeasurement::Kind::kBendingLength;
  measurement.sigma = 0.001;
  measurement.value = std::cbrt(1.0e-4 / (0.15 * 9.81));
  for (int k = 0; k < 8; ++k) {
    Scene strip = PeirceStripScene(specimen, measurement);
    strip.solver.tolerance = 1e-8;
    Model model = BuildModel(strip);
    RunSolve(strip, model, "newton");
    measurement.value =
        EvaluateMeasurement(measurement, model, model.positions.data(), {}).model_value;
  }
  return measurement.value;
}

struct Case {
  std::string name;
  std::string description;
  std::string fit_file;       // written into its folder
  std::vector<double> truth;  // per parameter; NaN: not checked (unidentifiable)
};

std::string Parameter(const std::string& key, double initial, double lower, double upper) {
  char text[200];
  std::snprintf(text, sizeof text,
                "  - {key: %s, initial: %.6g, bounds: [%.6g, %.6g], log: true}\n", key.c_str(),
                initial, lower, upper);
  return text;
}

std::vector<Case> MakeCases() {
  std::vector<Case> cases;
  const std::string springs = Source("configs/fit/sheet_springs.yaml");
  const std::string fv = Source("configs/fit/drape_fv.yaml");
  const Model hammock =
      SolveTruth("configs/fit/sheet_springs.yaml", {"material.springs.structural=35"});
  const Model drape = SolveTruth("configs/fit/drape_fv.yaml", {});
  for (const double noise : {0.0, 0.5e-3}) {
    const std::string tag = noise > 0 ? "_noisy" : "";
    const std::string words = noise > 0 ? ", 0.5 mm noise" : ", noise-free";
    std::string folder = Folder("springs" + tag);
    WritePositions(hammock, false, noise, 1, folder + "/nodes.csv");
    cases.push_back({"springs" + tag,
                     "spring stiffness from node positions" + words,
                     folder + "/fit.yaml",
                     {35.0}});
    std::ofstream(cases.back().fit_file)
        << "scene: " << springs << "\nparameters:\n"
        << Parameter("material.springs.structural", 20, 1, 1000)
        << "measurements:\n  - positions: {file: nodes.csv}\nmax_evaluations: 300\n";
    folder = Folder("scan" + tag);
    WritePositions(drape, true, noise, 7, folder + "/scan.csv");
    cases.push_back({"scan" + tag,
                     "D_warp, D_weft, G from a scanned drape (point cloud)" + words,
                     folder + "/fit.yaml",
                     {1e-4, 5e-5, 5.0}});
    std::ofstream(cases.back().fit_file)
        << "scene: " << fv << "\nparameters:\n"
        << Parameter("material.finite_volume.D_warp", 8e-5, 1e-6, 1e-3)
        << Parameter("material.finite_volume.D_weft", 6e-5, 1e-6, 1e-3)
        << Parameter("material.finite_volume.G", 4, 0.01, 100)
        << "measurements:\n  - positions: {file: scan.csv}\nmax_evaluations: 300\n";
  }
  std::string folder = Folder("dc");
  char value[64];
  std::snprintf(value, sizeof value, "%.17g", DrapeCoefficientOf(drape));
  cases.push_back({"drape_coefficient",
                   "D_warp from a drape coefficient, noise-free",
                   folder + "/fit.yaml",
                   {1e-4}});
  std::ofstream(cases.back().fit_file)
      << "scene: " << fv << "\nparameters:\n"
      << Parameter("material.finite_volume.D_warp", 7e-5, 1e-6, 1e-3)
      << "measurements:\n  - drape_coefficient: {value: " << value
      << ", disc_radius: 0.06}\nmax_evaluations: 300\n";
  folder = Folder("bl");
  std::snprintf(value, sizeof value, "%.17g", SelfConsistentBendingLength());
  cases.push_back(
      {"bending_length", "D_warp from a bending length, noise-free", folder + "/fit.yaml", {1e-4}});
  std::ofstream(cases.back().fit_file)
      << "scene: " << fv << "\nparameters:\n"
      << Parameter("material.finite_volume.D_warp", 4e-5, 1e-6, 1e-3)
      << "measurements:\n  - bending_length: {value: " << value << "}\nmax_evaluations: 300\n";
  folder = Folder("unidentifiable");
  WritePositions(drape, false, 0.0, 0, folder + "/nodes.csv");
  cases.push_back({"unidentifiable",
                   "D_warp and E_warp from node positions of a bending-dominated "
                   "drape (E_warp cannot be identified)",
                   folder + "/fit.yaml",
                   {1e-4, NAN}});
  std::ofstream(cases.back().fit_file)
      << "scene: " << fv << "\nparameters:\n"
      << Parameter("material.finite_volume.D_warp", 8e-5, 1e-6, 1e-3)
      << Parameter("material.finite_volume.E_warp", 1000, 10, 1e5)
      << "measurements:\n  - positions: {file: nodes.csv}\nmax_evaluations: 300\n";
  return cases;
}

struct Row {
  std::string method;
  bool converged = false;
  int evaluations = 0, jacobians = 0;
  double seconds = 0.0;
  double worst_error = 0.0;  // max relative error over the checked parameters
  std::string identifiable;  // yes/no per parameter
};

Row RunCase(const Case& c, const std::string& method) {
  FitSpec spec = LoadFitFile(c.fit_file);
  spec.method = method;
  FitProblem problem(spec);
  const FitResult result = RunFit(problem);
  Row row;
  row.method = method;
  row.converged = result.converged;
  row.evaluations = result.evaluations;
  row.jacobians = result.jacobian_evaluations;
  row.seconds = result.wall_time_s;
  for (size_t j = 0; j < c.truth.size(); ++j) {
    if (!std::isnan(c.truth[j]) && !result.parameters.empty()) {
      row.worst_error = std::max(row.worst_error, std::abs(result.parameters[j] / c.truth[j] - 1));
    }
    row.identifiable +=
        std::string(j ? "/" : "") + (result.parameters.empty()                ? "?"
                                     : result.identifiability.identifiable[j] ? "yes"
                                                                              : "no");
  }
  std::fprintf(stderr, "%-18s %-15s converged %d, %3d evaluations, %6.2f s, error %.2e, %s\n",
               c.name.c_str(), method.c_str(), row.converged, row.evaluations, row.seconds,
               row.worst_error, row.identifiable.c_str());
  return row;
}

void WriteReport(const std::vector<Case>& cases, const std::vector<std::vector<Row>>& rows,
                 std::ostream& out) {
  out << "# Fitting: derivative-free and derivative-based methods compared\n\n"
      << "Generated by `build/fit_report` (tools/fit_report.cc), which writes synthetic "
         "measurements of known parameters (the validation cases of tests/fit_solver_test.cc) and "
         "fits them with every method of `drape fit`. Noise: independent Gaussian N(0, (0.5 "
         "mm)²) on every measured coordinate, std::mt19937 seeded per case. Times are wall-clock "
         "on the machine that ran it (2 cores shared with other builds and tests: indicative "
         "within a factor of about 2), and include every inner newton solve. "
         "`error` is the largest relative error of the identifiable parameters against the known "
         "values; `identifiable` is the fit's own verdict per parameter (docs/reference.md: "
         "Fitting).\n\n"
      << "Methods: `bobyqa`, `nelder-mead`, `sbplx`, `cobyla` are NLopt's derivative-free LN_ "
         "algorithms on the log-parameters; `implicit-lbfgs` (NLopt LD_LBFGS on ½Σr², gradient "
         "Jᵀr) and `implicit-lm` (Ceres Levenberg–Marquardt on r, Jacobian J) use the implicit "
         "derivatives dx*/dθ = −H⁻¹ ∂g/∂θ (one CHOLMOD factorisation of the exact Hessian per "
         "evaluation). `evaluations` counts objective evaluations (each solves every equilibrium); "
         "`with J` how many of them also computed the Jacobian.\n\n";
  for (size_t c = 0; c < cases.size(); ++c) {
    out << "## " << cases[c].name << ": " << cases[c].description << "\n\n"
        << "| method | converged | evaluations | with J | time (s) | error | identifiable |\n"
        << "|---|---|---|---|---|---|---|\n";
    for (const auto& row : rows[c]) {
      char line[300];
      std::snprintf(line, sizeof line, "| %s | %s | %d | %d | %.2f | %.1e | %s |\n",
                    row.method.c_str(), row.converged ? "yes" : "no", row.evaluations,
                    row.jacobians, row.seconds, row.worst_error, row.identifiable.c_str());
      out << line;
    }
    out << "\n";
  }
  out << "## Notes\n\n"
      << "- Every evaluation solves each equilibrium with `newton` to a relative residual of "
         "1e-10 (or its roundoff floor, accepted up to 1e-8), warm-started from the equilibrium "
         "solved at the nearest parameters if they lie within 0.2 in u (22% for a log parameter), "
         "from the flat specimen otherwise (docs/reference.md: Fitting, inner solves). The cost of "
         "an "
         "evaluation is therefore very uneven: a cold start of the 11 × 11 drape takes 50–60 "
         "newton iterations, a warm start near the optimum 0–3.\n"
      << "- A method whose steps are large (the first steps of the derivative-free methods, "
         "L-BFGS's line search) pays cold starts, and can reach parameters where newton does not "
         "converge within the scene's 500 iterations (near a change of the drape's fold pattern, "
         "e.g. D_warp ≈ 4e-5 N·m for this fabric): such an evaluation counts as failed (a large "
         "objective for NLopt, a rejected step for Ceres) and costs the whole iteration budget.\n"
      << "- The drape coefficient is rasterised (noise ~1e-6), so the derivative-free methods "
         "end on a noisy objective; the implicit Jacobian differentiates the shadow with a step "
         "of 2e-3 of the specimen's size along dx*/dθ.\n"
      << "- With noise, every method converges to the same least-squares optimum (same error); "
         "the error is then that of the data, not of the method.\n"
      << "- `converged` no is the method's own verdict, not the error's: sbplx and cobyla stop at "
         "their evaluation limit, and implicit-lbfgs can end in NLopt's generic failure "
         "(NLOPT_FAILURE) where the objective is flat to rounding near the optimum. `drape fit` "
         "then reports the best point it evaluated, with that reason as its termination.\n\n";
}

}  // namespace
}  // namespace drape

int main(int argc, char** argv) {
  const std::string output =
      argc > 1 ? argv[1] : std::string(DRAPE_SOURCE_DIR) + "/docs/fitting.md";
  const std::vector<drape::Case> cases = drape::MakeCases();
  std::vector<std::vector<drape::Row>> rows(cases.size());
  for (size_t c = 0; c < cases.size(); ++c) {
    for (const auto& method : drape::FitMethods())
      rows[c].push_back(drape::RunCase(cases[c], method));
  }
  std::ostringstream text;
  drape::WriteReport(cases, rows, text);
  std::ofstream(output) << text.str() << "Command: `build/fit_report` (Release build).\n";
  std::cout << "wrote " << output << "\n";
  return 0;
}
