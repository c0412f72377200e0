#include "src/output/provenance.h"

#include <algorithm>

#include "src/numerics/library_threads.h"
#include "src/output/json.h"
#include "src/output/version.h"

namespace drape {

std::vector<std::pair<std::string, std::string>> ProvenanceMembers(const Provenance& provenance) {
  std::vector<std::pair<std::string, std::string>> members = {
      {"drape_version", JsonString(DrapeVersion())},
      {"blas_kernels", JsonString(BlasKernelsText())},
      {"command_line", JsonString(provenance.command_line)},
      {"overrides", JsonList(JsonStrings(provenance.overrides))}};
  if (!provenance.calibration.empty()) {
    members.emplace_back("calibration", JsonString(provenance.calibration));
  }
  return members;
}

std::string ProvenanceLine(const Provenance& provenance) {
  std::string line = "drape " + DrapeVersion();
  if (!provenance.command_line.empty()) line += "; command: " + provenance.command_line;
  std::string missing;
  for (const std::string& override : provenance.overrides) {
    if (provenance.command_line.find(override) == std::string::npos) {
      missing += (missing.empty() ? "" : ", ") + override;
    }
  }
  if (!missing.empty()) line += "; overrides: " + missing;
  if (!provenance.calibration.empty()) line += "; calibration: " + provenance.calibration;
  std::replace(line.begin(), line.end(), '\n', ' ');
  std::replace(line.begin(), line.end(), '\r', ' ');
  return line;
}

}  // namespace drape
