// drape's version, as recorded in every result (summary.json) and printed by `drape --version`:
// the CMake project version, and `git describe --always --dirty` of the source tree at build time
// when built from a git clone (CMakeLists.txt and cmake/git_describe.cmake, for version.cc only).
#ifndef DRAPE_SRC_OUTPUT_VERSION_H_
#define DRAPE_SRC_OUTPUT_VERSION_H_

#include <string>

namespace drape {

// "0.1" or "0.1 (git 4bf4acd-dirty)".
std::string DrapeVersion();

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_VERSION_H_
