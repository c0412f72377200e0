// The sweep's report: OUT/sweep.html with gnuplot PNGs under OUT/plots/ — each response (drape
// coefficient, energy, iterations, time) against each varied numeric key, and a heat map of the
// drape coefficient (else the energy) when the sweep is a grid of exactly two axes. Read from
// OUT/sweep.csv; missing values are empty cells there and are skipped by the plots.
#ifndef DRAPE_SRC_SWEEP_SWEEP_REPORT_H_
#define DRAPE_SRC_SWEEP_SWEEP_REPORT_H_

#include <ostream>
#include <string>

#include "src/output/provenance.h"
#include "src/sweep/sweep_file.h"

namespace drape {

// Writes sweep.html and its plots into `directory` (which holds sweep.csv). A plot gnuplot cannot
// draw is left out, once said on `log`. The scripts are tools/sweep_*.gp, from $DRAPE_TOOLS_DIR
// if set, else the copies embedded in the binary.
// `provenance` heads the page.
void WriteSweepReport(const SweepSpec& spec, const std::string& directory,
                      const Provenance& provenance, std::ostream& log);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_SWEEP_REPORT_H_
