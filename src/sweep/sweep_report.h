// The sweep's report: OUT/sweep.html, one self-contained page (src/output/report_page.h) whose
// charts are inline SVG (src/output/svg_chart.h) — each response (drape coefficient, energy,
// iterations, time) against each varied numeric key, and a heat map of the drape coefficient (else
// the energy) when the sweep is a grid of exactly two axes — above the table of tasks. Read from
// OUT/sweep.csv; missing values are empty cells there and are skipped by the charts.
#ifndef DRAPE_SRC_SWEEP_SWEEP_REPORT_H_
#define DRAPE_SRC_SWEEP_SWEEP_REPORT_H_

#include <string>

#include "src/output/provenance.h"
#include "src/sweep/sweep_file.h"

namespace drape {

// Writes sweep.html into `directory` (which holds sweep.csv); `provenance` heads the page.
void WriteSweepReport(const SweepSpec& spec, const std::string& directory,
                      const Provenance& provenance);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_SWEEP_REPORT_H_
