#include "src/scene/calibration.h"

#include <cassert>
#include <cmath>
#include <cstdio>

#include "src/scene/fabric_parameters.h"
#include "src/scene/number_text.h"
#include "src/scene/yaml_reader.h"

namespace drape {
namespace {

// Geometric steps of 1.5 about 1: from 1/2.25 to 3.375 (the factors the published fabrics'
// measured DCs ask of their bending, ×1.1–×2.5, lie inside).
const std::vector<double>& ScaleGrid() {
  static const std::vector<double> grid = {1.0 / 2.25, 1.0 / 1.5, 1.0, 1.5, 2.25, 3.375};
  return grid;
}

std::string Number(double value, const char* format = "%.6g") {
  char text[40];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

bool IsUncalibrated(const Calibration& calibration, const std::string& name) {
  const CalibrationConstant* constant = FindCalibrationConstant(name);
  assert(constant);
  return calibration.Value(name) == constant->uncalibrated;
}

InputError CalibrationError(const Calibration& calibration, const std::string& label,
                            const std::string& key, const std::string& what) {
  return InputError(Location{calibration.file.empty() ? label : calibration.file,
                             calibration.file.empty() ? 0 : 1, calibration.file.empty() ? 0 : 1,
                             "calibration." + key},
                    what);
}

// A region that sets a rigidity a constant rescales would keep its own value uncalibrated.
void RefuseRegionsItRescales(const Calibration& calibration, const Scene& scene,
                             const std::string& label) {
  const bool bending = !IsUncalibrated(calibration, "bending_scale") ||
                       !IsUncalibrated(calibration, "bending_power");
  const bool shear = !IsUncalibrated(calibration, "shear_scale");
  for (const RegionSpec& region : scene.regions) {
    for (const auto& [key, value] : region.finite_volume) {
      const bool rescaled = (bending && key.rfind("D_", 0) == 0) || (shear && key == "G");
      if (!rescaled) continue;
      throw CalibrationError(
          calibration, label, bending && key != "G" ? "bending_scale" : "shear_scale",
          "the scene's region " +
              (region.name.empty() ? std::string("") : "'" + region.name + "' ") + "sets " + key +
              ", which the calibration would leave uncalibrated; calibrate a "
              "scene whose regions do not set the rigidities it rescales");
    }
  }
}

// D' = s · D · (D / D_ref)^p.
double BendingFactor(const Calibration& calibration, double rigidity) {
  const double scale = calibration.Value("bending_scale");
  const double power = calibration.Value("bending_power");
  if (rigidity <= 0.0 || power == 0.0) return scale;
  return scale * std::pow(rigidity / kCalibrationReferenceRigidity, power);
}

}  // namespace

const std::vector<CalibrationConstant>& CalibrationConstants() {
  static const std::vector<CalibrationConstant> constants = {
      {"bending_scale", "1", 1.0, 0.01, 100.0, ScaleGrid(),
       "s: every bending rigidity times s (D_warp, D_weft, D_12, D_66)"},
      {"bending_power",
       "1",
       0.0,
       -1.0,
       2.0,
       {-0.2, 0.0, 0.2, 0.4, 0.6, 0.8},
       "p: each bending rigidity D becomes s · D · (D / 1 µN·m)^p, a conversion that is not "
       "proportional"},
      {"shear_scale", "1", 1.0, 0.01, 100.0, ScaleGrid(),
       "the in-plane shear rigidity G times this"},
      {"bending_friction_scale",
       "1",
       1.0,
       0.0,
       10.0,
       {0.0, 0.25, 0.5, 0.75, 1.0, 1.5},
       "a given bending friction H times this: the part of KES 2HB/2 that acts in a settled "
       "drape"},
      {"bending_friction_share",
       "1/m",
       0.0,
       0.0,
       10000.0,
       {0.0, 12.5, 25.0, 50.0, 100.0, 200.0},
       "h: a fabric given no bending friction gets H = h · D in each direction (KES 2HB/2 in "
       "proportion to B; Matsudaira's cotton broad: 52.5 1/m)"},
  };
  return constants;
}

const CalibrationConstant* FindCalibrationConstant(const std::string& name) {
  for (const CalibrationConstant& constant : CalibrationConstants()) {
    if (constant.name == name) return &constant;
  }
  return nullptr;
}

std::string CalibrationConstantsMarkdown() {
  std::string text =
      "| constant | unit | uncalibrated | accepted | --calibrate solves at | meaning |\n"
      "|---|---|---|---|---|---|\n";
  for (const CalibrationConstant& c : CalibrationConstants()) {
    std::string grid;
    for (const double value : c.grid) grid += (grid.empty() ? "" : ", ") + Number(value, "%.4g");
    text += "| `" + c.name + "` | " + c.unit + " | " + Number(c.uncalibrated) + " | " +
            Number(c.low) + " to " + Number(c.high) + " | " + grid + " | " + c.doc + " |\n";
  }
  return text;
}

double Calibration::Value(const std::string& name) const {
  for (const auto& [key, value] : values) {
    if (key == name) return value;
  }
  const CalibrationConstant* constant = FindCalibrationConstant(name);
  assert(constant && "a constant of CalibrationConstants()");
  return constant->uncalibrated;
}

std::string Calibration::Text() const {
  if (values.empty()) return "none";
  std::string text;
  for (const auto& [key, value] : values) {
    const std::string& unit = FindCalibrationConstant(key)->unit;
    text +=
        (text.empty() ? "" : ", ") + key + " " + Number(value) + (unit == "1" ? "" : " " + unit);
  }
  return text;
}

std::string Calibration::ExactText() const {
  std::string text;
  for (const auto& [key, value] : values) {
    text += (text.empty() ? "" : ", ") + key + "=" + FormatNumber(value);
  }
  return text;
}

std::string Calibration::Provenance() const {
  return (file.empty() ? std::string("fitted here") : file) + " (" + Text() + ")";
}

Calibration ReadCalibration(const std::string& path) {
  const YAML::Node root = ReadYamlFile(path, "calibration file");
  const YamlOrigins origins(path);
  const YamlValue document = YamlRoot(root, origins);
  if (!root || root.IsNull()) Fail(document, "an empty calibration file (expected `calibration:`)");
  const YamlMap top(document, {"calibration", "fitted"});
  const YamlValue constants = top.Get("calibration");
  std::vector<std::string> names;
  for (const CalibrationConstant& c : CalibrationConstants()) names.push_back(c.name);
  const YamlMap given(constants, names);
  if (given.Keys().empty()) {
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
    Fail(constants, "names no constant (expected one or more of: " + list + ")");
  }
  Calibration calibration;
  calibration.file = path;
  for (const CalibrationConstant& c : CalibrationConstants()) {
    const std::optional<YamlValue> value = given.Find(c.name);
    if (!value) continue;
    const double number = ReadNumber(*value);
    if (number < c.low || number > c.high) {
      Fail(*value, "must be in [" + FormatNumber(c.low) + ", " + FormatNumber(c.high) + "], got " +
                       FormatNumber(number));
    }
    calibration.values.emplace_back(c.name, number);
  }
  return calibration;
}

std::string CalibrationYaml(const Calibration& calibration,
                            const std::vector<std::string>& comment_lines,
                            const std::string& fitted_body) {
  std::string text;
  for (const std::string& line : comment_lines) text += "# " + line + "\n";
  text += "calibration:\n";
  for (const auto& [key, value] : calibration.values) {
    text += "  " + key + ": " + FormatNumber(value) + "\n";
  }
  if (!fitted_body.empty()) text += "fitted:\n" + fitted_body;
  return text;
}

void ApplyCalibration(const Calibration& calibration, Scene* scene, const std::string& label) {
  if (calibration.empty()) return;
  switch (scene->material.model) {  // a switch: a new model names itself here (-Wswitch)
    case MaterialModel::kFiniteVolume:
      break;
    case MaterialModel::kSprings:
      throw CalibrationError(calibration, label, calibration.values.front().first,
                             "a calibration applies to a finite_volume material; scene '" +
                                 scene->name + "' has springs");
  }
  RefuseRegionsItRescales(calibration, *scene, label);
  FiniteVolumeSpec& fv = scene->material.finite_volume;
  const double warp = BendingFactor(calibration, fv.D_warp);
  const double weft = BendingFactor(calibration, fv.D_weft);
  const double both = std::sqrt(warp * weft);
  fv.D_warp *= warp;
  fv.D_weft *= weft;
  fv.D_12 *= both;
  fv.D_66 = fv.twist_source == FiniteVolumeSpec::TwistSource::kDefault
                ? DefaultTorsionalRigidity(fv.D_warp, fv.D_weft)
                : fv.D_66 * both;
  fv.G *= calibration.Value("shear_scale");
  const double friction = calibration.Value("bending_friction_scale");
  const bool given = fv.bending_friction_warp > 0.0 || fv.bending_friction_weft > 0.0;
  fv.bending_friction_warp *= friction;
  fv.bending_friction_weft *= friction;
  const double share = calibration.Value("bending_friction_share");
  if (share > 0.0 && !given) {
    fv.bending_friction_warp = share * fv.D_warp;
    fv.bending_friction_weft = share * fv.D_weft;
  }
}

}  // namespace drape
