// The report of `drape fabrics`, OUT/report.html: one self-contained page (its chart inline SVG,
// its pictures embedded PNG) with the summary line, the measured-against-predicted chart (both
// error bars and the line y = x), the table of fabrics, what a lab should quote, and each
// fabric's shadow (its single solve's, or its first drop's).
#ifndef DRAPE_SRC_SWEEP_FABRICS_REPORT_H_
#define DRAPE_SRC_SWEEP_FABRICS_REPORT_H_

#include <ostream>
#include <string>
#include <vector>

#include "src/output/provenance.h"
#include "src/sweep/fabrics.h"

namespace drape {

// The chart alone (SVG text): a point per fabric with both a prediction and a measurement, the
// prediction's error bar vertical, the measured SD horizontal, the diagonal; its title says how
// many fabrics it shows.
std::string MeasuredAgainstPredictedChart(const FabricsSpec& spec,
                                          const std::vector<FabricPrediction>& predictions);

void WriteFabricsReport(const FabricsSpec& spec, const std::vector<FabricPrediction>& predictions,
                        const FabricsSummary& summary, const Provenance& provenance,
                        std::ostream& html);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_FABRICS_REPORT_H_
