// The standard output of a shell command, for the facts a report records about the machine
// (gnuplot's version in compare's report) and for tests that ask git about the sources.
#ifndef DRAPE_SRC_OUTPUT_COMMAND_OUTPUT_H_
#define DRAPE_SRC_OUTPUT_COMMAND_OUTPUT_H_

#include <string>

namespace drape {

// What `command` (run by /bin/sh) writes to stdout, trailing newlines and spaces removed; empty
// if it could not be started or wrote nothing.
std::string CommandOutput(const std::string& command);

// A shell word: single quotes, with '\'' for a quote inside.
std::string ShellQuoted(const std::string& text);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_COMMAND_OUTPUT_H_
