// The report of `drape fabrics --calibrate`, OUT/report.html: the result line, predicted against
// measured before and after the calibration with each fabric's leave-one-out prediction, each
// fabric's DC along the constant's grid (one constant) or the fit's RMS over the grid (two), the
// table of fabrics, and how to use the calibration.
#ifndef DRAPE_SRC_SWEEP_CALIBRATE_REPORT_H_
#define DRAPE_SRC_SWEEP_CALIBRATE_REPORT_H_

#include <ostream>
#include <string>

#include "src/output/provenance.h"
#include "src/sweep/calibrate.h"

namespace drape {

// The charts alone (SVG text).
std::string CalibrationChart(const CalibrateSummary& summary);
std::string CalibrationGridChart(const CalibrateSummary& summary);

void WriteCalibrateReport(const CalibrateSummary& summary, const Provenance& provenance,
                          std::ostream& html);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_CALIBRATE_REPORT_H_
