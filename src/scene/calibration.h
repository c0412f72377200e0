// A laboratory's calibration of the finite-volume fabric's inputs: a few global constants that map
// every fabric's given inputs to the rigidities drape solves with, fitted by `drape fabrics TABLE
// --calibrate KEY...` to the lab's measured drape coefficients (src/sweep/calibrate.h) and taken
// by later runs as `--calibration FILE` (docs/reference.md, "Calibration").
//
// Why such constants exist: a simulator's inputs are converted from a lab's instruments, and the
// conversion is the uncertain part (KES-FB2's B is the moment–curvature slope at 0.5–1.5 cm⁻¹ and
// leaves out the stiff start of the curve a drape's small curvatures follow; the fibre friction
// 2HB is rarely published). Commercial simulators are calibrated the same way (CLO's fabric kit;
// the KES→simulator relations fitted in the literature). Each constant's uncalibrated value leaves
// the model as it is; docs/validation.md measures what each does on published fabrics.
//
// The constants (CalibrationConstants(), the one list; a test holds docs/reference.md to it):
//   bending_scale s and bending_power p: each bending rigidity D (warp, weft) becomes
//     D' = s · D · (D / D_ref)^p with D_ref = 1 µN·m (woven fabrics' 0.3–10 µN·m), the power law a
//     conversion that is not proportional takes; D_12 and a given or bias D_66 take the geometric
//     mean of the warp's and weft's factors, a default D_66 is the default rule of the new D's;
//   shear_scale: G' = shear_scale · G;
//   bending_friction_scale f: a given bending friction H (KES 2HB/2) becomes f · H, the part of
//     the hysteresis of KES-FB2's loop (to ±2.5 cm⁻¹) that acts in a drape settled from flat;
//   bending_friction_share h (1/m): a fabric given no bending friction gets H = h · D' in each
//     direction (KES 2HB/2 in proportion to B; the one published pair, Matsudaira's cotton broad,
//     has 2HB/2 / B = 52.5 m⁻¹).
#ifndef DRAPE_SRC_SCENE_CALIBRATION_H_
#define DRAPE_SRC_SCENE_CALIBRATION_H_

#include <string>
#include <utility>
#include <vector>

#include "src/scene/scene.h"

namespace drape {

struct CalibrationConstant {
  std::string name;          // "bending_scale"
  std::string unit;          // "1", "1/m"
  double uncalibrated = 0;   // the value that leaves the model as it is
  double low = 0, high = 0;  // accepted in a calibration file
  std::vector<double> grid;  // the values --calibrate solves at; holds `uncalibrated`
  std::string doc;           // one line, for the reference
};

const std::vector<CalibrationConstant>& CalibrationConstants();

// The constant named `name`, or null.
const CalibrationConstant* FindCalibrationConstant(const std::string& name);

// D_ref of bending_power, N·m.
constexpr double kCalibrationReferenceRigidity = 1e-6;

// docs/reference.md's table of the constants (between `<!-- calibration-constants -->` and
// `<!-- /calibration-constants -->`).
std::string CalibrationConstantsMarkdown();

struct Calibration {
  std::vector<std::pair<std::string, double>> values;  // in CalibrationConstants() order
  std::string file;                                    // where it was read; "" if made here

  bool empty() const { return values.empty(); }
  // The value of `name`, its uncalibrated value where not given.
  double Value(const std::string& name) const;
  // "bending_scale 1.5, bending_friction_share 25 1/m" ("none" when empty).
  std::string Text() const;
  // "bending_scale=0.8333333333333334": every digit, for a result's identity.
  std::string ExactText() const;
  // "calibration.yaml (bending_scale 1.5)": the file and the values, for the provenance.
  std::string Provenance() const;
};

// Reads a calibration file:
//   calibration: {bending_scale: 1.5, bending_friction_share: 25}
//   fitted: {...}   # what --calibrate wrote about the fit; not read
// Throws InputError, located, for an unknown constant (with the nearest), a value outside its
// range, an empty calibration, or any other key.
Calibration ReadCalibration(const std::string& path);

// The calibration's YAML text: the comment lines, `calibration:` and `fitted:` (already YAML, a
// map's body indented by two spaces; may be empty).
std::string CalibrationYaml(const Calibration& calibration,
                            const std::vector<std::string>& comment_lines,
                            const std::string& fitted_body);

// Applies `calibration` to `scene`'s finite-volume material. Throws InputError, located at the
// calibration (its file, or `label` for one made in memory), when the scene has no finite-volume
// material, or a region sets what a constant rescales (its rigidities would not be calibrated).
void ApplyCalibration(const Calibration& calibration, Scene* scene,
                      const std::string& label = "--calibration");

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_CALIBRATION_H_
