#include "src/output/version.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "src/output/command_output.h"
#include "tests/test_paths.h"

namespace drape {
namespace {

// The version names the sources the binary was built from: `git describe --always --dirty` of
// the tree now, which is the tree it was built from when the tests run after their build (as
// `ctest` after `cmake --build` does; a file changed since the build fails this test, rightly:
// the binary's version would not name it). Before build-time describing, a commit after CMake
// last configured kept the old description in every summary.json.
TEST(Version, NamesTheSourcesItWasBuiltFrom) {
  const std::string version = DrapeVersion();
  EXPECT_EQ(version.rfind("0.", 0), 0u) << version;
  const std::string source = drape_tests::kSourceDir;
  if (!std::filesystem::exists(source + "/.git")) GTEST_SKIP() << "not built from a git clone";
  const std::string describe =
      CommandOutput("git -C '" + source + "' describe --always --dirty 2>/dev/null");
  if (describe.empty()) GTEST_SKIP() << "git is not available";
  EXPECT_NE(version.find("(git " + describe + ")"), std::string::npos)
      << version << " against git describe " << describe;
}

}  // namespace
}  // namespace drape
