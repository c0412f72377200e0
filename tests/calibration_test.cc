// A calibration of the fabric's inputs (src/scene/calibration.h): each constant changes the
// rigidities as its formula says and nothing else, the uncalibrated values leave a scene as it
// is, a calibration file is read with every error located, and docs/reference.md lists the
// constants as CalibrationConstants() has them.
#include "src/scene/calibration.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "src/scene/fabric_parameters.h"
#include "src/scene/scene_loader.h"
#include "tests/reference_block.h"
#include "tests/scratch_folder.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// A finite-volume drape test with rigidities on either side of D_ref = 1 µN·m.
Scene FromText(const std::string& text) { return LoadSceneText(text, "<scene>", "."); }

Scene CalibrationScene(const std::string& extra = "") {
  return FromText(
      "name: calibrated\n"
      "drape_test: {specimen_diameter: 0.30}\n"
      "mesh: {spacing: 0.05}\n"
      "material:\n"
      "  model: finite_volume\n"
      "  density: 0.15\n"
      "  finite_volume: {E_warp: 500, E_weft: 400, G: 40, D_warp: 4.0e-6, D_weft: 0.25e-6" +
      extra + "}\n");
}

Calibration Values(std::vector<std::pair<std::string, double>> values) {
  Calibration calibration;
  calibration.values = std::move(values);
  return calibration;
}

TEST(Calibration, TheUncalibratedValuesLeaveTheSceneAsItIs) {
  Scene scene = CalibrationScene();
  const FiniteVolumeSpec before = scene.material.finite_volume;
  std::vector<std::pair<std::string, double>> values;
  for (const CalibrationConstant& c : CalibrationConstants()) {
    values.emplace_back(c.name, c.uncalibrated);
    EXPECT_NE(std::find(c.grid.begin(), c.grid.end(), c.uncalibrated), c.grid.end())
        << c.name << ": --calibrate's grid holds the uncalibrated value (the 'before' solve)";
    EXPECT_TRUE(std::is_sorted(c.grid.begin(), c.grid.end())) << c.name;
    EXPECT_GE(c.grid.front(), c.low) << c.name;
    EXPECT_LE(c.grid.back(), c.high) << c.name;
  }
  ApplyCalibration(Values(values), &scene);
  const FiniteVolumeSpec& after = scene.material.finite_volume;
  EXPECT_EQ(after.D_warp, before.D_warp);
  EXPECT_EQ(after.D_weft, before.D_weft);
  EXPECT_EQ(after.D_66, before.D_66);
  EXPECT_EQ(after.G, before.G);
  EXPECT_EQ(after.bending_friction_warp, 0.0);
}

// D' = s · D · (D / 1 µN·m)^p in each direction; the default twist follows the new rigidities.
TEST(Calibration, TheBendingConstantsFollowTheirFormula) {
  Scene scene = CalibrationScene();
  ApplyCalibration(Values({{"bending_scale", 1.5}, {"bending_power", 0.5}}), &scene);
  const FiniteVolumeSpec& fv = scene.material.finite_volume;
  EXPECT_DOUBLE_EQ(fv.D_warp, 1.5 * 4.0e-6 * 2.0);   // (4)^0.5 = 2
  EXPECT_DOUBLE_EQ(fv.D_weft, 1.5 * 0.25e-6 * 0.5);  // (0.25)^0.5 = 0.5
  EXPECT_EQ(fv.twist_source, FiniteVolumeSpec::TwistSource::kDefault);
  EXPECT_DOUBLE_EQ(fv.D_66, DefaultTorsionalRigidity(fv.D_warp, fv.D_weft));
  EXPECT_EQ(fv.G, 40.0);
}

// A given D_66 takes the geometric mean of the two directions' factors.
TEST(Calibration, AGivenTwistTakesTheMeanFactor) {
  Scene scene = CalibrationScene(", D_66: 0.3e-6");
  ApplyCalibration(Values({{"bending_power", 1.0}}), &scene);
  EXPECT_DOUBLE_EQ(scene.material.finite_volume.D_66, 0.3e-6 * std::sqrt(4.0 * 0.25));
}

// H = h · D' where the fabric has no bending friction; a given friction is kept.
TEST(Calibration, TheFrictionShareFillsOnlyAMissingFriction) {
  Scene scene = CalibrationScene();
  ApplyCalibration(Values({{"bending_scale", 2.0}, {"bending_friction_share", 50.0}}), &scene);
  EXPECT_DOUBLE_EQ(scene.material.finite_volume.bending_friction_warp, 50.0 * 8.0e-6);
  EXPECT_DOUBLE_EQ(scene.material.finite_volume.bending_friction_weft, 50.0 * 0.5e-6);

  Scene given = CalibrationScene(", bending_friction_warp: 1.0e-4");
  ApplyCalibration(Values({{"bending_friction_share", 50.0}}), &given);
  EXPECT_EQ(given.material.finite_volume.bending_friction_warp, 1.0e-4);
  EXPECT_EQ(given.material.finite_volume.bending_friction_weft, 0.0);
}

// f · H on a given friction; a fabric given none keeps none (the share gives it one).
TEST(Calibration, TheFrictionScaleScalesOnlyAGivenFriction) {
  Scene given = CalibrationScene(", bending_friction_warp: 1.0e-4, bending_friction_weft: 2.0e-4");
  ApplyCalibration(Values({{"bending_friction_scale", 0.25}, {"bending_friction_share", 50.0}}),
                   &given);
  EXPECT_DOUBLE_EQ(given.material.finite_volume.bending_friction_warp, 0.25e-4);
  EXPECT_DOUBLE_EQ(given.material.finite_volume.bending_friction_weft, 0.5e-4);
  Scene none = CalibrationScene();
  ApplyCalibration(Values({{"bending_friction_scale", 0.25}}), &none);
  EXPECT_EQ(none.material.finite_volume.bending_friction_warp, 0.0);
}

TEST(Calibration, TheShearScaleScalesG) {
  Scene scene = CalibrationScene();
  ApplyCalibration(Values({{"shear_scale", 0.5}}), &scene);
  EXPECT_DOUBLE_EQ(scene.material.finite_volume.G, 20.0);
  EXPECT_EQ(scene.material.finite_volume.D_warp, 4.0e-6);
}

TEST(Calibration, ASceneItCannotCalibrateIsRefused) {
  Scene springs = FromText(
      "name: springs\nmesh: {size: [1, 1], nodes: [3, 3]}\n"
      "material: {density: 0.1, springs: {structural: 100}}\n");
  try {
    ApplyCalibration(Values({{"bending_scale", 2.0}}), &springs);
    FAIL() << "a springs material was calibrated";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("applies to a finite_volume material"),
              std::string::npos)
        << error.what();
  }
  Scene region = FromText(
      "name: region\ndrape_test: {specimen_diameter: 0.30}\nmesh: {spacing: 0.05}\n"
      "material: {model: finite_volume, density: 0.15, finite_volume: {E_warp: 500, E_weft: 400, "
      "G: 40, D_warp: 4.0e-6, D_weft: 0.25e-6}}\n"
      "regions: [{name: hem, nodes: {outside: {center: [0, 0, 0.001], radius: 0.14}}, "
      "D_warp: 1.0e-5}]\n");
  EXPECT_THROW(ApplyCalibration(Values({{"bending_scale", 2.0}}), &region), InputError);
  EXPECT_NO_THROW(ApplyCalibration(Values({{"shear_scale", 2.0}}), &region));
}

class CalibrationFileTest : public ::testing::Test {
 protected:
  std::string Write(const std::string& text) const {
    const fs::path path = scratch_.path() / "calibration.yaml";
    std::ofstream(path) << text;
    return path.string();
  }
  std::string ErrorOf(const std::string& text) const {
    try {
      ReadCalibration(Write(text));
    } catch (const InputError& error) {
      return error.what();
    }
    ADD_FAILURE() << "accepted: " << text;
    return "";
  }
  testing::ScratchFolder scratch_{"calibration"};
};

TEST_F(CalibrationFileTest, WhatItWritesItReads) {
  const Calibration written =
      Values({{"bending_scale", 1.6180339887}, {"bending_friction_share", 25}});
  const Calibration read = ReadCalibration(
      Write(CalibrationYaml(written, {"a comment"}, "  table: t.csv\n  fabrics: 7\n")));
  EXPECT_EQ(read.values, written.values);
  EXPECT_EQ(read.Text(), "bending_scale 1.61803, bending_friction_share 25 1/m");
}

TEST_F(CalibrationFileTest, EachErrorIsLocated) {
  EXPECT_NE(ErrorOf("calibration: {bending_scal: 2}\n")
                .find("calibration.yaml:1:15: calibration.bending_scal: unknown key"),
            std::string::npos)
      << ErrorOf("calibration: {bending_scal: 2}\n");
  EXPECT_NE(ErrorOf("calibration: {bending_scal: 2}\n").find("did you mean 'bending_scale'"),
            std::string::npos);
  EXPECT_NE(ErrorOf("calibration:\n  bending_scale: 1000\n")
                .find(":2:18: calibration.bending_scale: must be in [0.01, 100], got 1000"),
            std::string::npos)
      << ErrorOf("calibration:\n  bending_scale: 1000\n");
  EXPECT_NE(ErrorOf("calibration: {}\n").find("names no constant"), std::string::npos);
  EXPECT_NE(ErrorOf("").find("an empty calibration file"), std::string::npos);
  EXPECT_NE(ErrorOf("calibration: {bending_scale: 2}\nscale: 3\n").find("scale"),
            std::string::npos);
  EXPECT_NE(ErrorOf("fitted: {}\n").find("calibration"), std::string::npos);
}

// docs/reference.md lists the constants as CalibrationConstants() has them
// (DRAPE_WRITE_SCHEMA_DOCS=1 writes the block instead of comparing it).
TEST(CalibrationConstants, TheReferenceListsThem) {
  testing::ExpectReferenceBlock("calibration-constants", CalibrationConstantsMarkdown(),
                                "CalibrationConstants()");
}

}  // namespace
}  // namespace drape
