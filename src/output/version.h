// drape's version, as recorded in every result (summary.json) and printed by `drape --version`:
// the CMake project version, and `git describe --always --dirty` of the source tree when CMake was
// configured from a git clone (CMakeLists.txt defines both for version.cc only).
#ifndef DRAPE_SRC_OUTPUT_VERSION_H_
#define DRAPE_SRC_OUTPUT_VERSION_H_

#include <string>

namespace drape {

// "0.1" or "0.1 (git 4bf4acd-dirty)".
std::string DrapeVersion();

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_VERSION_H_
