#include "src/output/version.h"

#ifndef DRAPE_PROJECT_VERSION
#define DRAPE_PROJECT_VERSION "unknown"
#endif
#ifndef DRAPE_GIT_DESCRIBE
#define DRAPE_GIT_DESCRIBE ""
#endif

namespace drape {

std::string DrapeVersion() {
  const std::string git = DRAPE_GIT_DESCRIBE;
  return std::string(DRAPE_PROJECT_VERSION) + (git.empty() ? "" : " (git " + git + ")");
}

}  // namespace drape
