// Where the tests find the clone and the built programs. CMake gives the paths to
// tests/test_paths.cc alone, so that no other test object depends on where the clone is and ccache
// reuses them from one clone to the next (docs/building.md).
#ifndef DRAPE_TESTS_TEST_PATHS_H_
#define DRAPE_TESTS_TEST_PATHS_H_

namespace drape_tests {

extern const char* const kSourceDir;    // the clone's root
extern const char* const kDrapeBinary;  // the built `drape`

}  // namespace drape_tests

#endif  // DRAPE_TESTS_TEST_PATHS_H_
