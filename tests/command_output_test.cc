#include "src/output/command_output.h"

#include <gtest/gtest.h>

namespace drape {
namespace {

TEST(CommandOutput, IsTheCommandsStdoutWithoutTrailingNewlines) {
  EXPECT_EQ(CommandOutput("printf 'two words\\n\\n'"), "two words");
  EXPECT_EQ(CommandOutput("printf 'a\\nb\\n'"), "a\nb");
  EXPECT_EQ(CommandOutput("echo to stderr >&2"), "");
  EXPECT_EQ(CommandOutput("exit 3"), "");
}

}  // namespace
}  // namespace drape
