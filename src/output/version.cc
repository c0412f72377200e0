#include "src/output/version.h"

#ifndef DRAPE_PROJECT_VERSION
#define DRAPE_PROJECT_VERSION "unknown"
#endif
#include "git_describe.h"  // DRAPE_GIT_DESCRIBE, written at build time (cmake/git_describe.cmake)

namespace drape {

std::string DrapeVersion() {
  const std::string git = DRAPE_GIT_DESCRIBE;
  return std::string(DRAPE_PROJECT_VERSION) + (git.empty() ? "" : " (git " + git + ")");
}

}  // namespace drape
