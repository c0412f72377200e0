#include "src/output/gnuplot_plots.h"

#include <cstdlib>

#include "src/output/atomic_file.h"
#include "src/output/command_output.h"
#include "src/output/plot_scripts.h"
#include "src/output/png_text.h"

namespace drape {

namespace fs = std::filesystem;

std::string GnuplotQuoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

std::string PlotScriptsDir(const std::string& tools_dir) {
  if (!tools_dir.empty()) return tools_dir;
  if (const char* dir = std::getenv("DRAPE_TOOLS_DIR")) return dir;
  return "";
}

GnuplotPlots::GnuplotPlots(const fs::path& out_dir, const std::string& tools_dir, std::ostream& log)
    : out_dir_(out_dir), scripts_dir_(PlotScriptsDir(tools_dir)), log_(log) {
  fs::create_directories(out_dir_ / "plots" / "data");
}

std::string GnuplotPlots::Data(const std::string& name,
                               const std::function<void(std::ostream&)>& write) {
  const std::string relative = "plots/data/" + name;
  WriteAtomically(out_dir_ / relative, write);
  return relative;
}

std::string GnuplotPlots::Draw(const std::string& script, const std::string& png,
                               const std::vector<std::pair<std::string, std::string>>& variables) {
  if (failed_) return "";
  const std::string relative = "plots/" + png;
  fs::path script_path = fs::path(scripts_dir_) / script;
  if (scripts_dir_.empty()) {  // the embedded copy, written beside the plot's data
    script_path = out_dir_ / "plots" / "data" / script;
    WriteAtomically(script_path,
                    [&script](std::ostream& out) { out << EmbeddedPlotScript(script); });
  }
  std::string settings = "output=" + GnuplotQuoted(relative) + ";";
  for (const auto& [name, value] : variables) settings += name + "=" + GnuplotQuoted(value) + ";";
  const std::string command =
      "cd " + ShellQuoted(out_dir_.string()) + " && gnuplot -e " + ShellQuoted(settings) + " " +
      ShellQuoted(fs::absolute(script_path).string()) + " >/dev/null 2>>plots/gnuplot.log";
  if (std::system(command.c_str()) != 0 || !fs::exists(out_dir_ / relative)) {
    log_ << "gnuplot could not draw " << relative
         << " (see plots/gnuplot.log); the report has no plots from here on\n";
    failed_ = true;
    return "";
  }
  AddDrapeVersionToPngFile(out_dir_ / relative);
  return relative;
}

}  // namespace drape
