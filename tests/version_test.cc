#include "src/output/version.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace drape {
namespace {

// The output of a shell command (trailing newlines removed); *ok false if it failed.
std::string CommandOutput(const std::string& command, bool* ok) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  *ok = pipe != nullptr;
  std::string out;
  if (!pipe) return out;
  std::array<char, 256> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe.get())) out += buffer.data();
  *ok = pclose(pipe.release()) == 0;
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

// The version names the sources the binary was built from: `git describe --always --dirty` of
// the tree now, which is the tree it was built from when the tests run after their build (as
// `ctest` after `cmake --build` does; a file changed since the build fails this test, rightly:
// the binary's version would not name it). Before build-time describing, a commit after CMake
// last configured kept the old description in every summary.json.
TEST(Version, NamesTheSourcesItWasBuiltFrom) {
  const std::string version = DrapeVersion();
  EXPECT_EQ(version.rfind("0.", 0), 0u) << version;
  const std::string source = DRAPE_SOURCE_DIR;
  if (!std::filesystem::exists(source + "/.git")) GTEST_SKIP() << "not built from a git clone";
  bool ok = false;
  const std::string describe =
      CommandOutput("git -C '" + source + "' describe --always --dirty 2>/dev/null", &ok);
  if (!ok || describe.empty()) GTEST_SKIP() << "git is not available";
  EXPECT_NE(version.find("(git " + describe + ")"), std::string::npos)
      << version << " against git describe " << describe;
}

}  // namespace
}  // namespace drape
