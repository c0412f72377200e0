// The catalogue of solver methods (src/scene/solver_methods.h): option ranges, defaults, and
// docs/reference.md's tables of per-method limits and options, which must be exactly the
// catalogue's.
#include "src/scene/solver_methods.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/test_paths.h"

namespace drape {
namespace {

TEST(SolverMethods, NamesAreUniqueAndEveryOptionHasItsDocumentation) {
  std::vector<std::string> seen;
  for (const auto& method : SolverMethods()) {
    EXPECT_EQ(FindSolverMethod(method.name), &method) << method.name << " is listed twice";
    EXPECT_FALSE(method.description.empty()) << method.name;
    EXPECT_GE(method.max_iterations, 1) << method.name;
    EXPECT_GT(method.time_limit, 0.0) << method.name;
    for (const auto& option : method.options) {
      EXPECT_FALSE(option.doc.empty()) << method.name << "." << option.key;
      EXPECT_LE(option.min, option.max) << method.name << "." << option.key;
      if (option.default_value) {
        EXPECT_EQ(CheckMethodOption(option, *option.default_value), "")
            << method.name << "." << option.key << ": its default is outside its range";
      } else {
        EXPECT_FALSE(option.default_text.empty()) << method.name << "." << option.key;
      }
    }
  }
  EXPECT_EQ(FindSolverMethod("no-such-method"), nullptr);
}

TEST(SolverMethods, RangesRefuseWhatTheSolversCannotTake) {
  const SolverMethod& nlopt = *FindSolverMethod("nlopt-lbfgs");
  const MethodOption& memory = *FindMethodOption(nlopt, "memory");
  EXPECT_EQ(CheckMethodOption(memory, 10), "");
  EXPECT_NE(CheckMethodOption(memory, -5), "");
  EXPECT_NE(CheckMethodOption(memory, 2.5), "");
  EXPECT_NE(CheckMethodOption(memory, 1e12), "");
  const MethodOption& line_search =
      *FindMethodOption(*FindSolverMethod("newton"), "max_line_search");
  EXPECT_NE(CheckMethodOption(line_search, -1), "");
  const MethodOption& limit =
      *FindMethodOption(*FindSolverMethod("explicit-euler"), "stretch_limit");
  EXPECT_EQ(CheckMethodOption(limit, 0.0), "");  // none
  EXPECT_NE(CheckMethodOption(limit, 0.5), "");
  EXPECT_EQ(CheckMethodOption(limit, 1.1), "");
  const MethodOption& friction = *FindMethodOption(*FindSolverMethod("explicit-euler"), "friction");
  EXPECT_NE(CheckMethodOption(friction, 1.0), "");
}

TEST(SolverMethods, AGivenOptionWinsAndAMissingOneTakesItsDefault) {
  EXPECT_EQ(MethodOptionValue("ceres-lbfgs", {}, "memory"), 20.0);
  EXPECT_EQ(MethodOptionValue("ceres-lbfgs", {{"memory", 7.0}}, "memory"), 7.0);
  EXPECT_FALSE(MethodOptionValue("explicit-euler", {}, "dt").has_value());  // from the model
  SolverSpec spec;
  EXPECT_EQ(EffectiveMaxIterations(spec, "explicit-euler"),
            FindSolverMethod("explicit-euler")->max_iterations);
  spec.max_iterations = 7;
  EXPECT_EQ(EffectiveMaxIterations(spec, "explicit-euler"), 7);
}

// The reference's two tables, as the catalogue writes them.
std::string LimitsTable() {
  std::ostringstream table;
  table << "| method | `max_iterations` | `time_limit` (s) |\n|---|---|---|\n";
  for (const auto& method : SolverMethods()) {
    table << "| `" << method.name << "` | " << method.max_iterations << " | " << method.time_limit
          << " |\n";
  }
  return table.str();
}

std::string OptionsTable() {
  std::ostringstream table;
  table << "| option | default | range | meaning |\n|---|---|---|---|\n";
  for (const auto& method : SolverMethods()) {
    for (const auto& option : method.options) {
      table << "| `" << method.name << "." << option.key << "` | " << DescribeDefault(option)
            << " | " << DescribeRange(option) << " | " << option.doc << " |\n";
    }
  }
  return table.str();
}

std::string ReferenceSection(const std::string& begin, const std::string& end) {
  std::ifstream file(std::string(drape_tests::kSourceDir) + "/docs/reference.md");
  std::stringstream text;
  text << file.rdbuf();
  const std::string readme = text.str();
  const size_t from = readme.find(begin), to = readme.find(end);
  if (from == std::string::npos || to == std::string::npos || to < from) return "";
  const size_t start = readme.find('\n', from) + 1;
  return readme.substr(start, to - start);
}

TEST(SolverMethods, TheReferenceTablesAreTheCatalogue) {
  EXPECT_EQ(ReferenceSection("<!-- solver-limits:begin", "<!-- solver-limits:end"), LimitsTable())
      << "docs/reference.md's table between the solver-limits markers should read:\n"
      << LimitsTable();
  EXPECT_EQ(ReferenceSection("<!-- solver-options:begin", "<!-- solver-options:end"),
            OptionsTable())
      << "docs/reference.md's table between the solver-options markers should read:\n"
      << OptionsTable();
}

}  // namespace
}  // namespace drape
