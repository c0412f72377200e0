// The gnuplot scripts of `drape sweep` (tools/sweep_*.gp), embedded in the binary when it is built
// (CMakeLists.txt generates sweep_plot_scripts.cc from src/sweep/sweep_plot_scripts.cc.in, as it
// does the compare report's), so that an installed or copied drape draws its plots.
#ifndef DRAPE_SRC_SWEEP_SWEEP_PLOT_SCRIPTS_H_
#define DRAPE_SRC_SWEEP_SWEEP_PLOT_SCRIPTS_H_

#include <string>

namespace drape {

// The text of tools/<name> (e.g. "sweep_scalar.gp") as it was at build time; empty if unknown.
std::string EmbeddedSweepPlotScript(const std::string& name);

}  // namespace drape

#endif  // DRAPE_SRC_SWEEP_SWEEP_PLOT_SCRIPTS_H_
