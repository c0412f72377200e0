// The command layer (src/commands/commands.h) refuses what it is given before any solve: an
// unknown fit method, a negative thread count, a task that is not one, drops without a drape
// test; and returns the line the command line prints.
#include "src/commands/commands.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "src/scene/scene_loader.h"
#include "tests/scratch_folder.h"
#include "tests/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

std::string Config(const std::string& relative) {
  return (fs::path(drape_tests::kSourceDir) / "configs" / relative).string();
}

TEST(Commands, AnUnknownFitMethodIsAnOptionError) {
  std::ostringstream log;
  FitCommand command;
  command.file = Config("fit/fit_drape_coefficient.yaml");
  command.method = "bobyqaa";
  EXPECT_THROW(RunFitCommand(command, CommandContext{log, "test"}), CommandOptionError);
  command.method.reset();
  command.threads = -1;
  EXPECT_THROW(RunFitCommand(command, CommandContext{log, "test"}), CommandOptionError);
  EXPECT_EQ(log.str(), "");  // nothing ran
}

TEST(Commands, ASweepTaskOutOfRangeIsAnOptionError) {
  std::ostringstream log;
  SweepCommand command;
  command.file = Config("sweep/sweep_small.yaml");
  command.only = 99;
  try {
    RunSweepCommand(command, CommandContext{log, "test"});
    FAIL() << "accepted";
  } catch (const CommandOptionError& error) {
    EXPECT_NE(std::string(error.what()).find("task 99 is not in the sweep (its tasks are 0 to 3)"),
              std::string::npos);
  }
}

TEST(Commands, DropsNeedADrapeTest) {
  std::ostringstream log;
  const Scene scene = LoadScene(Config("examples/hanging_sheet.yaml"));
  DropsCommand command;
  command.drops = 2;
  EXPECT_THROW(RunDropsCommand(scene, command, CommandContext{log, "test"}), InputError);
}

// The drops' command writes its files and gives the statistics line and its progress, a line per
// drop, to the context's stream.
TEST(Commands, DropsGiveTheirLineAndProgress) {
  testing::ScratchFolder scratch("commands");
  std::ostringstream log;
  const Scene scene = LoadScene(Config("fv/drape_tester_cotton_30.yaml"), {"mesh.spacing=0.05"});
  DropsCommand command;
  command.drops = 2;
  command.threads = 1;
  command.directory = (scratch.path() / "drops").string();
  const DropsCommandResult result = RunDropsCommand(scene, command, CommandContext{log, "test"});
  ASSERT_FALSE(result.lines.empty());
  EXPECT_EQ(result.lines[0].rfind("2 drops: drape coefficient ", 0), 0u) << result.lines[0];
  EXPECT_NE(log.str().find("drop 2 ("), std::string::npos) << log.str();
  EXPECT_TRUE(fs::exists(scratch.path() / "drops" / "drops.csv"));
}

}  // namespace
}  // namespace drape
