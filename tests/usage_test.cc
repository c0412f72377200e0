// The command line described from its parser (src/cli/usage.h), on a small CLI11 app of the same
// shape as drape's: synopsis lines, the command that arguments name, and the nearest known word.
#include "src/cli/usage.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace drape {
namespace {

class UsageTest : public ::testing::Test {
 protected:
  UsageTest() : app_("a toy", "drape") {
    CLI::App* solve = app_.add_subcommand("solve", "solve it");
    solve->add_option("file", file_, "scene")->required()->type_name("SCENE.yaml");
    solve->add_option("-o,--out", out_, "folder")->type_name("DIR");
    solve->add_option("--set", sets_, "overrides")->type_name("key.path=value ...");
    solve->add_option("--task-id", task_, "task")->expected(0, 1)->type_name("I");
    solve->add_flag("--no-plots", flag_, "no plots");
    app_.add_subcommand("solvers", "list them");
    app_.add_subcommand("help", "help")->add_option("command", topic_, "")->type_name("COMMAND");
  }

  CLI::App app_;
  std::string file_, out_, task_, topic_;
  std::vector<std::string> sets_;
  bool flag_ = false;
};

TEST_F(UsageTest, ASynopsisNamesEveryOptionWithItsValueAndThePositionalsLast) {
  EXPECT_EQ(CommandSynopsis(*NamedCommand(app_, {"solve"})),
            "drape solve [-o|--out DIR] [--set key.path=value ...] [--task-id [I]] [--no-plots] "
            "[--] SCENE.yaml");
  EXPECT_EQ(CommandSynopsis(*NamedCommand(app_, {"solvers"})), "drape solvers");
  const std::string synopsis = Synopsis(app_);
  EXPECT_EQ(synopsis.substr(synopsis.find("drape solvers")),
            "drape solvers\ndrape help [COMMAND] | --help | --version\n");
}

TEST_F(UsageTest, TheCommandIsTheFirstWord) {
  EXPECT_EQ(NamedCommand(app_, {"solve", "x.yaml"})->get_name(), "solve");
  EXPECT_EQ(NamedCommand(app_, {"x.yaml", "solve"}), nullptr);
  EXPECT_EQ(NamedCommand(app_, {}), nullptr);
}

TEST_F(UsageTest, AnUnknownCommandOrOptionGetsTheNearestKnownOne) {
  EXPECT_EQ(UnknownWord(app_, {"sovle", "x.yaml"}),
            "unknown command 'sovle'; did you mean 'solve'?");
  EXPECT_EQ(UnknownWord(app_, {"solve", "x.yaml", "--ot=a"}),
            "unknown option '--ot' of `drape solve`; did you mean '--out'?");
  EXPECT_EQ(UnknownWord(app_, {"frobnicate"}),
            "unknown command 'frobnicate' (expected one of: solve, solvers, help)");
}

TEST_F(UsageTest, KnownWordsValuesAndWhatFollowsDashDashAreLeftToTheParser) {
  EXPECT_EQ(UnknownWord(app_, {"solve", "x.yaml", "-o", "d", "--set", "a=-1", "--no-plots"}),
            std::nullopt);
  EXPECT_EQ(UnknownWord(app_, {"solve", "--task-id", "-1", "x.yaml"}), std::nullopt);
  EXPECT_EQ(UnknownWord(app_, {"solve", "--", "-scene.yaml"}), std::nullopt);
  EXPECT_EQ(UnknownWord(app_, {"--version"}), std::nullopt);
  EXPECT_EQ(UnknownWord(app_, {}), std::nullopt);
}

}  // namespace
}  // namespace drape
