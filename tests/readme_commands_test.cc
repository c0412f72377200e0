// README.md's two commands and CI (.ci/run) stay one: CI installs every package the first command
// installs and runs the second command exactly as the README writes it, so a command that works in
// CI works for a user who copies it.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/test_paths.h"

namespace drape {
namespace {

std::string FileText(const std::string& relative) {
  std::ifstream file(std::string(drape_tests::kSourceDir) + "/" + relative);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// The bodies of the ```sh blocks of README.md's "Two commands" section, in order.
std::vector<std::string> ReadmeCommands() {
  const std::string readme = FileText("README.md");
  const size_t section = readme.find("## Two commands");
  const size_t next = readme.find("\n## ", section + 1);
  const std::string text = readme.substr(section, next - section);
  std::vector<std::string> commands;
  const std::regex block("```sh\n([^`]*)\n```");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), block);
       it != std::sregex_iterator(); ++it) {
    commands.push_back((*it)[1]);
  }
  return commands;
}

// The words after `apt-get install -y` up to the next `&&`.
std::set<std::string> InstalledPackages(const std::string& command) {
  std::set<std::string> packages;
  const size_t install = command.find("apt-get install -y ");
  if (install == std::string::npos) return packages;
  std::istringstream words(command.substr(install + 19));
  for (std::string word; words >> word && word != "&&";) packages.insert(word);
  return packages;
}

// The words of .ci/run's bash arrays `packages=(…)` and `packages+=(…)`, comments left out.
std::set<std::string> CiPackages() {
  const std::string run = FileText(".ci/run");
  std::set<std::string> packages;
  const std::regex array("\npackages\\+?=\\(([^)]*)\\)");
  for (auto it = std::sregex_iterator(run.begin(), run.end(), array); it != std::sregex_iterator();
       ++it) {
    std::istringstream words((*it)[1].str());
    for (std::string word; words >> word;) packages.insert(word);
  }
  return packages;
}

TEST(ReadmeCommands, AreTwoAndTheFirstSolvesTheExampleWithDrapeAlone) {
  const std::vector<std::string> commands = ReadmeCommands();
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_NE(commands[0].find("cmake --build build -j2 --target drape &&"), std::string::npos)
      << "the first command builds what the example needs, and no more";
  EXPECT_NE(commands[0].find("./build/drape solve configs/examples/"), std::string::npos);
  EXPECT_NE(commands[1].find("ctest --test-dir build"), std::string::npos);
}

TEST(ReadmeCommands, CiInstallsTheFirstCommandsPackages) {
  const std::vector<std::string> commands = ReadmeCommands();
  ASSERT_EQ(commands.size(), 2u);
  const std::set<std::string> readme = InstalledPackages(commands[0]);
  const std::set<std::string> ci = CiPackages();
  ASSERT_GT(readme.size(), 5u);
  for (const std::string& package : readme) EXPECT_TRUE(ci.count(package)) << package;
}

TEST(ReadmeCommands, CiRunsTheTestCommandAsWritten) {
  const std::vector<std::string> commands = ReadmeCommands();
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_NE(FileText(".ci/run").find(commands[1]), std::string::npos)
      << ".ci/run should run README.md's test command:\n"
      << commands[1];
}

}  // namespace
}  // namespace drape
