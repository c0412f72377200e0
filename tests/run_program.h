// Running a program from a test and reading what it wrote: the outcome of a shell command (exit
// status, stdout, stderr), drape's command line quoted for the shell, and a file read whole. One
// copy for every test that runs the built drape (cli_test, bad_input_test, the MPI tests, ...).
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "src/output/command_output.h"
#include "tests/test_paths.h"

namespace drape::testing {

struct ProgramOutcome {
  int exit_status = -1;  // 124: killed by a time limit (`timeout`)
  std::string out, err;
};

// The text of the file at `path`; empty when it cannot be read.
inline std::string ReadText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Quoting for the shell is drape's own (src/output/command_output.h).
using drape::ShellQuoted;

// The built drape with `args`, each quoted: a shell command line.
inline std::string DrapeCommand(const std::vector<std::string>& args) {
  std::string command = ShellQuoted(drape_tests::kDrapeBinary);
  for (const auto& arg : args) command += " " + ShellQuoted(arg);
  return command;
}

// Runs `command` (a shell command line) with stdout and stderr captured in files of `folder`
// (removed afterwards).
inline ProgramOutcome RunProgram(const std::string& command, const std::filesystem::path& folder) {
  const auto out = folder / "stdout.txt", err = folder / "stderr.txt";
  const int status = std::system(
      (command + " > " + ShellQuoted(out.string()) + " 2> " + ShellQuoted(err.string())).c_str());
  ProgramOutcome outcome;
  outcome.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  outcome.out = ReadText(out);
  outcome.err = ReadText(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return outcome;
}

}  // namespace drape::testing
