#include "tests/test_paths.h"

namespace drape_tests {

const char* const kSourceDir = DRAPE_SOURCE_DIR;
const char* const kDrapeBinary = DRAPE_BINARY;

}  // namespace drape_tests
