// The gnuplot scripts of `drape compare`'s report (tools/compare_*.gp), embedded in the binary
// when it is built (CMakeLists.txt generates plot_scripts.cc from src/output/plot_scripts.cc.in),
// so that an installed or copied drape draws its plots without a file lookup.
#ifndef DRAPE_SRC_OUTPUT_PLOT_SCRIPTS_H_
#define DRAPE_SRC_OUTPUT_PLOT_SCRIPTS_H_

#include <string>

namespace drape {

// The text of tools/<name> (e.g. "compare_curves.gp") as it was at build time; empty if unknown.
std::string EmbeddedPlotScript(const std::string& name);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_PLOT_SCRIPTS_H_
