// The report of `drape compare`: runs.csv, curves.csv, references.csv, gnuplot plots (tools/
// compare_*.gp), report.md and a self-contained report.html (plots embedded as data URIs).
#ifndef DRAPE_SRC_COMPARE_COMPARE_REPORT_H_
#define DRAPE_SRC_COMPARE_COMPARE_REPORT_H_

#include <ostream>
#include <vector>

#include "src/compare/compare.h"

namespace drape {

// Writes every file into options.out_dir (created if needed), each through a temporary file and a
// rename. A plot that gnuplot cannot draw is left out with a note; the rest is still written.
// Throws std::runtime_error only when a file cannot be written.
void WriteCompareReport(const std::vector<SceneComparison>& comparisons,
                        const CompareOptions& options, double total_time_s, std::ostream& log);

}  // namespace drape

#endif  // DRAPE_SRC_COMPARE_COMPARE_REPORT_H_
