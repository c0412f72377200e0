// The gnuplot plots of drape's HTML reports (`drape compare`, `drape sweep`): the one plotter, with
// its quoting and where it finds its scripts. Each plot is a data file under OUT/plots/data, a
// script of tools/*.gp run by gnuplot in OUT, and a PNG under OUT/plots, which the report then
// embeds (HtmlPngImage, src/output/html_text.h).
#ifndef DRAPE_SRC_OUTPUT_GNUPLOT_PLOTS_H_
#define DRAPE_SRC_OUTPUT_GNUPLOT_PLOTS_H_

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace drape {

// A gnuplot string literal: single quotes, with '' for a quote inside.
std::string GnuplotQuoted(const std::string& text);

// Where the scripts are read from: `tools_dir` if not empty, else $DRAPE_TOOLS_DIR if set, else ""
// (the copies embedded in the binary, src/output/plot_scripts.h).
std::string PlotScriptsDir(const std::string& tools_dir);

class GnuplotPlots {
 public:
  // Plots into `out_dir`/plots (created), with the scripts of PlotScriptsDir(tools_dir); a plot
  // gnuplot cannot draw is said on `log`.
  GnuplotPlots(const std::filesystem::path& out_dir, const std::string& tools_dir,
               std::ostream& log);

  // Writes a data file under plots/data; returns its path relative to `out_dir`.
  std::string Data(const std::string& name, const std::function<void(std::ostream&)>& write);

  // Runs `script` (e.g. "sweep_scalar.gp") in `out_dir` with `output` set to plots/`png` and the
  // given gnuplot string variables; returns the PNG's path relative to `out_dir`, or "" when
  // gnuplot failed (said once on the log, its messages in plots/gnuplot.log: a gnuplot that fails
  // once, missing or too old, is not run again for the report's other plots).
  std::string Draw(const std::string& script, const std::string& png,
                   const std::vector<std::pair<std::string, std::string>>& variables);

 private:
  std::filesystem::path out_dir_;
  std::string scripts_dir_;  // empty: the embedded scripts
  std::ostream& log_;
  bool failed_ = false;
};

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_GNUPLOT_PLOTS_H_
